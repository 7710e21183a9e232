"""A match of many racks on a Dask cluster: the racks as tasks, summed as one process sums them.

A rack of `billiard match` depends on the match's seed and its own index alone (rack r is
seeded SampleSeed(seed, r) and broken by player r % 2: planner/game/match.h), so the racks of a
tournament-scale match can be played anywhere, in any order, and their records
(`billiard.play_rack`) summed by the library's own code (`billiard.match_summary`, the one
`billiard match` sums with) give the figures one process gives for the same seed; only the
decision times, which are the clock's, differ.

    import distributed, billiard_dask
    client = distributed.Client("tcp://10.77.0.1:8786")   # or distributed.LocalCluster(...)
    summary = billiard_dask.play_match(client, "nine-ball", ["ours", "easiest-looking"],
                                       racks=400, seed=1, noise="computational-pool")

The workers import this module and `billiard`: start them with the interpreter the module was
built for and the module on its path, `build/python/python3 -m distributed.cli.dask_worker
SCHEDULER` (or `dask-worker` with PYTHONPATH=build/python), on every host. A task plays
`racks_per_task` consecutive racks, each on one thread (a worker process per core plays as
many racks at once as there are cores); the runs are fixed by the rack count and
`racks_per_task` alone, and the records are gathered in rack order.

From the command line, as `billiard match` with a scheduler's address (or --local N workers):

    build/python/python3 -m billiard_dask --scheduler tcp://10.77.0.1:8786 --workers 2 \\
        --game nine-ball --players ours,easiest-looking --racks 400 --seed 1 --json

JSON on stdout, progress on stderr; a bad command line exits 2 with one line on stderr
(docs/exit-codes.md). docs/python.md has the measurements.
"""

import argparse
import contextlib
import json
import sys

import billiard

# A task's racks by default: racks // MIN_TASKS, 1 to MAX_RACKS_PER_TASK. A task costs Dask
# milliseconds of its own (measured on a loaded 2-core machine: 400 racks of 0.05 s CPU each
# took 124 s in tasks of 8 and 164 s in tasks of 1, docs/python.md), so runs amortise it; at least MIN_TASKS tasks
# keep a cluster's workers evenly busy to the end of a match of racks of seconds.
MAX_RACKS_PER_TASK = 8
MIN_TASKS = 32
# How long the command line waits for --workers workers to join the scheduler.
WORKERS_TIMEOUT_S = 60


def play_racks_here(game, players, racks, seed, noise, shot_limit):
    """The records of `racks` (rack indices), played in this process one after the other."""
    return [billiard.play_rack(game, players, rack, seed=seed, noise=noise,
                               shot_limit=shot_limit, threads=1) for rack in racks]


def default_racks_per_task(racks):
    """A task's racks when not given: fixed by the match's rack count alone."""
    return min(MAX_RACKS_PER_TASK, max(1, racks // MIN_TASKS))


def chunks(racks, racks_per_task):
    """Racks 0..racks-1 in runs of racks_per_task (the last shorter), in order."""
    return [range(first, min(first + racks_per_task, racks))
            for first in range(0, racks, racks_per_task)]


def play_racks(client, game, players, racks, seed=1, noise="robot", shot_limit=200,
               racks_per_task=None, progress=None):
    """The records of racks 0..racks-1 of the match, played as tasks on `client`'s cluster and
    returned in rack order, `racks_per_task` racks a task (default_racks_per_task when None).
    `progress(done, racks, workers)` is told as each task ends: the racks done so far and the
    addresses of the workers that hold the task's records."""
    if racks_per_task is None:
        racks_per_task = default_racks_per_task(racks)
    if racks < 1 or racks_per_task < 1:
        raise ValueError("racks and racks_per_task must be >= 1")
    billiard.match_summary([], game, players, seed, noise)  # the names checked before any task
    import distributed  # only where a cluster plays: the module imports without it
    futures = [client.submit(play_racks_here, game, list(players), chunk, seed, noise,
                             shot_limit)
               for chunk in chunks(racks, racks_per_task)]
    if progress:
        done = 0
        for future in distributed.as_completed(futures):
            done += len(future.result())
            progress(done, racks, client.who_has(future).get(future.key, ()))
    return [record for chunk in client.gather(futures) for record in chunk]


def play_match(client, game, players, racks, seed=1, noise="robot", shot_limit=200,
               racks_per_task=None, progress=None):
    """The match as `billiard match --json` prints it, its racks played on `client`'s cluster."""
    records = play_racks(client, game, players, racks, seed, noise, shot_limit, racks_per_task,
                         progress)
    return billiard.match_summary(records, game, players, seed, noise)


def without_clock(summary):
    """A match summary without its decision times, the figures the clock does not change."""
    kept = {key: value for key, value in summary.items() if key != "decision_us"}
    kept["players"] = [{key: value for key, value in p.items() if key != "decision_us"}
                       for p in summary["players"]]
    return kept


class _Parser(argparse.ArgumentParser):
    """argparse's, its errors one line on stderr and exit 2, as every command's here."""

    def error(self, message):
        self.exit(2, f"{self.prog}: {message} (see --help)\n")


def _whole(least):
    """argparse's type of a whole number `least` or more."""
    def parse(text):
        value = int(text)
        if value < least:
            raise ValueError(text)
        return value
    parse.__name__ = f"whole number >= {least}"
    return parse


def _arguments(argv):
    parser = _Parser(
        prog="billiard_dask",
        description="billiard match with its racks as tasks on a Dask cluster")
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", help="the scheduler's address, tcp://HOST:PORT")
    where.add_argument("--local", type=_whole(1), metavar="N",
                       help="a cluster of N worker processes on this machine, one thread each")
    parser.add_argument("--workers", type=_whole(0), default=0,
                        help="wait for this many workers before playing")
    parser.add_argument("--game", required=True, help="nine-ball | eight-ball")
    parser.add_argument("--players", required=True, help="two players, A,B")
    parser.add_argument("--racks", type=_whole(1), default=20)
    parser.add_argument("--noise", default="robot")
    parser.add_argument("--seed", type=_whole(0), default=1)
    parser.add_argument("--shot-limit", type=_whole(1), default=200)
    parser.add_argument("--racks-per-task", type=_whole(1),
                        help="racks a task (default: racks // 32, 1 to 8)")
    parser.add_argument("--json", action="store_true", help="one JSON object on stdout")
    args = parser.parse_args(argv)
    args.players = args.players.split(",")
    return args


def _client(args, stack):
    """A client of --scheduler's cluster or of a local one, closed with `stack`."""
    import distributed
    if args.scheduler:
        client = stack.enter_context(distributed.Client(args.scheduler))
    else:
        cluster = stack.enter_context(distributed.LocalCluster(
            n_workers=args.local, threads_per_worker=1, processes=True, dashboard_address=None))
        client = stack.enter_context(distributed.Client(cluster))
    if args.workers:
        client.wait_for_workers(args.workers, timeout=WORKERS_TIMEOUT_S)
    return client


def main(argv=None):
    args = _arguments(argv)
    try:
        billiard.match_summary([], args.game, args.players, args.seed, args.noise)
    except ValueError as e:
        print(f"billiard_dask: {e}", file=sys.stderr)
        return 2
    with contextlib.ExitStack() as stack:
        try:
            client = _client(args, stack)
        except (OSError, TimeoutError) as e:  # no scheduler there, or too few workers in time
            print(f"billiard_dask: no cluster to play on: {e}", file=sys.stderr)
            return 1
        summary = play_match(
            client, args.game, args.players, args.racks, args.seed, args.noise,
            args.shot_limit, args.racks_per_task,
            progress=lambda done, racks, workers: print(
                f"racks {done}/{racks} ({', '.join(workers)})", file=sys.stderr))
    for p in summary["players"]:
        print(f"{p['name']}: {p['racks_won']} racks won of {summary['racks']}, {p['pots']} pots "
              f"of {p['attempts']} attempts, {p['fouls']} fouls", file=sys.stderr)
    print(json.dumps(summary), file=sys.stdout if args.json else sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
