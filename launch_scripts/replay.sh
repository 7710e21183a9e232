#!/usr/bin/env bash
# usage: launch_scripts/replay.sh LOG [--params P] [--camera FILE] [--json] [-h | --help]
#
# Replays a run recorded by run_loop.sh --log FILE: its CAMERA_IMAGE frames and SHOT_REQUESTs go,
# in the recorded order, through fresh estimator and planner nodes (in one process, on LCM's
# in-memory provider, each message handled before the next as in the lockstep run), and their
# TABLE_STATE and CUE_COMMAND messages are compared with the recorded ones: every TABLE_STATE field
# by field, every CUE_COMMAND in all fields but solve_us (the planning wall time). The first
# message that differs is named with its first differing field.
#
#   LOG            the LCM log (run_loop.sh --log FILE)
#   --params P     paper | pool | a JSON parameter file, as the loop's nodes had (default pool)
#   --camera FILE  the estimator's camera model JSON, as the loop's had (default: the simulator's)
#   --json         the comparison as one JSON object on stdout
#   -h, --help     this text
#
# Paths are the caller's: the script runs the tool where it is called from. Exit 0 when all match;
# 2 when LOG is not an LCM log, is empty or cannot be read; 3 when any message differs, and when
# the log cannot be replayed bit for bit (recorded with --realtime, or --log-frames none).
set -euo pipefail
source "$(dirname "$0")/script_support.sh"
# The tool reads the rest of the command line: one parser, one set of messages.
case "${1-}" in
  -h | --help) help_and_exit ;;
  "") usage_error "which LOG? (see --help)" ;;
esac
exec "$bin_dir/billiard" replay "$@"
