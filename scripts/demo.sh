#!/usr/bin/env bash
# Builds the command-line program and remeshes CGAL's elephant (from the Debian
# package libcgal-demo) with the default map; writes build/demo/elephant_quads.off
# and prints the statistics.
# Usage: scripts/demo.sh [extra options for range_space_remesh]
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
      -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=ON >/dev/null
cmake --build build -j "$(nproc)" --target range_space_remesh

mkdir -p build/demo
input=build/demo/elephant.off
if [ ! -f "$input" ]; then
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -O data/meshes/elephant.off > "$input.part"
  mv "$input.part" "$input"
fi
build/bin/range_space_remesh --stats --cell-size 0.01 "$@" "$input" build/demo/elephant_quads.off
echo "wrote build/demo/elephant_quads.off"
