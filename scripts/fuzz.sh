#!/usr/bin/env bash
# Fuzzes the command-line program's input path and the remesher with libFuzzer
# (clang, with AddressSanitizer and UndefinedBehaviorSanitizer).
#
#   scripts/fuzz.sh [SECONDS] [JOBS]     (default: 600 seconds, 1 job)
#
# Starts from test/Range_space_remeshing/fuzz/corpus; what it learns goes to
# build-fuzz/corpus, crashes to build-fuzz/artifacts. Keep each crash's reproducer in
# test/Range_space_remeshing/fuzz/regressions/ once fixed: ctest replays them.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
jobs="${2:-1}"

bash scripts/install_dependencies.sh clang libclang-rt-14-dev

mkdir -p build-fuzz/corpus build-fuzz/artifacts
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
binary=build-fuzz/fuzz_remesh
ccache clang++ -std=c++17 -O1 -g -DRSR_LIBFUZZER -fsanitize=fuzzer,address,undefined \
  -Iinclude -Iexamples/Range_space_remeshing \
  test/Range_space_remeshing/fuzz/fuzz_remesh.cpp -lgmp -lmpfr -o "$binary"
parallel=()
if [ "$jobs" -gt 1 ]; then parallel=(-jobs="$jobs" -workers="$jobs"); fi
# a huge count in a file makes CGAL's readers ask for exabytes: std::bad_alloc, handled
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=test/Range_space_remeshing/ubsan.supp \
  "$binary" -max_total_time="$seconds" "${parallel[@]}" -max_len=8192 -rss_limit_mb=6144 -malloc_limit_mb=16384 \
  -timeout=20 -artifact_prefix=build-fuzz/artifacts/ -print_final_stats=1 \
  build-fuzz/corpus test/Range_space_remeshing/fuzz/corpus
