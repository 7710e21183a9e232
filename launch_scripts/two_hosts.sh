#!/usr/bin/env bash
# usage: launch_scripts/two_hosts.sh [--shots N] [--seed S] [--dask RACKS] [--no-build]
#                                     [-h | --help]
#
# The closed loop on two computers of a LAN, made on this one: two network namespaces joined by
# a virtual Ethernet pair (10.77.0.1 and 10.77.0.2), the planner in the first, the estimator and
# the table simulator in the second, talking UDP multicast with ttl=1 across the link (as on a
# real LAN: docs/closed-loop.md, "Several hosts"). Lockstep, noise off: the shots are those of run_loop.sh
# with the same --shots and --seed. Prints the table simulator's JSON summary on stdout.
#
# With --dask, a match on a Dask cluster across the link instead (tools/python/billiard_dask.py):
# the scheduler and a worker in the first namespace, a worker and the client in the second,
# RACKS racks of nine-ball between two easiest-looking players seeded --seed; prints the
# match's JSON (that of billiard match --json for the same racks and seed).
#
#   --shots N     shots (default 5)
#   --seed S      seed of the targets, or of the match (default 1)
#   --dask RACKS  a match of RACKS racks on Dask, not the loop
#   --no-build    run what build/ holds, without build.sh first
#   -h, --help    this text
#
# It needs root and `ip netns`; without them it prints {"skipped": "<why>"} and exits 0.
set -euo pipefail
source "$(dirname "$0")/script_support.sh"

shots=5 seed=1 build=true dask_racks=0
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --shots) need_number 1 "$@"; shots=$2; shift 2 ;;
    --seed) need_number 0 "$@"; seed=$2; shift 2 ;;
    --dask) need_number 1 "$@"; dask_racks=$2; shift 2 ;;
    --no-build) build=false; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
failures_are_internal
cd "$(dirname "$0")/.."
if [ "$dask_racks" -gt 0 ]; then
  targets=(--target billiard_python)
else
  targets=(--target estimator_node --target planner_node --target table_sim_node)
fi
$build && bash launch_scripts/build.sh "${targets[@]}"

# Names of this run's own, so that runs side by side do not meet.
a=billiard_a_$$ b=billiard_b_$$
if [ "$(id -u)" -ne 0 ] || ! ip netns add "$a" 2>/dev/null; then
  echo '{"skipped": "two network namespaces need root and ip netns"}'
  exit 0
fi
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  ip netns del "$a" 2>/dev/null || true
  ip netns del "$b" 2>/dev/null || true
}
trap cleanup EXIT
ip netns add "$b"
# The pair's two ends, one in each namespace: the cable between the two computers.
ip link add "va$$" type veth peer name "vb$$"
ip link set "va$$" netns "$a"
ip link set "vb$$" netns "$b"
for side in "$a va$$ 10.77.0.1" "$b vb$$ 10.77.0.2"; do
  read -r ns dev address <<<"$side"
  ip -n "$ns" link set lo up
  ip -n "$ns" addr add "$address/24" dev "$dev"
  ip -n "$ns" link set "$dev" up multicast on
  # Multicast leaves by the LAN's interface (on a real host: the route or LCM's interface).
  ip -n "$ns" route add 224.0.0.0/4 dev "$dev"
done
if [ "$dask_racks" -gt 0 ]; then
  # The interpreter the module was built for, billiard and billiard_dask on its path.
  python=build/python/python3 scheduler=tcp://10.77.0.1:8786
  ip netns exec "$a" "$python" -m distributed.cli.dask_scheduler --host 10.77.0.1 --port 8786 \
    --no-dashboard >/dev/null 2>&1 &
  pids+=($!)
  for ns in "$a" "$b"; do
    ip netns exec "$ns" "$python" -m distributed.cli.dask_worker "$scheduler" --nworkers 1 \
      --nthreads 1 --no-dashboard >/dev/null 2>&1 &
    pids+=($!)
  done
  ip netns exec "$b" "$python" -m billiard_dask --scheduler "$scheduler" --workers 2 \
    --game nine-ball --players easiest-looking,easiest-looking --racks "$dask_racks" \
    --seed "$seed" --json
  exit 0
fi
# ttl=1: one hop, the LAN; ttl=0 would keep every datagram on its own host.
url="udpm://239.255.76.67:7667?ttl=1&recv_buf_size=4194304"
ip netns exec "$a" build/bin/planner_node --lcm-url "$url" --params pool >/dev/null 2>&1 &
pids+=($!)
ip netns exec "$b" build/bin/estimator_node --lcm-url "$url" --params pool 2>/dev/null &
pids+=($!)
sleep 0.5  # the nodes subscribe
ip netns exec "$b" build/bin/table_sim_node --lcm-url "$url" --params pool --shots "$shots" \
  --seed "$seed" --noise off
