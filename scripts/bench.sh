#!/usr/bin/env bash
# Builds the benchmark programs (Release, assertions off) into build-bench/ and runs
#  * table1: the whole pipeline at n = 3, 6, 9 on CGAL's sample meshes, against
#    CGAL's isotropic remeshing and Garland–Heckbert simplification at the same
#    vertex count, the scaling with the input size and a deforming mesh;
#  * contour_benchmark: the stages of the primal contouring and the cost of D.
# The Markdown goes to stdout and to benchmark/RESULTS.md (written when complete).
# Usage: scripts/bench.sh [--quick]   (--quick: two meshes, fewer runs, for a check)
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
if [ "${1:-}" = "--quick" ]; then quick=1; fi

bash scripts/install_dependencies.sh libeigen3-dev
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
      -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=OFF -DRANGE_SPACE_REMESHING_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build-bench -j "$(nproc)" --target rsr_benchmarks

data=build-bench/data
mkdir -p "$data"
meshes=(refined_elephant bunny00 armadillo fandisk_large man)
for mesh in "${meshes[@]}"; do
  if [ ! -f "$data/$mesh.off" ]; then
    tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -O "data/meshes/$mesh.off" > "$data/$mesh.off.part"
    mv "$data/$mesh.off.part" "$data/$mesh.off"
  fi
done
paths=()
for mesh in "${meshes[@]}"; do paths+=("$data/$mesh.off"); done
runs=(--runs 11 --peer-runs 5)
if [ "$quick" = 1 ]; then paths=("${paths[@]:0:2}"); runs=(--runs 5 --peer-runs 1); fi

output=benchmark/RESULTS.md
if [ "$quick" = 1 ]; then output=build-bench/RESULTS-quick.md; fi
{
  echo "# Benchmark results"
  echo
  echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), one thread."
  echo "Command: \`scripts/bench.sh\` ($(date -u +%Y-%m-%d), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown))."
  echo
  build-bench/bin/table1 "${runs[@]}" --scaling "$data/refined_elephant.off" --deforming "$data/bunny00.off" \
    "${paths[@]}"
  echo
  echo "## Stages of the primal contouring, cost of the dimension"
  echo
  build-bench/bin/contour_benchmark "${runs[@]:0:2}" "${paths[@]:0:2}"
  echo
  echo "## Progress visitor: the longest wait between two calls"
  echo
  build-bench/bin/progress_gaps "${paths[@]}"
} | tee "$output.part"
# the hand-kept part below the tables (measurements the manual quotes, made by other
# programs and tests) is kept as it is
if [ "$quick" = 0 ] && grep -q '^## Measurements from the manual' "$output"; then
  { echo; sed -n '/^## Measurements from the manual/,$p' "$output"; } >> "$output.part"
fi
mv "$output.part" "$output"
