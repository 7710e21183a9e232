#!/usr/bin/env bash
# usage: launch_scripts/setup.sh [-h | --help]
#
# Installs the Debian packages the project builds and runs with (apt-get, through sudo unless
# root). Idempotent: when nothing is missing it prints nothing and touches nothing, so every
# README command can start with it.
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
  python3 iproute2 procps
  # fuzz/: clang with libFuzzer and the sanitizer runtimes; llvm-14 for llvm-symbolizer
  clang libclang-rt-14-dev llvm-14
)
# javac for the Java message types (lcm-gen --java): the JDK only where none is installed.
command -v javac >/dev/null 2>&1 || packages+=(default-jdk-headless)
# lcm-spy's window: Swing's X11 toolkit, which a headless JRE lacks, only where no JVM has it.
ls /usr/lib/jvm/*/lib/libawt_xawt.so >/dev/null 2>&1 || packages+=(default-jre)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq >&2
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
