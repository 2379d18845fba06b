#!/usr/bin/env bash
# Renders the manual's figures from real runs of the command-line program and the
# examples (f3d, headless under xvfb-run): doc/Range_space_remeshing/fig/*.png.
# The meshes behind them stay in build/figures/.
# Usage: scripts/figures.sh [getting-started]   (the argument: only the figures of the
# manual's Getting started page, which need the program alone)
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install_dependencies.sh f3d xvfb xauth
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2" \
      -DBUILD_TESTING=ON -DRANGE_SPACE_REMESHING_BUILD_EXAMPLES=ON > /dev/null
targets=(range_space_remesh color_map_example sizing_field_example)
[ "${1:-}" = getting-started ] && targets=(range_space_remesh)
cmake --build build -j 2 --target "${targets[@]}" > /dev/null

work=build/figures
figures=doc/Range_space_remeshing/fig
mkdir -p "$work" "$figures"
meshes="$work/meshes"
mkdir -p "$meshes"
for mesh in elephant fandisk elephant-with-holes man; do
  [ -f "$meshes/$mesh.off" ] || tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -O "data/meshes/$mesh.off" > "$meshes/$mesh.off"
done
cli=build/bin/range_space_remesh

# render MESH PNG [f3d options...]: a 640 x 640 picture with edges, light background;
# the surface colour is $colour if set (f3d keeps the first --color it is given)
render() {
  local mesh="$1" png="$2"
  shift 2
  xvfb-run -a f3d --output="$figures/$png" --resolution=640,640 --edges --bg-color=1,1,1 \
    --color="${colour:-0.85,0.85,0.8}" --up=+Y "$@" "$mesh" > /dev/null 2>&1
  echo "$figures/$png"
}
# remesh NAME INPUT [options...]: the CLI's output in $work/NAME.off, its stats in NAME.json
remesh() {
  local name="$1" input="$2"
  shift 2
  "$cli" --stats "$@" "$input" "$work/$name.off" > "$work/$name.json"
}

elephant="$meshes/elephant.off"
# the Getting started page: the elephant at three cell sizes (fractions of the
# bounding-box diagonal; halving the cell about quadruples the vertices), then the
# identity against position + normal at two normal weights, all at about 3,000
# output vertices (--target-vertices searches the cell size)
for cell in 0.03 0.02 0.01; do
  remesh "start_cell_$cell" "$elephant" --cell-size "$cell"
  render "$work/start_cell_$cell.off" "start_cell_$cell.png"
done
remesh start_map_identity "$elephant" --target-vertices 3000
render "$work/start_map_identity.off" start_map_identity.png
for weight in 0.05 0.2; do
  remesh "start_map_normal_$weight" "$elephant" --target-vertices 3000 --map position-normal --normal-weight "$weight"
  render "$work/start_map_normal_$weight.off" "start_map_normal_$weight.png"
done
[ "${1:-}" = getting-started ] && exit 0

render "$elephant" input_elephant.png
# the paper's figure 2: primal, dual at two resolutions, Gauss map, R^6 from uniform
# to anisotropic
remesh primal_elephant "$elephant" --output primal --cell-size 0.02
render "$work/primal_elephant.off" primal_elephant.png
remesh dual_elephant_coarse "$elephant" --cell-size 0.018
render "$work/dual_elephant_coarse.off" dual_elephant_coarse.png
remesh dual_elephant_fine "$elephant" --cell-size 0.01
render "$work/dual_elephant_fine.off" dual_elephant_fine.png
remesh gauss_elephant "$elephant" --map gauss --cell-size 0.2 --absolute
render "$work/gauss_elephant.off" gauss_elephant.png
for weight in 0 0.02 0.05; do
  remesh "r6_elephant_$weight" "$elephant" --map position-normal --normal-weight "$weight" --cell-size 0.02
  render "$work/r6_elephant_$weight.off" "r6_elephant_$weight.png"
done
# the paper's figure 1: the stages of the pipeline on fandisk
fandisk="$meshes/fandisk.off"
remesh stage_primal "$fandisk" --output primal --cell-size 0.025
remesh stage_dual "$fandisk" --no-collapse --relax 0 --cell-size 0.025
remesh stage_collapse "$fandisk" --relax 0 --cell-size 0.025
remesh stage_relax "$fandisk" --cell-size 0.025
for stage in primal dual collapse relax; do
  render "$work/stage_$stage.off" "stage_$stage.png" --camera-azimuth-angle=30 --camera-elevation-angle=20
done
# R^9: the colour example's output (red/white boundary at mid-height), direct colours
(cd "$work" && ../bin/color_map_example "../../$elephant" > /dev/null)
render "$work/colored.ply" colour_elephant.png --scalars --comp=-2
# a surface with 106 holes
holes="$meshes/elephant-with-holes.off"
render "$holes" input_elephant_with_holes.png
remesh holes "$holes" --cell-size 0.01
render "$work/holes.off" dual_elephant_with_holes.png
# topology (the manual's section on it): the elephant at cells of 10 % of the
# diagonal, the input faces the check flags (red), the primal there with
# --allow-topology-change, and the primal by default (refined around the defects)
remesh topology_coarse "$elephant" --output primal --cell-size 0.1 --allow-topology-change --topology-report "$work/topology_flagged.off" 2> /dev/null
python3 scripts/colour_flagged_faces.py "$elephant" "$work/topology_flagged.off" "$work/topology_flagged.ply"
render "$work/topology_flagged.ply" topology_elephant_flagged.png --scalars --cells --comp=-2
render "$work/topology_coarse.off" topology_elephant_coarse.png
remesh topology_preserved "$elephant" --output primal --cell-size 0.1
render "$work/topology_preserved.off" topology_elephant_preserved.png
# the same section: CGAL's man at a quarter of its vertices, from behind, with
# --allow-topology-change (two small pieces come off at a hand: 3
# components, chi 8) and by default (refined around the defects: kept)
man="$meshes/man.off"
remesh man_changed "$man" --target-vertices 4373 --allow-topology-change 2> /dev/null
remesh man_kept "$man" --target-vertices 4373
for mesh in man man_changed man_kept; do
  input="$work/$mesh.off"
  [ "$mesh" = man ] && input="$man"
  render "$input" "topology_$mesh.png" --camera-position=0,2.2,0.1 --camera-focal-point=0,0,0 --camera-view-up=0,0,1
done
# the same, position + normal (the manual's section on normals): the normals as
# computed (pieces come off at the hands and feet) and averaged 8 times (the default)
remesh man_normals_raw "$man" --target-vertices 4373 --map position-normal --normal-smoothing 0 2> /dev/null
remesh man_normals_averaged "$man" --target-vertices 4373 --map position-normal
for mesh in man_normals_raw man_normals_averaged; do
  render "$work/$mesh.off" "$mesh.png" --camera-position=0,2.2,0.1 --camera-focal-point=0,0,0 --camera-view-up=0,0,1
done
# a sizing field (the manual's section on range maps): the example's elephant, four
# times finer in each direction around its highest point
(cd "$work" && ../bin/sizing_field_example "../../$elephant" > sizing_field_example.txt)
render "$work/sized.off" sized_elephant.png
# texture coordinates (the manual's section on vertex attributes): a bumpy disc with one
# UV per vertex (no seam) and a generated checkerboard, and the dual remesh at about a
# quarter of its vertices, written as OBJ with vt. f3d 1.3 textures an OBJ's vt with
# --geometry-only (its OBJ importer otherwise keeps the file's materials) and does
# not read the PLY s t the program writes.
python3 scripts/textured_disc.py "$work/textured_disc.obj" "$work/checker.png" 40
"$cli" --stats --map position-normal --target-vertices 1230 "$work/textured_disc.obj" "$work/textured_dual.obj" \
  > "$work/textured_dual.json"
for mesh in textured_disc textured_dual; do
  colour=1,1,1 render "$work/$mesh.obj" "$mesh.png" --geometry-only --texture-base-color="$work/checker.png" \
    --roughness=1 --camera-position=0,-2.8,2.9 --camera-focal-point=0,0,-0.05 --camera-view-up=0,0,1
done
