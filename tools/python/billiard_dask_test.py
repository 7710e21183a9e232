"""billiard_dask against `billiard match`: the racks of a match played as tasks on a local Dask
cluster of two worker processes (one thread each) sum to the figures one process prints for the
same seed, every one of them but the clock's decision times."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import billiard

distributed = pytest.importorskip("distributed", reason="python3-distributed is not installed")
import billiard_dask  # noqa: E402  (after the skip: it needs nothing of Dask to import, its tests do)

SOURCE = Path(__file__).resolve().parents[2]
BILLIARD_BIN = os.environ.get("BILLIARD_BIN", str(SOURCE / "build" / "bin" / "billiard"))
CHEAP = ["easiest-looking", "easiest-looking"]  # tenths of a second a rack


def billiard_match(game, players, racks, seed, noise="robot"):
    out = subprocess.run([BILLIARD_BIN, "match", "--game", game, "--players", ",".join(players),
                          "--racks", str(racks), "--seed", str(seed), "--noise", noise,
                          "--threads", "2", "--json"],
                         check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def test_nine_ball_on_two_workers_is_the_one_process_match(client):
    told = []
    summary = billiard_dask.play_match(client, "nine-ball", CHEAP, racks=6, seed=7,
                                       noise="computational-pool",
                                       progress=lambda done, racks, workers: told.append((done, racks, len(workers))))
    truth = billiard_match("nine-ball", CHEAP, 6, 7, "computational-pool")
    assert billiard_dask.without_clock(summary) == billiard_dask.without_clock(truth)
    assert summary["racks"] == 6
    assert sum(p["attempts"] for p in summary["players"]) > 0
    assert told[-1] == (6, 6, 1) and len(told) == 6
    assert set(summary["decision_us"]) == {"median", "p95"}


def test_eight_ball_in_chunks_of_three_is_the_one_process_match(client):
    records = billiard_dask.play_racks(client, "eight-ball", CHEAP, racks=5, seed=2,
                                       racks_per_task=3)
    assert [r["rack"] for r in records] == list(range(5))
    assert [r["breaker"] for r in records] == [0, 1, 0, 1, 0]
    summary = billiard.match_summary(records, "eight-ball", CHEAP, 2)
    truth = billiard_match("eight-ball", CHEAP, 5, 2)
    assert billiard_dask.without_clock(summary) == billiard_dask.without_clock(truth)


def test_the_tasks_racks_depend_on_the_rack_count_alone():
    assert billiard_dask.chunks(5, 3) == [range(0, 3), range(3, 5)]
    assert [billiard_dask.default_racks_per_task(n) for n in (1, 20, 64, 100, 400, 4000)] == \
        [1, 1, 2, 3, 8, 8]


def test_a_rack_is_a_function_of_the_seed_and_its_index():
    alone = billiard.play_rack("nine-ball", CHEAP, 3, seed=7, threads=2)
    again = billiard.play_rack("nine-ball", CHEAP, 3, seed=7, threads=1)
    other = billiard.play_rack("nine-ball", CHEAP, 4, seed=7, threads=1)
    for record in (alone, again):
        for p in record["players"]:
            p.pop("decisions_us")
    assert alone == again
    assert alone["breaker"] == 1 and other["breaker"] == 0
    tallies = alone["players"]
    assert alone["shots"] >= sum(p["attempts"] + p["safeties"] for p in tallies)
    assert alone["winner"] in (0, 1, None)


def test_records_in_any_order_sum_to_the_same_match():
    records = [billiard.play_rack("nine-ball", CHEAP, r, seed=5) for r in range(4)]
    forward = billiard.match_summary(records, "nine-ball", CHEAP, 5)
    backward = billiard.match_summary(records[::-1], "nine-ball", CHEAP, 5)
    assert billiard_dask.without_clock(forward) == billiard_dask.without_clock(backward)
    assert forward["racks"] == 4
    assert sum(p["racks_won"] for p in forward["players"]) + forward["undecided"] == 4


def test_bad_input_is_a_value_error():
    record = billiard.play_rack("nine-ball", CHEAP, 0, seed=1)
    with pytest.raises(ValueError, match="record 0: 'winner' is not 0, 1 or None"):
        billiard.match_summary([dict(record, winner=2)], "nine-ball", CHEAP)
    with pytest.raises(ValueError, match="record 0 player 1: no 'attempts'"):
        broken = dict(record, players=[record["players"][0], {}])
        billiard.match_summary([broken], "nine-ball", CHEAP)
    with pytest.raises(ValueError, match="unknown game 'snooker'"):
        billiard.play_rack("snooker", CHEAP, 0)
    with pytest.raises(ValueError, match="players"):
        billiard_dask.play_racks(None, "nine-ball", ["ours"], racks=2)


def test_the_command_line_refuses_bad_input_in_one_line():
    run = subprocess.run([sys.executable, "-m", "billiard_dask", "--local", "2", "--game",
                          "snooker", "--players", "ours,ours"], capture_output=True, text=True)
    assert run.returncode == 2
    assert run.stderr.strip().splitlines() == [
        "billiard_dask: game: unknown game 'snooker' (nine-ball, eight-ball)"]
    run = subprocess.run([sys.executable, "-m", "billiard_dask", "--local", "0", "--game",
                          "nine-ball", "--players", "ours,ours"], capture_output=True, text=True)
    assert run.returncode == 2 and len(run.stderr.strip().splitlines()) == 1


def test_no_scheduler_is_a_one_line_failure():
    env = dict(os.environ, DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s")
    run = subprocess.run([sys.executable, "-m", "billiard_dask", "--scheduler", "tcp://127.0.0.1:1",
                          "--game", "nine-ball", "--players", "ours,ours"],
                         capture_output=True, text=True, env=env)
    assert run.returncode == 1
    assert run.stderr.strip().splitlines() == [
        "billiard_dask: no cluster to play on: Timed out trying to connect to tcp://127.0.0.1:1 "
        "after 2 s"]
