#!/usr/bin/env bash
# Replays a run recorded by run_loop.sh --log FILE: its CAMERA_IMAGE frames and SHOT_REQUESTs go,
# in the recorded order, through fresh estimator and planner nodes (in one process, on LCM's
# in-memory provider, each message handled before the next as in the lockstep run), and their
# TABLE_STATE and CUE_COMMAND messages are compared with the recorded ones: every TABLE_STATE byte
# for byte, every CUE_COMMAND in all fields but solve_us (the planning wall time). Exit 0 when all
# match, 3 when any differs.
#
#   launch_scripts/replay.sh LOG [--params P] [--camera FILE] [--json]
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { echo "usage: launch_scripts/replay.sh LOG [--json]" >&2; exit 2; }
exec build/bin/billiard replay "$@"
