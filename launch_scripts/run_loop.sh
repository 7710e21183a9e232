#!/usr/bin/env bash
# The closed loop: estimator_node, planner_node and table_sim_node over LCM, for N shots to random
# targets; prints the summary on stderr and, with --json, one JSON object on stdout.
#
#   launch_scripts/run_loop.sh [--shots N] [--seed S] [--noise on|off] [--log FILE]
#                              [--lockstep | --realtime] [--json] [--no-build]
#
# LCM traffic stays on this host: inside a private network namespace with multicast routed to
# loopback when one can be made (unshare -n), else UDP multicast with ttl=0, else (no multicast
# route at all) the three nodes in one process on LCM's in-memory provider, which says so.
set -euo pipefail
cd "$(dirname "$0")/.."

shots=20 seed=1 noise=off log="" clock=--lockstep json=false build=true
while [ $# -gt 0 ]; do
  case "$1" in
    --shots) shots="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --noise) noise="$2"; shift 2 ;;
    --log) log="$2"; shift 2 ;;
    --lockstep) clock=--lockstep; shift ;;
    --realtime) clock=--realtime; shift ;;
    --json) json=true; shift ;;
    --no-build) build=false; shift ;;
    --in-namespace) in_namespace=true; shift ;;
    *) echo "run_loop: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
$build && bash launch_scripts/build.sh

source launch_scripts/lcm_network.sh
enter_private_network "$0" --no-build --shots "$shots" --seed "$seed" --noise "$noise" \
  ${log:+--log "$log"} "$clock" $($json && echo --json)
# Without a namespace, separate processes only where multicast reaches back over loopback;
# otherwise one process on LCM's in-memory provider.
in_process=false
if [ -z "${in_namespace:-}" ]; then
  if ! ip route get 239.255.76.67 >/dev/null 2>&1; then
    in_process=true
    echo "run_loop: no network namespace and no multicast route: the three nodes run in one" \
         "process over memq://${log:+ (nothing to record: --log needs multicast)}" >&2
    log=""
  else
    echo "run_loop: no network namespace; UDP multicast with ttl=0" >&2
  fi
fi

pids=()
summary_file=$(mktemp)
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -f "$summary_file"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

if [ -n "$log" ]; then
  lcm-logger --quiet --force "$log" >/dev/null 2>&1 &
  pids+=($!)
fi
if ! $in_process; then
  build/bin/estimator_node --params pool 2>/dev/null &
  pids+=($!)
  build/bin/planner_node --params pool >/dev/null 2>&1 &
  pids+=($!)
  sleep 0.5  # the nodes subscribe
fi

sim_clock=""
[ "$clock" = --realtime ] && sim_clock=--realtime
# In the background, so that a signal reaches the trap at once and the cleanup stops it too.
session=(build/bin/table_sim_node)
$in_process && session=(build/bin/billiard loop)
"${session[@]}" --params pool --shots "$shots" --seed "$seed" --noise "$noise" \
  $sim_clock >"$summary_file" &
pids+=($!)
status=0
wait $! || status=$?
[ $status -eq 130 ] && exit 130
[ $status -eq 0 ] || { echo "run_loop: table_sim_node failed (exit $status)" >&2; exit 1; }
summary=$(cat "$summary_file")
$json && echo "$summary"
python3 - "$summary" >&2 <<'PY'
import json, sys
s = json.loads(sys.argv[1])
print(f"{'shot':>4} {'target':>16} {'final':>16} {'miss mm':>9} {'plan ms':>8}  status")
for i, shot in enumerate(s["shots"]):
    t, f = shot["target"], shot["final"]
    print(f"{i:>4} ({t[0]:6.3f},{t[1]:6.3f}) ({f[0]:6.3f},{f[1]:6.3f}) {1e3*shot['miss_m']:9.2f} "
          f"{shot['plan_ms']:8.2f}  {shot['status']}")
print(f"median miss {1e3*s['median_miss_m']:.2f} mm, max {1e3*s['max_miss_m']:.2f} mm, "
      f"mean {1e3*s['mean_miss_m']:.2f} +- {1e3*s['stddev_miss_m']:.2f} mm, {s['wall_s']:.1f} s")
PY
