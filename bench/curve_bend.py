#!/usr/bin/env python3
"""How much a curve can bend within the hop limit: for cue elevations of 5 to 30 degrees, the
fastest cue that keeps the ball within 1 mm of the cloth (sim/cue/stroke_limits.h, HopFreeSpeed)
and the path `billiard simulate --cue` gives a lone ball struck at that speed on the open cloth
(the converged integral model, the pool set), with the gantry's largest tip offset: half a radius
of side, or 0.35 of a radius of side and of draw (the planner's curve, planner/pot/routes.cc).

    bench/curve_bend.py [--billiard build/bin/billiard]

Printed as Markdown (docs/planning.md, "How much a curve bends"): per elevation the cue speed,
the squirt (the launch off the cue's heading), the turn of the path over its slide, where the
slide ends (the slip at 5 % of the launch's), the path's distance from its launch line after 0.5, 1.0 and 1.5 m, and its bend: the
largest distance of the path from its chord over those lengths. A ball that stands across the
straight line by less than the bend (and near the chord's middle) is one a curve can pass.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import tempfile

ELEVATIONS_DEG = [5, 7.5, 10, 12.5, 15, 20, 25, 30]
LENGTHS_M = [0.5, 1.0, 1.5]
RADIUS = 0.028575  # the pool ball's (sim/params/pool.json)
GRAVITY = 9.81
# sim/cue/stroke_limits.h: the bed's restitution and the highest hop the model covers [m].
BED_RESTITUTION = 0.5
MAX_HOP = 1e-3
# The gantry's largest tip offset: half a radius (sim/params/robots/gantry.json).
TIPS = [("side 0.5 r", -0.5, 0.0), ("side 0.35 r, draw 0.35 r", -0.35, -0.35)]
# The slide is taken to end where the contact point's slip falls to this fraction of the launch's
# (it falls at 7/2 mu g while the ball slides; the side spin leaves a few cm/s of it after).
SLIDE_END = 0.05


def simulate(billiard, speed, elevation, side, height, trajectory):
    out = subprocess.run([billiard, "simulate", "--cue", f"{speed},0,{side * RADIUS},{height * RADIUS},{elevation}",
                          "--model", "integral", "--t-end", "6", "--json", "--trajectory", trajectory],
                         check=True, capture_output=True, text=True)
    with open(trajectory) as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return json.loads(out.stdout)["launch"], rows


def hop_free_speed(billiard, elevation, side, height, trajectory):
    """The hop grows with the square of the cue speed (the strike is linear in it)."""
    launch, _ = simulate(billiard, 1.0, elevation, side, height, trajectory)
    up = BED_RESTITUTION * launch[2] * math.tan(elevation)  # the heading is +x
    return math.sqrt(MAX_HOP / (up * up / (2 * GRAVITY)))


def arc_lengths(points):
    s = [0.0]
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        s.append(s[-1] + math.hypot(x1 - x0, y1 - y0))
    return s


def measure(billiard, elevation_deg, side, height, trajectory):
    elevation = math.radians(elevation_deg)
    speed = hop_free_speed(billiard, elevation, side, height, trajectory)
    launch, rows = simulate(billiard, speed, elevation, side, height, trajectory)
    squirt = math.atan2(launch[3], launch[2])
    points = [(r["X"], r["Y"]) for r in rows]
    s = arc_lengths(points)
    slip = [math.hypot(r["vx"] - RADIUS * r["wy"], r["vy"] + RADIUS * r["wx"]) for r in rows]
    slide_end = next((i for i, u in enumerate(slip) if u < SLIDE_END * slip[0]), len(rows) - 1)
    turn = math.atan2(rows[slide_end]["vy"], rows[slide_end]["vx"]) - squirt
    off_line, bend = [], []
    for length in LENGTHS_M:
        end = next((i for i, si in enumerate(s) if si >= length), None)
        if end is None:  # the ball rests first
            off_line.append(None)
            bend.append(None)
            continue
        ex, ey = points[end]
        chord = math.hypot(ex, ey)
        off_line.append(abs(ex * math.sin(squirt) - ey * math.cos(squirt)))
        bend.append(max(abs(px * ey - py * ex) / chord for px, py in points[:end + 1]))
    return speed, squirt, turn, s[slide_end], off_line, bend, s[-1]


def mm(values):
    return " / ".join("-" if v is None else f"{v * 1e3:.0f}" for v in values)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--billiard", default="build/bin/billiard")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        trajectory = os.path.join(scratch, "path.csv")
        for name, side, height in TIPS:
            print(f"\n{name} (left):\n")
            print("| elevation | cue [m/s] | squirt | turn | slide ends at | off the launch line at 0.5 / 1 / 1.5 m "
                  "[mm] | bend off the chord of 0.5 / 1 / 1.5 m [mm] | rests at |")
            print("|---|---|---|---|---|---|---|---|")
            for deg in ELEVATIONS_DEG:
                speed, squirt, turn, slide, off_line, bend, rest = measure(args.billiard, deg, side, height,
                                                                             trajectory)
                print(f"| {deg} deg | {speed:.2f} | {math.degrees(squirt):.1f} deg | {math.degrees(turn):.1f} deg | "
                      f"{slide:.2f} m | {mm(off_line)} | {mm(bend)} | {rest:.2f} m |")


if __name__ == "__main__":
    main()
