"""The billiard Python module against independent truths: Alciatore's closed form for the cue
strike, the CLI's own answers for the same input (the module is a second front end over the same
library: it must agree to the bit), a plan's launch arriving at its target, and the refusals."""
import json
import math
import os
import struct
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest

import billiard

SOURCE = Path(__file__).resolve().parents[2]
BILLIARD_BIN = os.environ.get("BILLIARD_BIN", str(SOURCE / "build" / "bin" / "billiard"))
POOL = json.loads((SOURCE / "sim" / "params" / "pool.json").read_text())


def cli(*args):
    out = subprocess.run([BILLIARD_BIN, *args, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def test_simulate_agrees_with_the_cli_to_the_bit():
    state = np.array([0.5, 0.5, 1.2, 0.3, -5.0, 20.0, 8.0])
    r = billiard.simulate(state, 3.0, sample_dt=0.01)
    j = cli("simulate", "--state", ",".join(repr(x) for x in state), "--t-end", "3")
    assert r["state"].tolist() == j["state"]
    assert r["trajectory"].shape == (301, 8)
    assert r["trajectory"][0, 1:].tolist() == state.tolist()
    assert r["trajectory"][-1, 0] == 3.0
    assert np.allclose(r["trajectory"][-1, 1:], r["state"])


def test_strike_is_alciatores_closed_form():
    ball, cue = POOL["ball"], POOL["cue"]
    m, mc, e, radius = ball["mass"], cue["mass"], cue["tip_restitution"], ball["radius"]
    q, speed = 0.5, 2.0
    v = (1 + e) * speed / (1 + m / mc + 2.5 * q * q)  # TP A.30
    follow = billiard.strike(speed, 0.0, tip_height=q * radius, at=np.array([1.0, 0.6]))
    assert follow[:2].tolist() == [1.0, 0.6]
    assert follow[2] == pytest.approx(v, abs=1e-12)
    assert follow[5] == pytest.approx(2.5 * v * q / radius, abs=1e-9)  # wy > 0: follow
    right = billiard.strike(speed, 0.0, tip_side=0.4 * radius)
    assert right[6] > 0 and right[3] > 0  # right english: counterclockwise, squirted left
    with pytest.raises(ValueError):
        billiard.strike(speed, 0.0, tip_side=radius)


def test_a_scene_runs_event_by_event_and_refuses_a_ball_over_a_pocket():
    states = np.array([[0.5, 0.635, 2.0, 0, 0, 0, 0], [1.0, 0.635, 0, 0, 0, 0, 0]])
    r = billiard.simulate_scene(states, ids=[0, 3])
    assert r["ids"] == [0, 3]
    assert r["states"].shape == (2, 7)
    first = next(e for e in r["events"] if e["type"] == "ball_ball")
    assert first["balls"] == [0, 3]
    assert r["states"][1, 0] > r["states"][0, 0] > 0.5  # the struck ball ahead of the cue ball
    assert r["at_rest"]
    with pytest.raises(ValueError, match="ball 3"):
        billiard.simulate_scene(np.array([[0.01, 0.01, 0, 0, 0, 0, 0]]), ids=[3])
    with pytest.raises(ValueError):
        billiard.simulate_scene(np.zeros((2, 6)))


def test_an_elevated_strike_hops_the_ball_and_the_scene_flies_it():
    """The slate returns half the downward speed v tan(elevation) (sim/physics/hop.h); a ball given
    it lands first after a projectile's rise and fall, 2 v_up / g."""
    elevation = math.radians(10.0)
    launch = billiard.strike(2.0, 0.0, elevation=elevation)
    up = billiard.launch_up_speed(2.0, 0.0, elevation=elevation)
    assert up == pytest.approx(0.5 * launch[2] * math.tan(elevation), rel=1e-12)
    assert billiard.launch_up_speed(2.0, 0.0) == 0.0
    launch[:2] = [0.5, 0.6]
    r = billiard.simulate_scene(np.array([launch]), up_speeds=[up], t_end=0.5)
    assert r["events"][0]["type"] == "transition"
    assert r["events"][0]["t"] == pytest.approx(2.0 * up / 9.81, rel=1e-12)
    with pytest.raises(ValueError, match="up_speeds"):
        billiard.simulate_scene(np.array([launch]), up_speeds=[up, up])


def test_a_plan_arrives_at_its_target_and_a_refusal_is_an_exception():
    plan = billiard.plan(np.array([0.5, 0.5]), np.array([1.5, 0.8]), spin="draw")
    assert plan["v0"].shape == (2,) and plan["w0"].shape == (3,)
    start = np.concatenate([[0.5, 0.5], plan["v0"], plan["w0"]])
    arrived = billiard.simulate(start, plan["arrival_time"])["state"]
    assert np.hypot(arrived[0] - 1.5, arrived[1] - 0.8) < 1e-4
    launch = billiard.strike(plan["cue"]["speed"], plan["cue"]["heading"],
                             plan["cue"]["tip_side"], plan["cue"]["tip_height"],
                             plan["cue"]["elevation"], at=np.array([0.5, 0.5]))
    assert np.allclose(launch[2:], start[2:], atol=1e-9)  # the stroke gives that launch
    with pytest.raises(billiard.Refused, match="off_table"):
        billiard.plan(np.array([0.5, 0.5]), np.array([5.0, 0.5]))
    with pytest.raises(ValueError):
        billiard.plan(np.array([0.5, np.nan]), np.array([1.0, 0.5]))


def test_a_plan_agrees_with_the_cli_at_the_elevation_the_robots_cue_needs():
    """0.5 m off the left rail the gantry's cue must rise over it: both front ends plan the same
    stroke at the same elevation, and the CLI says it clears."""
    plan = billiard.plan(np.array([0.5, 0.5]), np.array([1.5, 0.8]), final_speed=0.3, spin="stun")
    j = cli("plan", "--from", "0.5,0.5", "--to", "1.5,0.8", "--final-speed", "0.3", "--spin", "stun")
    assert plan["cue"] == {key: j["cue"][key] for key in plan["cue"]}
    assert plan["v0"].tolist() == j["v0"] and plan["w0"].tolist() == j["w0"]
    assert plan["cue"]["elevation"] > 0 and j["cue"]["clearance"]["clears"]
    with pytest.raises(ValueError, match="robot"):
        billiard.plan(np.array([0.5, 0.5]), np.array([1.5, 0.8]), robot="no-such-robot")


def test_a_pot_agrees_with_plan_pot_and_a_refusal_is_an_exception():
    scene = json.loads((SOURCE / "docs" / "pictures" / "pot_scene.json").read_text())
    states = np.array([b["state"] for b in scene["balls"]])
    ids = [b["id"] for b in scene["balls"]]
    plan = billiard.plan_pot(states, ids=ids, ball=1, pocket="upper_right")
    path = SOURCE / "docs" / "pictures" / "pot_scene.json"
    j = cli("plan-pot", "--scene", str(path), "--ball", "1", "--pocket", "upper_right")
    assert plan["kind"] == j["kind"] and plan["why"] == j["why"]
    assert plan["v0"].tolist() == j["v0"] and plan["w0"].tolist() == j["w0"]
    assert plan["cue_rest"].tolist() == j["cue_rest"]
    assert plan["margin_deg"] == j["margin_deg"]
    assert plan["paths"][1].shape[1] == 2
    with pytest.raises(billiard.Refused, match="no_such_pocket"):
        billiard.plan_pot(states, ids=ids, ball=1, pocket="upper_centre")
    with pytest.raises(ValueError):
        billiard.plan_pot(states, ids=ids, ball=1, kind="sideways")


def test_the_documented_one_liner_runs_whatever_python3_is_first_on_path(tmp_path):
    """build/python/python3 is the interpreter the module was built for: a python3 first on PATH
    that cannot import it (here one that fails at once) is not the one that runs."""
    launcher = Path(billiard.__file__).parent / "python3"
    (tmp_path / "python3").write_text("#!/bin/sh\necho 'the wrong python3' >&2\nexit 9\n")
    (tmp_path / "python3").chmod(0o755)
    env = {"PATH": f"{tmp_path}:{os.environ['PATH']}"}
    out = subprocess.run([str(launcher), "-c", "import billiard; print(billiard.simulate("
                          "[0, 0, 1, 0, 0, 35, 0], 8.0)['state'][0])"],
                         env=env, check=True, capture_output=True, text=True)
    assert float(out.stdout) == billiard.simulate([0, 0, 1, 0, 0, 35, 0], 8.0)["state"][0]


NINE_BALL = SOURCE / "tests" / "data" / "nine_ball_layout.json"


def scene_arrays(path):
    scene = json.loads(path.read_text())
    return np.array([b["state"] for b in scene["balls"]]), [b["id"] for b in scene["balls"]]


def test_choose_shot_agrees_with_the_cli_to_the_bit():
    states, ids = scene_arrays(NINE_BALL)
    r = billiard.choose_shot(states, ids=ids, rules="nine-ball", samples=16, threads=2)
    j = cli("choose-shot", "--scene", str(NINE_BALL), "--rules", "nine-ball", "--samples", "16")
    for key in ("ball", "pocket", "kind", "cue", "margin_deg", "success_probability",
                "probability_stderr", "samples", "next_shot_value", "score"):
        assert r["choice"][key] == j["choice"][key], key
    assert r["choice"]["v0"].tolist() == j["choice"]["v0"]
    assert r["likely"] == j["likely"] and r["candidates"] == len(j["candidates"])
    assert r["cue_placement"] is None
    placed = billiard.choose_shot(states, ids=ids, rules="nine-ball", samples=16, ball_in_hand=True)
    j = cli("choose-shot", "--scene", str(NINE_BALL), "--rules", "nine-ball", "--samples", "16",
            "--ball-in-hand")
    assert placed["cue_placement"].tolist() == j["cue_placement"]
    with pytest.raises(billiard.Refused, match="no_target"):
        billiard.choose_shot(np.array([[1.0, 0.6, 0, 0, 0, 0, 0]]))
    with pytest.raises(ValueError):
        billiard.choose_shot(states, ids=ids, rules="snooker")


# The decision's wall time, which no two runs share.
TIMES = {"decision_us", "median_decision_us"}


def assert_same_game(mine, theirs):
    """billiard.play's answer is play --json's game: the same keys and values, the times aside
    (the CLI adds the options it was given: the caller of play knows its own)."""
    assert set(mine) == {"shots", "summary", "balls_left"} <= set(theirs)
    assert len(mine["shots"]) == len(theirs["shots"]) == mine["summary"]["shots"]
    for a, b in zip(mine["shots"], theirs["shots"]):
        assert set(a) == set(b) and "safety" in a and "cue" in a
        assert {k: v for k, v in a.items() if k not in TIMES} == {
            k: v for k, v in b.items() if k not in TIMES}
    assert {k: v for k, v in mine["summary"].items() if k not in TIMES} == {
        k: v for k, v in theirs["summary"].items() if k not in TIMES}
    assert mine["balls_left"] == theirs["balls_left"]


def test_play_agrees_with_the_cli_shot_by_shot():
    r = billiard.play(rack="nine-ball", seed=3, samples=16, shot_limit=4)
    j = cli("play", "--rack", "nine-ball", "--seed", "3", "--samples", "16", "--shot-limit", "4")
    assert_same_game(r, j)
    assert r["shots"][0]["break"]
    with pytest.raises(ValueError):
        billiard.play()
    with pytest.raises(ValueError):
        billiard.play(rack="eight-ball")


def test_play_on_a_scene_agrees_with_the_cli_stroke_and_clearance_included():
    states, ids = scene_arrays(NINE_BALL)
    r = billiard.play(states, ids=ids, rules="nine-ball", samples=16, shot_limit=2)
    j = cli("play", "--scene", str(NINE_BALL), "--rules", "nine-ball", "--samples", "16",
            "--shot-limit", "2")
    assert_same_game(r, j)
    first = r["shots"][0]
    assert not first["break"] and first["cue"]["speed"] > 0
    assert isinstance(first["safety"], bool)
    assert set(first["cue"]["clearance"]) >= {"clears", "nearest", "distance"}


def read_png_rgb(path):
    """An 8-bit RGB, non-interlaced PNG (the test frame's format) as an H x W x 3 array."""
    data = path.read_bytes()
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, colour, interlace) == (8, 2, 0)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, 1 + 3 * width)
    out = np.zeros((height, 3 * width), np.int32)
    prior = np.zeros(3 * width, np.int32)
    for y in range(height):
        kind, row = raw[y, 0], raw[y, 1:].astype(np.int32)
        if kind == 0:
            line = row
        elif kind == 2:
            line = (row + prior) & 255
        elif kind == 1:  # Sub: each byte adds the one a pixel left, a running sum per channel
            line = np.cumsum(row.reshape(width, 3), axis=0).reshape(-1) & 255
        else:  # Average or Paeth: byte by byte
            line = row.copy()
            for x in range(3 * width):
                a = line[x - 3] if x >= 3 else 0
                b, c = prior[x], (prior[x - 3] if x >= 3 else 0)
                if kind == 3:
                    line[x] = (row[x] + (a + b) // 2) & 255
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    line[x] = (row[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out[y], prior = line, line
    return out.reshape(height, width, 3).astype(np.uint8)


def test_detect_finds_what_the_cli_finds_and_refuses_a_frame_without_a_table():
    data = Path(os.environ.get("BILLIARD_TEST_DATA", SOURCE.parent / "shared" / "data"))
    frame = data / "real-tables" / "snooker_overhead_1280x720.png"
    with pytest.raises(billiard.Refused):
        billiard.detect(np.zeros((120, 160, 3), np.uint8))
    with pytest.raises(ValueError):
        billiard.detect(np.zeros((10, 10, 4), np.uint8))
    if not frame.exists():
        pytest.skip(f"no test data at {data}")
    bgr = np.ascontiguousarray(read_png_rgb(frame)[:, :, ::-1])
    found = billiard.detect(bgr, ball_set="snooker")
    j = cli("detect", str(frame), "--ball-set", "snooker")
    assert found["balls"].shape == (len(j["balls"]), 4)
    assert len(j["balls"]) > 10
    for row, ball, name in zip(found["balls"], j["balls"], found["classes"]):
        assert row.tolist() == [ball["u"], ball["v"], ball["radius_px"], ball["score"]]
        assert name == ball["class"]
