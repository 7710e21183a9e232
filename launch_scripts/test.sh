#!/usr/bin/env bash
# The README's test command: install what is missing, configure, build with -j2, run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash launch_scripts/build.sh
ctest --test-dir build --output-on-failure -j2
