#!/usr/bin/env python3
"""A rig learnt once, on real frames: `billiard learn-balls` on one labelled frame of a camera,
`billiard detect --ball-model` on another frame of the same camera, against `detect` with the
hand-set colours (docs/vision.md, "A rig's own balls"). The dev frames are test data: the models
are written to a scratch directory and measured, never kept.

    bench/rig_pairs.py [--billiard build/bin/billiard] [--data ../shared/data/real-tables]

A labelled ball counts where a detection lies within its label's ball radius; it is named right
when the detection's class is its label's (carom's "white" the cue ball, pool's "eight" or
"black" the 8; "solid", "stripe" and unlabelled balls are neither learnt nor counted).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

# Frames of one camera (the same source, table and view), each learnt and the others named.
RIGS = [["rex_c11.png", "rex_c15.png"], ["fou_02.jpg", "fou_03.jpg", "fou_04.jpg"],
        ["pjk_05.jpg", "pjk_06.jpg"], ["pjk_01.jpg", "pjk_02.jpg"], ["kng_01.png", "kng_04.png"],
        ["ch_cap1445.jpg", "ch_cap4857.jpg"]]
SETS = ["dev", "dev2"]


def class_name(label, ball_set):
    if label is None or label in ("solid", "stripe"):
        return None
    if label == "white":
        return "cue"
    if label == "eight" or (ball_set == "pool" and label == "black"):
        return "8"
    return label


def classed_balls(frame, ball_set):
    return [(class_name(c, ball_set), u, v)
            for (u, v), c in zip(frame["balls"], frame.get("classes", []))
            if class_name(c, ball_set)]


def detect(billiard, image, ball_set, model=None):
    args = [billiard, "detect", image, "--ball-set", ball_set, "--json"]
    if model:
        args += ["--ball-model", model]
    run = subprocess.run(args, capture_output=True, text=True)
    return json.loads(run.stdout)["balls"] if run.returncode == 0 else None


def named_right(found, balls, radius):
    seen = right = 0
    for name, u, v in balls:
        near = [(((b["u"] - u) ** 2 + (b["v"] - v) ** 2) ** 0.5, b) for b in found]
        near = [n for n in near if n[0] < radius]
        if near:
            seen += 1
            right += min(near, key=lambda n: n[0])[1]["class"] == name
    return seen, right


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--billiard", default="build/bin/billiard")
    parser.add_argument("--data", default="../shared/data/real-tables")
    args = parser.parse_args()
    frames = {}
    for s in SETS:
        with open(os.path.join(args.data, s, "labels.json")) as f:
            for name, frame in json.load(f).items():
                if not name.startswith("_"):
                    frames[name] = (os.path.join(args.data, s, name), frame)
    totals = {"model": [0, 0], "hand-set": [0, 0]}
    scratch = tempfile.mkdtemp(prefix="rig_pairs_")
    for rig in RIGS:
        for learnt in rig:
            image, frame = frames[learnt]
            ball_set = frame["kind"]
            placed = [{"id": n, "u": u, "v": v} for n, u, v in classed_balls(frame, ball_set)]
            balls_file = os.path.join(scratch, learnt + ".balls.json")
            model = os.path.join(scratch, learnt + ".model.json")
            with open(balls_file, "w") as f:
                json.dump(placed, f)
            run = subprocess.run([args.billiard, "learn-balls", image, "--balls", balls_file,
                                  "--ball-set", ball_set, "--out", model, "--json"],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                print(f"{learnt}: not learnt ({run.stderr.strip()})")
                continue
            for named in rig:
                if named == learnt:
                    continue
                other, labels = frames[named]
                balls = classed_balls(labels, ball_set)
                line = f"{ball_set:8s} {learnt} -> {named}:"
                for what, found in (("model", detect(args.billiard, other, ball_set, model)),
                                    ("hand-set", detect(args.billiard, other, ball_set))):
                    if found is None:
                        line += f" {what} no table;"
                        continue
                    seen, right = named_right(found, balls, labels["ball_radius_px"])
                    totals[what][0] += seen
                    totals[what][1] += right
                    line += f" {what} {right} of {seen};"
                print(line)
    shutil.rmtree(scratch)
    for what, (seen, right) in totals.items():
        print(f"{what}: {right} of {seen} found balls named right")
    return 0


if __name__ == "__main__":
    sys.exit(main())
