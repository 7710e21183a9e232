#!/usr/bin/env bash
# usage: fuzz/run_fuzzers.sh [--minutes M | --seconds S] [--json] [--seed N] [--corpus DIR]
#                            [--artifacts DIR] [--bin-dir DIR] [-h | --help] [TARGET...]
#
# Runs fuzz targets for a bounded time each, one after the other, from their generated seeds, and
# reports libFuzzer's final figures per target: a table on stderr, and with --json one JSON object
# on stdout. Exits 1 when any target crashed (a crash, leak, timeout, out-of-memory, sanitizer
# report or broken property); the inputs that did are kept under the artifacts folder.
#
#   --minutes M      minutes per target (default 1)
#   --seconds S      seconds per target, instead of --minutes
#   --json           the figures as one JSON object on stdout
#   --seed N         libFuzzer's seed (default 1; 0: a random one)
#   --corpus DIR     keep what the runs find in DIR/TARGET, and go on from there next time
#                    (default: each run starts from the seeds alone, in a temporary folder)
#   --artifacts DIR  where the inputs that crashed are kept (default: BIN_DIR/../fuzz-artifacts)
#   --bin-dir DIR    where the targets are (default: build/bin)
#   -h, --help       this text
#   TARGET           fuzz_table_state, fuzz_image, ... (default: every fuzz_* of the bin folder)
#
# No targets to run, or a TARGET that is not there, is exit 2 (build with launch_scripts/build.sh).
set -uo pipefail
source "$(dirname "$0")/../launch_scripts/script_support.sh"

repo=$(cd "$(dirname "$0")/.." && pwd)
seconds=60
json=0
seed=1
corpus_root=
bin_dir=$repo/build/bin
artifacts=
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h | --help) help_and_exit ;;
    --minutes) need_number 1 "$@"; seconds=$(($2 * 60)); shift 2 ;;
    --seconds) need_number 1 "$@"; seconds=$2; shift 2 ;;
    --json) json=1; shift ;;
    --seed) need_number 0 "$@"; seed=$2; shift 2 ;;
    --corpus) need_value "$@"; corpus_root=$2; shift 2 ;;
    --artifacts) need_value "$@"; artifacts=$2; shift 2 ;;
    --bin-dir) need_value "$@"; bin_dir=$2; shift 2 ;;
    -*) unknown_argument "$1" ;;
    *) targets+=("$1"); shift ;;
  esac
done
artifacts=${artifacts:-$bin_dir/../fuzz-artifacts}
if [ ${#targets[@]} -eq 0 ]; then
  for f in "$bin_dir"/fuzz_*; do [ -x "$f" ] && targets+=("$(basename "$f")"); done
fi
[ ${#targets[@]} -gt 0 ] ||
  usage_error "no fuzz targets in $bin_dir (build with launch_scripts/build.sh)"
# Before the first target runs: a mistyped one is said at once, not minutes later.
for target in "${targets[@]}"; do
  [ -x "$bin_dir/$target" ] || usage_error "no $bin_dir/$target"
done

# ASan finds llvm-symbolizer on the PATH only; Debian's llvm-14 installs it with a suffix.
if ! command -v llvm-symbolizer >/dev/null && command -v llvm-symbolizer-14 >/dev/null; then
  export ASAN_SYMBOLIZER_PATH=$(command -v llvm-symbolizer-14)
fi
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The number after `key` on the last line of the log that has one (0 if none).
last_number() { grep -o "$2[: ]*[0-9]*" "$1" | tail -n 1 | grep -o '[0-9]*$' || echo 0; }

row='%-18s %10s %8s %7s %6s %7s %6s %7s\n'
printf "$row" target runs exec/s corpus cov ft rss_mb crashes >&2
entries=()
total_crashes=0
for target in "${targets[@]}"; do
  binary=$bin_dir/$target
  corpus=${corpus_root:+$corpus_root/$target}
  corpus=${corpus:-$work/$target/corpus}
  mkdir -p "$corpus" "$work/$target/artifacts"
  "$binary" -write_seeds="$corpus" || exit 1
  log=$work/$target/log
  "$binary" -max_total_time="$seconds" -seed="$seed" -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$work/$target/artifacts/" "$corpus" >"$log" 2>&1
  status=$?

  kept=()
  for a in "$work/$target"/artifacts/*; do
    [ -e "$a" ] || continue
    mkdir -p "$artifacts/$target"
    mv "$a" "$artifacts/$target/"
    kept+=("$(cd "$artifacts/$target" && pwd)/$(basename "$a")")
  done
  crashes=${#kept[@]}
  [ "$status" -ne 0 ] && [ "$crashes" -eq 0 ] && crashes=1
  total_crashes=$((total_crashes + crashes))

  # libFuzzer's final stats, and the last status line's coverage (cov: edges, ft: features) and
  # corpus (corp: inputs kept).
  runs=$(last_number "$log" 'stat::number_of_executed_units')
  rate=$(last_number "$log" 'stat::average_exec_per_sec')
  rss=$(last_number "$log" 'stat::peak_rss_mb')
  cov=$(last_number "$log" ' cov')
  ft=$(last_number "$log" ' ft')
  units=$(last_number "$log" ' corp')
  printf "$row" "$target" "$runs" "$rate" "$units" "$cov" "$ft" "$rss" "$crashes" >&2
  if [ "$crashes" -ne 0 ]; then
    echo "---- $target: exit $status, the end of its log ----" >&2
    tail -n 60 "$log" >&2
    for a in "${kept[@]}"; do echo "reproduce: $binary $a" >&2; done
  fi
  list=
  [ ${#kept[@]} -gt 0 ] && list=$(printf '"%s",' "${kept[@]}")
  entries+=("$(printf '{"target":"%s","seconds":%s,"runs":%s,"execs_per_sec":%s,"corpus_size":%s,"coverage":%s,"features":%s,"peak_rss_mb":%s,"crashes":%s,"artifacts":[%s]}' \
    "$target" "$seconds" "$runs" "$rate" "$units" "$cov" "$ft" "$rss" "$crashes" "${list%,}")")
done

if [ "$json" -eq 1 ]; then
  joined=$(IFS=,; echo "${entries[*]}")
  printf '{"seconds_per_target":%s,"seed":%s,"crashes":%s,"targets":[%s]}\n' "$seconds" "$seed" \
    "$total_crashes" "$joined"
fi
[ "$total_crashes" -eq 0 ]
