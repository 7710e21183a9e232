#!/usr/bin/env bash
# usage: launch_scripts/two_hosts.sh [--shots N] [--seed S] [--no-build] [-h | --help]
#
# The closed loop on two computers of a LAN, made on this one: two network namespaces joined by
# a virtual Ethernet pair (10.77.0.1 and 10.77.0.2), the planner in the first, the estimator and
# the table simulator in the second, talking UDP multicast with ttl=1 across the link (as on a
# real LAN: docs/closed-loop.md, "Several hosts"). Lockstep, noise off: the shots are those of run_loop.sh
# with the same --shots and --seed. Prints the table simulator's JSON summary on stdout.
#
#   --shots N   shots (default 5)
#   --seed S    seed of the targets (default 1)
#   --no-build  run what build/ holds, without build.sh first
#   -h, --help  this text
#
# It needs root and `ip netns`; without them it prints {"skipped": "<why>"} and exits 0.
set -euo pipefail
source "$(dirname "$0")/script_support.sh"

shots=5 seed=1 build=true
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --shots) need_number 1 "$@"; shots=$2; shift 2 ;;
    --seed) need_number 0 "$@"; seed=$2; shift 2 ;;
    --no-build) build=false; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
failures_are_internal
cd "$(dirname "$0")/.."
$build && bash launch_scripts/build.sh --target estimator_node --target planner_node \
  --target table_sim_node

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
# ttl=1: one hop, the LAN; ttl=0 would keep every datagram on its own host.
url="udpm://239.255.76.67:7667?ttl=1&recv_buf_size=4194304"
ip netns exec "$a" build/bin/planner_node --lcm-url "$url" --params pool >/dev/null 2>&1 &
pids+=($!)
ip netns exec "$b" build/bin/estimator_node --lcm-url "$url" --params pool 2>/dev/null &
pids+=($!)
sleep 0.5  # the nodes subscribe
ip netns exec "$b" build/bin/table_sim_node --lcm-url "$url" --params pool --shots "$shots" \
  --seed "$seed" --noise off
