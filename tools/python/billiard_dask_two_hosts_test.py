"""A match on a Dask cluster across two hosts' network (launch_scripts/two_hosts.sh --dask: two
network namespaces joined by a virtual Ethernet pair, the scheduler and a worker on 10.77.0.1, a
worker and the client on 10.77.0.2): the same figures as `billiard match --json` for the same
racks and seed, and racks played on both hosts. Exits 77 (skipped) where the namespaces cannot
be made (no root, no `ip netns`)."""
import json
import os
import subprocess
import sys
from pathlib import Path

import billiard_dask

SOURCE = Path(__file__).resolve().parents[2]
BILLIARD_BIN = os.environ.get("BILLIARD_BIN", str(SOURCE / "build" / "bin" / "billiard"))
SKIPPED = 77  # ctest's SKIP_RETURN_CODE
RACKS, SEED = 6, 3
HOSTS = ("10.77.0.1", "10.77.0.2")


def main():
    run = subprocess.run(["bash", str(SOURCE / "launch_scripts" / "two_hosts.sh"), "--no-build",
                          "--dask", str(RACKS), "--seed", str(SEED)],
                         capture_output=True, text=True, check=True)
    summary = json.loads(run.stdout)
    if "skipped" in summary:
        print(f"skipped: {summary['skipped']}")
        return SKIPPED
    truth = json.loads(subprocess.run(
        [BILLIARD_BIN, "match", "--game", "nine-ball", "--players",
         "easiest-looking,easiest-looking", "--racks", str(RACKS), "--seed", str(SEED),
         "--threads", "2", "--json"], capture_output=True, text=True, check=True).stdout)
    if billiard_dask.without_clock(summary) != billiard_dask.without_clock(truth):
        print(f"across two hosts:\n{json.dumps(summary)}\none process:\n{json.dumps(truth)}")
        return 1
    idle = [host for host in HOSTS if f"tcp://{host}:" not in run.stderr]
    if idle:
        print(f"no rack played on {', '.join(idle)}:\n{run.stderr}")
        return 1
    print(f"{RACKS} racks on {' and '.join(HOSTS)}: the figures of billiard match --json")
    return 0


if __name__ == "__main__":
    sys.exit(main())
