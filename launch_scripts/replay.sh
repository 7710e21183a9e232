#!/usr/bin/env bash
# Replays a run recorded by run_loop.sh --log FILE: its CAMERA_IMAGE frames and SHOT_REQUESTs go,
# in the recorded order, through fresh estimator and planner nodes (in one process, on LCM's
# in-memory provider, each message handled before the next as in the lockstep run), and their
# TABLE_STATE and CUE_COMMAND messages are compared with the recorded ones: every TABLE_STATE field
# by field, every CUE_COMMAND in all fields but solve_us (the planning wall time). The first
# message that differs is named with its first differing field.
#
#   launch_scripts/replay.sh LOG [--params P] [--camera FILE] [--json]
#
# Paths are the caller's: the script runs the tool where it is called from. Exit 0 when all match;
# 2 when LOG is not an LCM log, is empty or cannot be read; 3 when any message differs, and when
# the log cannot be replayed bit for bit (recorded with --realtime, or --log-frames none).
set -euo pipefail
usage() { sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "$0"; }
case "${1:-}" in
  --help|-h) usage; exit 0 ;;
  "") usage >&2; exit 2 ;;
esac
exec "$(dirname "$0")/../build/bin/billiard" replay "$@"
