#!/usr/bin/env bash
# usage: tests/install_test.sh BUILD_DIR examples | deb
#
# The library as a user gets it (docs/installing.md), registered with ctest (label integration):
#
#   examples  installs BUILD_DIR into a temporary prefix, copies examples/ out of the tree, builds
#             each with find_package(billiard) and that prefix alone (no path of the source or
#             build tree in any compile or link command), and runs them: the break simulates to
#             rest, the C++ and Java clients get a plan from the installed planner_node. Also: the
#             installed headers include only billiard/... paths, the physics headers and a
#             physics-and-params project need nothing but Eigen and nlohmann-json, both
#             pkg-config files compile and link a program, and the installed billiard runs the
#             installed parameter files as the built-in sets.
#   deb       cpack -G DEB in a temporary directory: the package holds the binaries, the headers,
#             the CMake package and the data, and every Depends is a package setup.sh installs.
#
# Prints what fails on stderr and exits 1; 0 when all holds; 77 (skipped) when the clients cannot
# reach a node, where there is neither a network namespace nor a multicast route.
set -euo pipefail
source "$(dirname "$0")/../launch_scripts/script_support.sh"
source "$(dirname "$0")/../launch_scripts/lcm_network.sh"
[ $# -ge 2 ] || usage_error "needs BUILD_DIR and examples or deb"
build=$(realpath -- "$1")
mode=$2
# Added by enter_private_network when the script runs itself again in its namespace.
[ "${3:-}" = --in-namespace ] && in_namespace=true
source_dir=$(realpath -- "$(dirname "$0")/..")
case "$mode" in
  examples) enter_private_network "$0" "$@" ;;  # the clients' LCM traffic stays in the test
  deb) ;;
  *) usage_error "unknown mode '$mode' (examples or deb)" ;;
esac

work=$(mktemp -d /tmp/billiard_install_XXXXXX)
planner_pid=""
cleanup() {
  [ -n "$planner_pid" ] && kill "$planner_pid" 2>/dev/null && wait "$planner_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "install_test: $*" >&2
  exit 1
}
# `expect DESCRIPTION COMMAND...`: fails with DESCRIPTION unless COMMAND succeeds.
expect() {
  local what=$1
  shift
  "$@" || fail "$what"
}

if [ "$mode" = deb ]; then
  (cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" >cpack.log 2>&1) ||
    fail "cpack failed: $(tail -5 "$work/cpack.log")"
  deb=$(ls "$work"/billiard_*.deb)
  contents=$(dpkg-deb --contents "$deb" | awk '{print $6}')
  for path in ./usr/bin/billiard ./usr/bin/planner_node ./usr/bin/estimator_node \
      ./usr/bin/table_sim_node ./usr/bin/camera_node ./usr/bin/viewer_node \
      ./usr/include/billiard/sim/physics/simulator.h \
      ./usr/include/billiard/lcmtypes/billiard/cue_command_t.hpp \
      ./usr/include/billiard/planner/shot_planner.h \
      ./usr/lib/cmake/billiard/billiardConfig.cmake \
      ./usr/lib/cmake/billiard/billiard-planner-targets.cmake \
      ./usr/lib/pkgconfig/billiard.pc ./usr/lib/libbilliard_physics.a \
      ./usr/share/billiard/params/pool.json ./usr/share/billiard/params/tables/pool-9ft.json \
      ./usr/share/billiard/lcmtypes/shot_request_t.lcm ./usr/share/java/billiard_lcmtypes.jar \
      ./usr/share/billiard/launch_scripts/run_loop.sh \
      ./usr/share/billiard/launch_scripts/camera_mode.sh; do
    grep -qxF "$path" <<<"$contents" || fail "the .deb lacks $path"
  done
  version=$("$build/bin/billiard" --version | cut -d' ' -f2)
  [ "$(dpkg-deb -f "$deb" Version)" = "$version" ] ||
    fail "the .deb is version $(dpkg-deb -f "$deb" Version), billiard --version $version"
  # Every dependency declared is one setup.sh installs (the words of its package list).
  setup_packages=$(sed -n '/^packages=(/,/^)/p' "$source_dir/launch_scripts/setup.sh" |
                     sed 's/#.*//' | tr ' ()' '\n\n\n')
  for dependency in $(dpkg-deb -f "$deb" Depends | tr ',' '\n' | awk '{print $1}'); do
    grep -qxF "$dependency" <<<"$setup_packages" ||
      fail "the .deb depends on $dependency, which setup.sh does not install"
  done
  echo "install_test: $(basename "$deb"): $(wc -l <<<"$contents") entries, Depends:" \
       "$(dpkg-deb -f "$deb" Depends)" >&2
  exit 0
fi

prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >"$work/install.log" || fail "cmake --install failed"

# Headers: every project include under billiard/, and the physics's need Eigen alone.
if grep -rnE '#include "(sim|planner|estimator|lcmtypes)/' "$prefix/include"; then
  fail "installed headers include paths of the source tree (above)"
fi
if grep -rnE '#include <(ceres|opencv2|lcm|nlohmann)/' "$prefix"/include/billiard/sim/{physics,batch,table,cue}; then
  fail "the installed physics headers include more than Eigen (above)"
fi

# The examples, copied out of the tree, built against the prefix alone.
cp -r "$source_dir/examples" "$work/examples"
for example in simulate_break shot_client java_shot_client; do
  cmake -S "$work/examples/$example" -B "$work/build/$example" -DCMAKE_PREFIX_PATH="$prefix" \
        -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_BUILD_TYPE=Release >"$work/$example.log" 2>&1 ||
    fail "$example does not configure: $(grep -A3 'Error' "$work/$example.log" | head -8)"
  cmake --build "$work/build/$example" -j2 >>"$work/$example.log" 2>&1 ||
    fail "$example does not build: $(grep -B2 -A6 'rror' "$work/$example.log" | head -20)"
  if grep -rlF -e "$source_dir" -e "$build" "$work/build/$example" --include='*.json' \
       --include='*.make' --include='*.txt'; then
    fail "$example was built with a path of the source or build tree (files above)"
  fi
done
# physics and params need no Ceres, OpenCV or LCM.
if grep -E '^(Ceres|OpenCV)_DIR|^LCM_' "$work/build/simulate_break/CMakeCache.txt"; then
  fail "find_package(billiard COMPONENTS physics params) found more than Eigen and nlohmann-json"
fi

break_json=$("$work/build/simulate_break/simulate_break" 3) || fail "simulate_break failed"
python3 - "$break_json" <<'EOF' || fail "the break did not simulate: $break_json"
import json, sys
b = json.loads(sys.argv[1])
assert b["at_rest"] and b["events"]["ball_ball"] >= 15 and b["events"]["ball_cushion"] >= 1, b
EOF

# pkg-config: the physics alone, and everything (the break links with it too).
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
cat >"$work/physics_only.cc" <<'EOF'
#include <iostream>

#include "billiard/sim/physics/simulator.h"

int main() { std::cout << billiard::physics::ModelName(billiard::physics::Model::kApproximate) << "\n"; }
EOF
# shellcheck disable=SC2046  # pkg-config's flags are words
g++ -std=c++17 "$work/physics_only.cc" -o "$work/physics_only" \
    $(pkg-config --cflags --libs billiard-physics) || fail "billiard-physics.pc does not link"
[ "$("$work/physics_only")" = approx ] || fail "the physics-only program printed otherwise"
# shellcheck disable=SC2046
g++ -std=c++17 -O1 "$work/examples/simulate_break/simulate_break.cc" -o "$work/break_pc" \
    $(pkg-config --cflags --libs billiard) || fail "billiard.pc does not link the break"
[ "$("$work/break_pc" 3)" = "$break_json" ] || fail "the pkg-config break differs"

# The installed tool: the build's version, and the installed parameter file runs as the built-in
# set of its name.
tool=$prefix/bin/billiard
[ "$("$tool" --version)" = "$("$build/bin/billiard" --version)" ] ||
  fail "the installed billiard is version '$("$tool" --version)'"
state=(--state 0.5,0.5,1,0.2,0,0,0 --t-end 3)
builtin=$("$tool" simulate "${state[@]}" --params pool --json) || fail "billiard simulate failed"
from_file=$("$tool" simulate "${state[@]}" --params "$prefix/share/billiard/params/pool.json" \
              --json) || fail "billiard simulate --params share/billiard/params/pool.json failed"
python3 - "$builtin" "$from_file" <<'EOF' || fail "the installed pool.json is not the built-in pool"
import json, sys
a, b = (json.loads(s) for s in sys.argv[1:])
assert a["state"] == b["state"], (a["state"], b["state"])
EOF

# The clients against the installed planner_node, over multicast: where there is neither a
# namespace nor a multicast route the rest is skipped (exit 77, ctest's SKIP_RETURN_CODE).
if [ -z "${in_namespace:-}" ] && ! ip route get 239.255.76.67 >/dev/null 2>&1; then
  echo "install_test: no network namespace and no multicast route: the clients and the loop" \
       "are not run" >&2
  exit 77
fi
"$prefix/bin/planner_node" --params pool 2>"$work/planner.err" &
planner_pid=$!
for client in "$work/build/shot_client/shot_client" \
              "$work/build/java_shot_client/run_java_shot_client"; do
  plan=$("$client" --from 0.5,0.5 --to 1.5,0.8 --timeout 20) ||
    fail "$(basename "$client") got no plan: $(tail -3 "$work/planner.err")"
  python3 - "$plan" <<'EOF' || fail "$(basename "$client") printed no plan to the target: $plan"
import json, sys
p = json.loads(sys.argv[1])
assert p["status"] == 0 and p["cue"]["speed"] > 0, p
assert abs(p["predicted_final"][0] - 1.5) < 1e-3 and abs(p["predicted_final"][1] - 0.8) < 1e-3, p
EOF
done
# A refusal is a plan too: status and reason, exit 3.
set +e
refused=$("$work/build/shot_client/shot_client" --to 9,9 --timeout 20)
status=$?
set -e
[ $status -eq 3 ] && grep -q '"status":2' <<<"$refused" ||
  fail "a target off the table was not refused (exit $status): $refused"
# The installed closed loop: its scripts run the installed nodes, nothing of the tree.
loop=$(cd "$work" && bash "$prefix/share/billiard/launch_scripts/run_loop.sh" --shots 1 --json \
         2>"$work/loop.err") || fail "the installed run_loop.sh failed: $(tail -3 "$work/loop.err")"
python3 - "$loop" <<'EOF' || fail "the installed loop did not land its shot: $loop"
import json, sys
s = json.loads(sys.argv[1])
assert len(s["shots"]) == 1 and s["shots"][0]["status"] == "ok" and s["max_miss_m"] < 0.01, s
EOF
echo "install_test: examples built against $prefix and run: break $break_json" >&2
