#!/usr/bin/env bash
# usage: launch_scripts/setup.sh [-h | --help]
#
# Installs the Debian packages the project builds and runs with (apt-get, through sudo unless
# root). Idempotent: when nothing is missing it says so in one line on stderr and touches
# nothing, so every README command can start with it.
#
#   -h, --help  this text
set -euo pipefail
source "$(dirname "$0")/script_support.sh"
no_options "$@"
failures_are_internal

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libceres-dev libopencv-dev libjpeg62-turbo-dev
  liblcm-dev liblcm-bin liblcm-java libglib2.0-dev
  # lcm-spy's charts (launch_scripts/spy.sh)
  libjchart2d-java
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcli11-dev
  # tools/viewer_node/: its HTTP server; its test's browser and HTTP client; run_loop.sh --view's
  # forwarding of the view out of the loop's network namespace
  libcpp-httplib-dev chromium curl socat
  # tools/camera_node/: GStreamer's base elements (videotestsrc, videoconvert, appsink), for a
  # --device pipeline and the test that plays one
  gstreamer1.0-plugins-base
  # plot/: billiard plot's pictures and billiard bench's chart
  libcairo2-dev
  # tools/python/: the billiard Python module (pybind11) and its pytest suite, on Debian's
  # python3 with Debian's NumPy; Dask's distributed for billiard_dask.py's matches on a cluster
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed
  # bench/peer_solvers.h: the solvers `billiard bench` measures ours against (Boost.Odeint,
  # header-only; SUNDIALS CVODE)
  libboost-dev libsundials-dev
  python3 iproute2 procps
  # spy.sh's window on a machine without a display: xvfb-run (and the xauth it runs)
  xvfb xauth
  # fuzz/: clang with libFuzzer and the sanitizer runtimes; llvm-14 for llvm-symbolizer
  clang libclang-rt-14-dev llvm-14
)
# javac for the Java message types (lcm-gen --java): the JDK only where none is installed.
command -v javac >/dev/null 2>&1 || packages+=(default-jdk-headless)
# lcm-spy's window: Swing's X11 toolkit, which a headless JRE lacks, only where no JVM has it.
ls /usr/lib/jvm/*/lib/libawt_xawt.so >/dev/null 2>&1 || packages+=(default-jre)

# The UDP receive buffer the nodes ask for (launch_scripts/lcm_network.sh: recv_buf_size): a
# stock kernel grants at most 208 kB, and a burst beyond it is dropped unseen. Raised (and kept
# across reboots) only by root, and only where it is lower; a container's read-only /proc/sys
# leaves it as it is, and the nodes say what to run.
receive_buffer=4194304
raise_receive_buffer() {
  local now
  now=$(cat /proc/sys/net/core/rmem_max 2>/dev/null || echo "$receive_buffer")
  [ "$now" -ge "$receive_buffer" ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: net.core.rmem_max is $now;" \
         "run as root: sysctl -w net.core.rmem_max=$receive_buffer" >&2
    return 0
  fi
  if { echo "$receive_buffer" >/proc/sys/net/core/rmem_max; } 2>/dev/null; then
    { echo "net.core.rmem_max = $receive_buffer" >/etc/sysctl.d/60-billiard-lcm.conf; } \
      2>/dev/null || true
    echo "setup: net.core.rmem_max raised from $now to $receive_buffer" >&2
  else
    echo "setup: cannot raise net.core.rmem_max from $now (read-only here)" >&2
  fi
}
raise_receive_buffer

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages the project needs are installed" >&2
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq >&2
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
