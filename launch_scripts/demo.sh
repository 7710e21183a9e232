#!/usr/bin/env bash
# The README's main command until the closed loop lands (issue 6): install, build, and simulate the
# five initial states of seed 000's Figs. 6-10 with every model; prints one table on stderr and,
# with --json, the per-run JSON objects on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
json=false
[ "${1:-}" = "--json" ] && json=true
bash launch_scripts/build.sh

figures=("0,0,0,1,-50,0,0" "0,0,0,1,-50,5,0" "0,0,0,1,150,5,0" "0,0,0,1,-50,-3.5,-150" "0,0,0,1,150,0,-150")
printf '%-6s %-12s %12s %12s %8s %12s\n' fig model X_m Y_m steps wall_us >&2
for i in "${!figures[@]}"; do
  for model in closed-form approx integral; do
    out=$(build/bin/billiard simulate --state "${figures[$i]}" --t-end 8 --model "$model" --json)
    $json && echo "$out"
    python3 - "$((i + 6))" "$out" >&2 <<'PY'
import json, sys
j = json.loads(sys.argv[2])
print(f"{sys.argv[1]:<6} {j['model']:<12} {j['state'][0]:12.6f} {j['state'][1]:12.6f} "
      f"{j['steps']:8d} {j['wall_us']:12.1f}")
PY
  done
done
