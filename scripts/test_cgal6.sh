#!/usr/bin/env bash
# Builds and runs the ctest suite (as scripts/test.sh: Release with assertions on,
# tests, examples, command-line program) against CGAL 6: Debian 13 (trixie)'s
# libcgal-dev, unpacked into build-cgal6/ by scripts/fetch_cgal6.sh. Nothing is
# installed system-wide for it; Boost, GMP, MPFR, TBB and CGAL's sample meshes are
# the machine's (scripts/install_dependencies.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh
build=build-cgal6
cgal_dir="$(bash scripts/fetch_cgal6.sh "$build" | tail -n 1)"
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" # cache hits across checkouts (CI clones afresh)
# Release optimisation, but without -DNDEBUG: CGAL assertions stay on in tests.
# CGAL_DIR points find_package(CGAL) at the unpacked CGAL 6 instead of /usr's 5.5.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2" \
      -DBUILD_TESTING=ON -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=ON \
      -DCGAL_DIR="$cgal_dir" | tee "$build/cmake-configure.log"
# the configure must have found the unpacked CGAL 6, not /usr's 5.5 (and the suite's
# test_cgal_version static_asserts that the headers compiled are that version)
grep -q "^-- CGAL 6\.[0-9.]* from $cgal_dir" "$build/cmake-configure.log" ||
  { echo "test_cgal6.sh: the configure did not find CGAL 6 in $cgal_dir" >&2; exit 1; }
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure -j 2
