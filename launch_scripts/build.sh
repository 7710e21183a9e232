#!/usr/bin/env bash
# Installs what is missing, configures and builds (Release, -j2) into build/. Build output goes to
# stderr so that callers keep stdout for machine-readable results.
set -euo pipefail
cd "$(dirname "$0")/.."
bash launch_scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2 >&2
