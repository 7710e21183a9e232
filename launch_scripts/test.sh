#!/usr/bin/env bash
# usage: launch_scripts/test.sh [--no-build] [-h | --help]
#
# The README's test command: install what is missing, configure, build with -j2 (build.sh), run
# every test. Exit 1 when the build or any test fails.
#
#   --no-build  test what build/ holds as it is
#   -h, --help  this text
set -euo pipefail
source "$(dirname "$0")/script_support.sh"
build=true
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --no-build) build=false; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
failures_are_internal
cd "$(dirname "$0")/.."
$build && bash launch_scripts/build.sh
ctest --test-dir build --output-on-failure -j2
