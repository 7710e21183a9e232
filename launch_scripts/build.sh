#!/usr/bin/env bash
# usage: launch_scripts/build.sh [--target NAME]... [-h | --help]
#
# Installs what is missing (setup.sh), configures and builds (Release, -j2) into build/: every
# target, or only those named (and what they need). Build output goes to stderr so that callers
# keep stdout for machine-readable results.
#
#   --target NAME  build NAME (a CMake target: billiard, planner_node, ...); repeatable
#   -h, --help     this text
set -euo pipefail
source "$(dirname "$0")/script_support.sh"
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --target) need_value "$@"; targets+=(--target "$2"); shift 2 ;;
    *) unknown_argument "$1" ;;
  esac
done
failures_are_internal
cd "$(dirname "$0")/.."
bash launch_scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 "${targets[@]}" >&2
