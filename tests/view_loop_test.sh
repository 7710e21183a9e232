#!/usr/bin/env bash
# usage: tests/view_loop_test.sh
#
# run_loop.sh --view as a user runs it: the live view answers on this host's port while the loop
# runs in its private network namespace, shows the table simulator's balls and the nodes' health,
# and is gone with the loop when run from a script (the port closed, the forwarding socket
# removed), kept until Ctrl-C when run from a terminal. Exit 77 (skipped)
# where no network namespace can be made: the view is then the viewer's own port, which
# tests/viewer_test.cc holds.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
unshare -n true 2>/dev/null || { echo "view_loop_test: no network namespace here" >&2; exit 77; }
port=$((20000 + RANDOM % 20000))
err=$(mktemp)
trap 'rm -f "$err"' EXIT
bash "$repo/launch_scripts/run_loop.sh" --no-build --shots 3 --realtime --view-port "$port" \
  >/dev/null 2>"$err" &
loop=$!
state=""
for _ in $(seq 100); do
  state=$(curl -s -m 1 "http://127.0.0.1:$port/state.json" || true)
  case "$state" in *'"truth"'*'"x"'*) break ;; esac
  sleep 0.2
done
wait "$loop" || { echo "view_loop_test: run_loop.sh failed" >&2; cat "$err" >&2; exit 1; }
fail() { echo "view_loop_test: $*" >&2; exit 1; }
grep -q "the live view is at http://127.0.0.1:$port/" "$err" || fail "no address printed"
case "$state" in *'"truth"'*'"x"'*) ;; *) fail "the view showed no ball: ${state:0:200}" ;; esac
case "$state" in *'"planner_node"'*) ;; *) fail "the view showed no node's health" ;; esac
curl -s -m 1 "http://127.0.0.1:$port/" >/dev/null && fail "the view outlived the loop"
ls "${TMPDIR:-/tmp}"/billiard-view.*.sock 2>/dev/null | grep -q . && fail "a forwarding socket was left"
echo "view_loop_test: the view answered during the loop and closed with it"

# From a terminal (script(1)'s pseudo-terminal), the view keeps the last table after the run and
# closes at Ctrl-C (SIGINT to the terminal's foreground process group), the run's status 0.
# (Started &, a non-interactive shell would hand it SIGINT ignored, which no trap can undo. The
# command is exec'd: where SHELL is sh, script(1)'s `sh -c` would otherwise stay as the parent
# and die of the Ctrl-C itself, status 130, as it did in CI.)
command -v script >/dev/null || { echo "view_loop_test: no script(1) for a terminal" >&2; exit 77; }
out=$(mktemp)
trap 'rm -f "$err" "$out"' EXIT
env --default-signal=INT script -qfec "exec bash '$repo/launch_scripts/run_loop.sh' --no-build --shots 1 --view-port $port" \
  /dev/null </dev/null >"$out" 2>&1 &
terminal=$!
for _ in $(seq 150); do grep -q "the run is over" "$out" && break; sleep 0.2; done
grep -q "the live view keeps its last table at http://127.0.0.1:$port/ until Ctrl-C" "$out" ||
  fail "no word of the view kept: $(tail -n 3 "$out")"
sleep 1
case "$(curl -s -m 1 "http://127.0.0.1:$port/state.json" || true)" in
  *'"truth"'*'"x"'*) ;;
  *) fail "the view did not keep the last table after the run" ;;
esac
run=$(pgrep -P "$terminal" | head -n 1)
kill -INT -- "-$(ps -o pgid= -p "$run" | tr -d ' ')"
status=0
wait "$terminal" || status=$?
[ "$status" -eq 0 ] || fail "Ctrl-C after the run ended it with status $status"
curl -s -m 1 "http://127.0.0.1:$port/" >/dev/null && fail "the view outlived Ctrl-C"
echo "view_loop_test: from a terminal the view kept the last table until Ctrl-C"
