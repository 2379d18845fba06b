#!/usr/bin/env bash
# Fuzzes with libFuzzer (clang, with AddressSanitizer and UndefinedBehaviorSanitizer)
# one of its targets:
#   remesh  the command-line program's input path and the remesher (fuzz_remesh.cpp)
#   read    the program's reader, prepare_input() and the writers, read back (fuzz_read.cpp)
#   options the program's option parser, on arguments separated by NUL bytes (fuzz_options.cpp)
#
#   scripts/fuzz.sh [SECONDS] [JOBS] [TARGET]     (default: 600 seconds, 1 job, remesh)
#
# Starts from test/Range_space_remeshing/fuzz/corpus (remesh), fuzz/read_corpus (read)
# or fuzz/options_corpus (options, with the option names of fuzz/options.dict); what
# it learns goes to build-fuzz/<target>/corpus, crashes to
# build-fuzz/<target>/artifacts. Keep each crash's reproducer in fuzz/regressions/,
# fuzz/read_regressions/ or fuzz/options_regressions/ once fixed: ctest replays them.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
jobs="${2:-1}"
target="${3:-remesh}"
dictionary=()
case "$target" in
  remesh) seeds=test/Range_space_remeshing/fuzz/corpus; max_len=8192 ;;
  read) seeds=test/Range_space_remeshing/fuzz/read_corpus; max_len=16384 ;;
  options) seeds=test/Range_space_remeshing/fuzz/options_corpus; max_len=1024
           dictionary=(-dict=test/Range_space_remeshing/fuzz/options.dict) ;;
  *) echo "fuzz.sh: unknown target '$target' (remesh, read, options)" >&2; exit 2 ;;
esac

bash scripts/install_dependencies.sh clang libclang-rt-14-dev

work="build-fuzz/$target"
mkdir -p "$work/corpus" "$work/artifacts"
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
binary="$work/fuzz_$target"
ccache clang++ -std=c++17 -O1 -g -DRSR_LIBFUZZER -fsanitize=fuzzer,address,undefined \
  -Iinclude -Itools/range_space_remesh \
  "test/Range_space_remeshing/fuzz/fuzz_$target.cpp" -lgmp -lmpfr -o "$binary"
parallel=()
if [ "$jobs" -gt 1 ]; then parallel=(-jobs="$jobs" -workers="$jobs"); fi
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=test/Range_space_remeshing/ubsan.supp \
  "$binary" -max_total_time="$seconds" "${parallel[@]}" "${dictionary[@]}" -max_len="$max_len" -rss_limit_mb=6144 \
  -malloc_limit_mb=16384 -timeout=20 -artifact_prefix="$work/artifacts/" -print_final_stats=1 \
  "$work/corpus" "$seeds"
