#!/usr/bin/env bash
# Builds the benchmark programs (Release, assertions off) into build-bench/ and runs
# the contouring benchmark on CGAL's refined_elephant and bunny00; the Markdown
# table goes to stdout and to benchmark/RESULTS.md.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
cmake -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
      -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=OFF -DRANGE_SPACE_REMESHING_BUILD_BENCHMARKS=ON >/dev/null
cmake --build build-bench -j "$(nproc)" --target contour_benchmark

data=build-bench/data
mkdir -p "$data"
for mesh in refined_elephant bunny00; do
  if [ ! -f "$data/$mesh.off" ]; then
    tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -O "data/meshes/$mesh.off" > "$data/$mesh.off.part"
    mv "$data/$mesh.off.part" "$data/$mesh.off"
  fi
done

{
  echo "# Benchmark results"
  echo
  echo "Primal contouring, identity map, one thread, output about 25 % of the input's vertices."
  echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'). Command: \`scripts/bench.sh\`."
  echo
  build-bench/bin/contour_benchmark --runs 21 "$data/refined_elephant.off" "$data/bunny00.off"
} | tee benchmark/RESULTS.md.part
mv benchmark/RESULTS.md.part benchmark/RESULTS.md
