#!/usr/bin/env bash
# usage: launch_scripts/build.sh [-h | --help]
#
# Installs what is missing (setup.sh), configures and builds (Release, -j2) into build/. Build
# output goes to stderr so that callers keep stdout for machine-readable results.
#
#   -h, --help  this text
set -euo pipefail
source "$(dirname "$0")/script_support.sh"
no_options "$@"
failures_are_internal
cd "$(dirname "$0")/.."
bash launch_scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 >&2
