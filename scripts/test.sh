#!/usr/bin/env bash
# Builds the package's tests, examples, command-line program and benchmark programs
# (Release with assertions on) into build/ and runs the ctest suite. The benchmarks
# are only built here (so that they keep compiling); scripts/bench.sh runs them.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh libeigen3-dev # Eigen: the benchmarks' peers
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" # cache hits across checkouts (CI clones afresh)
# Release optimisation, but without -DNDEBUG: CGAL assertions stay on in tests.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2" \
      -DBUILD_TESTING=ON -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=ON \
      -DRANGE_SPACE_REMESHING_BUILD_BENCHMARKS=ON
cmake --build build -j "$(nproc)"
ctest --test-dir build --output-on-failure -j 2
