#!/usr/bin/env bash
# usage: launch_scripts/spy.sh [--lcm-url URL] [--build-dir DIR] [--check] [-h | --help]
#
# lcm-spy, LCM's viewer of live traffic (it needs a display), on the LCM traffic of URL, decoding
# the project's messages (lcmtypes/*.lcm) from the jar the build makes,
# DIR/lcmtypes/java/billiard_lcmtypes.jar.
#
#   --lcm-url URL    the LCM URL to listen on (default: $LCM_DEFAULT_URL, else the project's
#                    multicast URL of launch_scripts/lcm_network.sh)
#   --build-dir DIR  the build tree (default: build)
#   --check          open no window: load lcm-spy's type database and report which of the
#                    project's types it would decode, one line per type on stderr and a JSON
#                    object {"decoded":{TYPE:FINGERPRINT,..},"missing":[TYPE,..]} on stdout;
#                    exit 1 when any is missing
#   -h, --help       this text
#
# Exit 1 also without a build, lcm-spy's jars or a display. Debian's lcm-spy wrapper cannot start
# on Java 17 (it passes -Xincgc, which no JVM since 9 accepts), so this runs lcm-spy's main class
# itself, on the wrapper's classpath plus the jar of the project's types.
set -euo pipefail
source "$(dirname "$0")/script_support.sh"

lcm_jar=/usr/share/java/lcm.jar
jchart2d_jar=/usr/share/java/jchart2d.jar

fail() {
  echo "spy: $1" >&2
  exit 1
}

url=${LCM_DEFAULT_URL:-} build_dir=build check=false
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --lcm-url) need_value "$@"; url=$2; shift 2 ;;
    --lcm-url=*) url=${1#*=}; shift ;;
    --build-dir) need_value "$@"; build_dir=$2; shift 2 ;;
    --check) check=true; shift ;;
    *) unknown_argument "$1" ;;
  esac
done
cd "$(dirname "$0")/.."
# The nodes the scripts start talk on the project's URL. Its private network namespace is not
# entered: lcm-spy there would see no one.
if [ -z "$url" ]; then
  source launch_scripts/lcm_network.sh
  url=$LCM_DEFAULT_URL
fi

java_out=$build_dir/lcmtypes/java
types_jar=$java_out/billiard_lcmtypes.jar
[ -f "$types_jar" ] || fail "no $types_jar: build first (bash launch_scripts/build.sh)"
for jar in "$lcm_jar" "$jchart2d_jar"; do
  [ -f "$jar" ] || fail "no $jar: install what lcm-spy needs (bash launch_scripts/setup.sh)"
done
classpath=$types_jar:$lcm_jar:$jchart2d_jar

if $check; then
  types=()
  for lcm_file in lcmtypes/*.lcm; do types+=("billiard.$(basename "$lcm_file" .lcm)"); done
  exec java -Djava.awt.headless=true -cp "$java_out/helpers:$classpath" SpyTypeCheck "${types[@]}"
fi

[ -n "${DISPLAY:-}" ] ||
  fail "no display (DISPLAY is unset): lcm-spy opens a window; --check does not"
# IPv4, as Debian's wrapper asks: LCM's multicast groups are IPv4.
exec java -Djava.net.preferIPv4Stack=true -cp "$classpath" lcm.spy.Spy --lcm-url "$url"
