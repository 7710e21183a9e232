# Sourced first by every script of launch_scripts/ and by fuzz/run_fuzzers.sh, so that their
# command lines and exit statuses are those of every other program here (docs/exit-codes.md): --help before any work, one line on stderr and exit 2 for a bad command line, 130 when
# a signal stops the script.
#
#   help_and_exit             prints the script's usage, the comment block at its top (from its
#                             second line to the first that is not a comment), and the exit
#                             codes, on stdout; exits 0
#   usage_error MESSAGE       "NAME: MESSAGE" on stderr; exits 2
#   unknown_argument ARG      the usage error of an argument the script does not take
#   need_value "$@"           exits 2 unless the option in $1 has a value in $2
#   need_number MIN "$@"      the same, and the value is a whole number >= MIN
#   no_options "$@"           the command line of a script that takes none: --help, or nothing
#   failures_are_internal     from here on, a command of the script that fails ends it with 1,
#                             whatever its own status (cmake's 2 and ctest's 8 would read as
#                             something else); for scripts under set -e
#   bin_dir                   where the executables are: build/bin/ of the checkout the script
#                             sits in, or PREFIX/bin/ for a copy installed in
#                             PREFIX/share/billiard/launch_scripts/ (docs/installing.md)
#   installed                 true in such an installed copy, which has nothing to build

# Read now: the script may cd before it prints its usage.
script_file=$(realpath -- "$0")
script_name=$(basename -- "$0" .sh)
# A checkout has the top CMakeLists.txt above its scripts; an installed copy has not.
if [ -f "$(dirname -- "$script_file")/../CMakeLists.txt" ]; then
  installed=false
  bin_dir=$(dirname -- "$(dirname -- "$script_file")")/build/bin
else
  installed=true
  bin_dir=$(realpath -m -- "$(dirname -- "$script_file")/../../../bin")
fi

trap 'exit 130' INT TERM

help_and_exit() {
  sed -n '2,/^[^#]/{/^[^#]/d;s/^# \{0,1\}//;p}' "$script_file"
  echo
  echo "Exit codes (README.md): 0 done, 1 failed, 2 bad command line or input, 3 refused, 130"
  echo "stopped by a signal."
  exit 0
}

usage_error() {
  echo "$script_name: $1" >&2
  exit 2
}

unknown_argument() {
  usage_error "unknown argument '$1' (see --help)"
}

need_value() {
  [ $# -ge 2 ] && [ -n "$2" ] || usage_error "$1 needs a value"
}

need_number() {
  local min=$1
  shift
  need_value "$@"
  # At most 9 digits: test's integers overflow beyond 18, and no count here is near 1e9.
  [[ $2 =~ ^[0-9]{1,9}$ ]] && [ "$2" -ge "$min" ] ||
    usage_error "$1 must be a whole number >= $min, not '$2'"
}

no_options() {
  [ $# -eq 0 ] && return
  case "$1" in
    -h | --help) help_and_exit ;;
    *) unknown_argument "$1" ;;
  esac
}

failures_are_internal() {
  set -eE
  trap 'exit 1' ERR
}
