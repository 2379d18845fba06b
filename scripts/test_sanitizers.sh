#!/usr/bin/env bash
# Builds the tests and the command-line program with AddressSanitizer and
# UndefinedBehaviorSanitizer (into build-sanitize/) and runs the ctest suite there:
# any memory error, leak or undefined behaviour fails it.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" # cache hits across checkouts (CI clones afresh)
# -g builds hash the working directory unless told not to: without this, a clone in
# another folder (as CI makes) recompiles everything
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
# -g1 (line tables): the reports' stack traces name files and lines, and a translation
# unit compiles in about 2/3 of the time of -g (fuzz_remesh.cpp: 415 s against 602 s)
flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=address,undefined"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
      -DBUILD_TESTING=ON -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=ON
# the tests and the command-line program; the examples and the installation and subproject tests
# add no code of the library that the suite does not already run
cmake --build build-sanitize -j "$(nproc)" --target rsr_test_programs
# a huge count in a file makes CGAL's readers ask for exabytes: std::bad_alloc, handled
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$PWD/test/Range_space_remeshing/ubsan.supp"
ctest --test-dir build-sanitize --output-on-failure -j 2 -E "^(example_|test_install|test_subdirectory)"
