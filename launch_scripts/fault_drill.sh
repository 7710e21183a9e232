#!/usr/bin/env bash
# usage: launch_scripts/fault_drill.sh [--shots N] [--no-build] [-h | --help]
#
# The fault drill: the closed loop over UDP multicast while its nodes are killed (SIGKILL) and
# started again, then a burst of shot requests at the planner. Prints one JSON object on stdout,
# the nodes' logs on stderr only when a step fails (exit 1).
#
#   --shots N   lockstep shots of sessions 1 and 2, N/2 of session 3 (default 8, at least 2)
#   --no-build  run what build/ holds, without build.sh first
#   -h, --help  this text
#
#   session 1  N lockstep shots; the estimator is killed 3 s in and started again 1 s later, then
#              the planner 4 s after that, likewise
#   session 2  a table simulator killed 3 s in, mid-session
#   session 3  a new table simulator (its clock starts again at 0) runs N/2 shots through the same
#              estimator and planner
#   stale      20 requests for a ball whose state is 2 s older than they are
#   bursts     twice 10,000 shot requests at the planner (billiard burst), with its memory
#              before and after each
#   nodes      every node process's last NODE_STATUS (billiard node-status on the drill's log)
#
# It needs the nodes as separate processes: a private network namespace or a multicast route.
# Without either it prints {"skipped": "<why>"} and exits 0.
set -euo pipefail
source "$(dirname "$0")/script_support.sh"

shots=8 build=true
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    # Session 3 runs N/2 shots, and a session has one at least.
    --shots) need_number 2 "$@"; shots=$2; shift 2 ;;
    --no-build) build=false; shift ;;
    # Added by enter_private_network when the script runs itself again in its namespace.
    --in-namespace) in_namespace=true; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
failures_are_internal
cd "$(dirname "$0")/.."
$build && bash launch_scripts/build.sh
source launch_scripts/lcm_network.sh
# By its absolute path: "$0" may be relative to the directory left by the cd above.
enter_private_network "$script_file" --no-build --shots "$shots"
if [ -z "${in_namespace:-}" ] && ! ip route get 239.255.76.67 >/dev/null 2>&1; then
  echo '{"skipped": "no network namespace and no multicast route: no separate node processes"}'
  exit 0
fi

work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
events=()
event() { events+=("{\"t_s\": $SECONDS, \"event\": \"$1\"}"); echo "fault_drill: $1" >&2; }
fail() {
  echo "fault_drill: $1" >&2
  tail -n 20 "$work"/*.err >&2 || true
  exit 1
}

start_estimator() {
  build/bin/estimator_node --params pool 2>>"$work/estimator.err" &
  estimator=$!
  pids+=($!)
}
start_planner() {
  build/bin/planner_node --params pool 2>>"$work/planner.err" &
  planner=$!
  pids+=($!)
}
table_sim() {  # output-name seed shots
  build/bin/table_sim_node --params pool --seed "$2" --shots "$3" >"$work/$1.json" \
    2>>"$work/$1.err" &
  sim=$!
  pids+=($!)
}

lcm-logger --quiet --force "$work/drill.lcm" >/dev/null 2>&1 &
pids+=($!)
start_estimator
start_planner
sleep 0.5
SECONDS=0

table_sim session1 11 "$shots"
sleep 3
kill -KILL "$estimator"; wait "$estimator" 2>/dev/null || true; event "estimator killed"
sleep 1
start_estimator; event "estimator started"
sleep 4
kill -KILL "$planner"; wait "$planner" 2>/dev/null || true; event "planner killed"
sleep 1
start_planner; event "planner started"
wait "$sim" || fail "session 1 failed"
event "session 1 done"

table_sim session2 12 "$shots"
sleep 3
kill -KILL "$sim"; event "table simulator killed"
wait "$sim" 2>/dev/null || true

table_sim session3 13 $((shots / 2))
wait "$sim" || fail "session 3 failed"
event "session 3 done"

rss_kb() { awk '/^VmRSS/ {print $2}' "/proc/$planner/status"; }
# A ball state 2 s older than the requests, as from an estimator that stopped: never planned from.
build/bin/billiard burst --json --requests 20 --state-age 2 >"$work/stale.json" \
  2>>"$work/burst.err" || fail "stale burst failed"
event "requests against a stale state answered"

# Twice: memory that a burst takes and does not give back shows as growth after the second.
rss_before=$(rss_kb)
build/bin/billiard burst --json >"$work/burst.json" 2>>"$work/burst.err" || fail "burst failed"
rss_after=$(rss_kb)
build/bin/billiard burst --json >"$work/burst2.json" 2>>"$work/burst.err" ||
  fail "second burst failed"
rss_after_second=$(rss_kb)
hwm=$(awk '/^VmHWM/ {print $2}' "/proc/$planner/status")
event "two bursts done"
sleep 2.2  # the nodes' next NODE_STATUS (once a second), after the burst

kill -TERM "${pids[0]}"  # lcm-logger: flush the log
wait "${pids[0]}" 2>/dev/null || true
build/bin/billiard node-status "$work/drill.lcm" >"$work/nodes.json"

python3 - "$work" "$rss_before" "$rss_after" "$rss_after_second" "$hwm" \
  "$(IFS=,; echo "${events[*]}")" <<'PY'
import json, sys
work, before, after, after_second, hwm, events = sys.argv[1:7]
load = lambda name: json.load(open(f"{work}/{name}.json"))
print(json.dumps({
    "session1": load("session1"),
    "session3": load("session3"),
    "burst": load("burst"),
    "second_burst": load("burst2"),
    "stale": load("stale"),
    "planner_rss_kb": {"before_burst": int(before), "after_burst": int(after),
                       "after_second_burst": int(after_second), "peak": int(hwm)},
    "nodes": load("nodes")["processes"],
    "events": json.loads(f"[{events}]"),
}))
PY
