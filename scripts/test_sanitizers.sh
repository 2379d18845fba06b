#!/usr/bin/env bash
# Builds the sanitizer part of the suite (ctest label "sanitizer": the command-line
# program, the readers and writers, the repair, the fuzz corpora and the engine's core
# tests) with AddressSanitizer and UndefinedBehaviorSanitizer into build-sanitize/, and
# runs it: any memory error, leak or undefined behaviour fails it. The compiler is
# clang: the plain builds are GCC's, so the package is also compiled by a second
# compiler, and clang instruments CGAL's templates in well under half of GCC's time.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh clang libclang-rt-14-dev
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" # cache hits across checkouts (CI clones afresh)
# -g builds hash the working directory unless told not to: without this, a clone in
# another folder (as CI makes) recompiles everything
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
# -g1 (line tables): the reports' stack traces name files and lines, in less compile
# time than -g
flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=address,undefined"
cmake -S . -B build-sanitize -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
      -DBUILD_TESTING=ON -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=ON
cmake --build build-sanitize -j "$(nproc)" --target rsr_sanitizer_programs
# a huge count in a file makes CGAL's readers ask for exabytes: std::bad_alloc, handled
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$PWD/test/Range_space_remeshing/ubsan.supp"
ctest --test-dir build-sanitize --output-on-failure -j 2 -L sanitizer
