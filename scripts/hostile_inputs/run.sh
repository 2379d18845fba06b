#!/usr/bin/env bash
# Runs range_space_remesh on every corpus file and on the special cases below, twice
# per file (default options, output in the input's format; --stats, output in another
# format), each under a 120 s timeout and an 8 GB address-space cap, and records exit
# code, stderr, peak RSS and time; report.py then checks every output independently
# (check_mesh.py) and writes RESULTS.md.
#
#   run.sh /path/to/range_space_remesh [outdir]
#
# Environment: TIMEOUT (s, default 120), AS_LIMIT (bytes, default 8000000000),
# ONLY (a grep -E pattern on case ids, to run a subset), RESULTS (where to write the
# table, default <corpus>/RESULTS.md; RESULTS=- for outdir only).
set -u
if [ $# -lt 1 ] || [ ! -x "$1" ]; then
  echo "usage: $0 /path/to/range_space_remesh [outdir]" >&2
  exit 64
fi
BIN=$(readlink -f "$1")
CORPUS=$(cd "$(dirname "$0")" && pwd)
OUTDIR=${2:-$(mktemp -d /tmp/rsr_corpus.XXXXXX)}
mkdir -p "$OUTDIR"
OUTDIR=$(cd "$OUTDIR" && pwd)
TIMEOUT=${TIMEOUT:-120}
AS_LIMIT=${AS_LIMIT:-8000000000}
ONLY=${ONLY:-}
RESULTS=${RESULTS:-$CORPUS/RESULTS.md}

if [ ! -x /usr/bin/time ]; then
  apt-get install -y -q time >/dev/null 2>&1 || { echo "needs /usr/bin/time (apt-get install time)" >&2; exit 64; }
fi
# the corpus files are generated: make them if missing (the conversions read CGAL's meshes)
if [ ! -d "$CORPUS/cgal/data/meshes" ] && [ -f /usr/share/doc/libcgal-dev/data.tar.gz ]; then
  mkdir -p "$CORPUS/cgal" && tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$CORPUS/cgal" data/meshes
fi
[ -f "$CORPUS/hostile/EXPECT.tsv" ] || python3 "$CORPUS/make_hostile.py" >/dev/null || exit 64
[ -f "$CORPUS/converted/sphere_colorfn.off" ] || python3 "$CORPUS/make_converted.py" || exit 64

rm -rf "$OUTDIR/out" "$OUTDIR/log" "$OUTDIR/work"
mkdir -p "$OUTDIR/out" "$OUTDIR/log" "$OUTDIR/work"
# run a private copy: a rebuild of BIN during the run must not mix two binaries
cp "$BIN" "$OUTDIR/range_space_remesh" || exit 64
BIN_ORIG=$BIN
BIN="$OUTDIR/range_space_remesh"
export BIN_ORIG BIN_MD5=$(md5sum <"$BIN" | cut -d' ' -f1)
RAW="$OUTDIR/raw.tsv"
printf 'key\tid\tmode\texpect\tflags\tinput\toutput\trc\tstderr_lines\tstderr_first\trss_kb\tseconds\toutput_exists\tleftover_tmp\tinput_changed\tstats_json\n' >"$RAW"
ulimit -c 0

# run_case ID MODE EXPECT FLAGS INPUT OUTPUT ARGS...   (ARGS: the program's arguments)
run_case() {
  local id=$1 mode=$2 expect=$3 flags=$4 input=$5 output=$6
  shift 6
  if [ -n "$ONLY" ] && ! printf '%s' "$id" | grep -qE -- "$ONLY"; then return; fi
  local key
  key=$(printf '%s.%s' "$id" "$mode" | tr '/\n"\\ ' '_____' | cut -c1-180)
  local log="$OUTDIR/log/$key"
  local outdir_of_output
  outdir_of_output=$(dirname -- "$output")
  [ "$output" != "$input" ] && rm -f -- "$output" 2>/dev/null
  printf '%s' "$input" >"$log.inpath"
  printf '%s' "$output" >"$log.outpath"
  local before=""
  [ -f "$input" ] && before=$(md5sum <"$input" | cut -d' ' -f1)
  /usr/bin/time -f '%M %e' -o "$log.time" \
    timeout -k 5 "$TIMEOUT" prlimit --as="$AS_LIMIT" "$BIN" "$@" >"$log.stdout" 2>"$log.stderr"
  local rc=$?
  local rss secs
  read -r rss secs < <(tail -n 1 "$log.time")
  local nlines first exists leftover changed json
  nlines=$(wc -l <"$log.stderr")
  first=$(head -n 1 "$log.stderr" | tr '\t\r' '  ' | cut -c1-300)
  exists=no
  [ -e "$output" ] && exists=yes
  leftover=$(find "$outdir_of_output" -maxdepth 1 -name '.*.tmp*' 2>/dev/null | head -n 1)
  [ -n "$leftover" ] && { leftover=yes; find "$outdir_of_output" -maxdepth 1 -name '.*.tmp*' -delete 2>/dev/null; } || leftover=no
  changed=no
  if [ -n "$before" ] && [ -f "$input" ] && [ "$(md5sum <"$input" | cut -d' ' -f1)" != "$before" ]; then changed=yes; fi
  json=-
  if [ "$mode" = stats ] && [ $rc -eq 0 ]; then
    if python3 -m json.tool <"$log.stdout" >/dev/null 2>&1; then json=valid; else json=invalid; fi
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' \
    "$key" "$(printf '%s' "$id" | tr '\t\n' '  ')" "$mode" "$expect" "$flags" "$(printf '%s' "$input" | tr '\t\n' '  ')" \
    "$(printf '%s' "$output" | tr '\t\n' '  ')" "$rc" "$nlines" "$first" "${rss:-0}" "${secs:-0}" \
    "$exists" "$leftover" "$changed" "$json" >>"$RAW"
  printf '%-60s %-7s rc=%-3s %6s KB %6ss %s\n' "$(printf '%s' "$id" | tr '\n' ' ' | cut -c1-60)" "$mode" "$rc" "${rss:-?}" "${secs:-?}" "$first"
}

ext_of() { local e=${1##*.}; printf '%s' "$e" | tr 'A-Z' 'a-z'; }
# the output format of the --stats run: another writer than the default run's
other_ext() { case $1 in off) echo ply ;; obj) echo off ;; ply) echo obj ;; stl) echo off ;; *) echo off ;; esac; }

# expectation of a hostile file from hostile/EXPECT.tsv; real/cgal/converted files are
# judged by report.py from the input itself (usable mesh or not)
declare -A EXPECT FLAGS
while IFS=$'\t' read -r name expect flags note; do
  case $name in '#'*|'') continue ;; esac
  EXPECT[$name]=$expect
  FLAGS[$name]=$flags
done <"$CORPUS/hostile/EXPECT.tsv"

for dir in real cgal/data/meshes converted hostile; do
  for f in "$CORPUS/$dir"/*; do
    [ -f "$f" ] || continue
    name=$(basename "$f")
    [ "$name" = EXPECT.tsv ] && continue
    id="$dir/$name"
    expect=auto; flags=-
    if [ "$dir" = hostile ]; then expect=${EXPECT[$name]:-any}; flags=${FLAGS[$name]:--}; fi
    e=$(ext_of "$name")
    case $e in off|obj|ply|stl) ;; *) e=off ;; esac
    base=$(printf '%s' "$id" | tr '/' '_')
    out1="$OUTDIR/out/$base.default.$e"
    run_case "$id" default "$expect" "$flags" "$f" "$out1" "$f" "$out1"
    e2=$(other_ext "$e")
    out2="$OUTDIR/out/$base.stats.$e2"
    run_case "$id" stats "$expect" "$flags" "$f" "$out2" --stats "$f" "$out2"
  done
done

# ---------------------------------------------------------------- special cases
W="$OUTDIR/work"
OCTA="$CORPUS/hostile/off_octahedron.off"
ELE="$CORPUS/cgal/data/meshes/elephant.off"
MAN="$CORPUS/cgal/data/meshes/man.off"

run_case special/missing_input default refuse - "$W/missing.off" "$W/o_missing.off" "$W/does/not/exist.off" "$W/o_missing.off"
mkdir -p "$W/a_directory.off"
run_case special/directory_as_input default refuse - "$W/a_directory.off" "$W/o_dir.off" "$W/a_directory.off" "$W/o_dir.off"
run_case special/output_in_missing_directory default refuse - "$OCTA" "$W/no/such/dir/o.off" "$OCTA" "$W/no/such/dir/o.off"
mkdir -p "$W/existing_dir.off"
run_case special/output_is_a_directory default refuse - "$OCTA" "$W/existing_dir.off/.sentinel" "$OCTA" "$W/existing_dir.off"
run_case special/output_unsupported_extension default refuse - "$OCTA" "$W/o.xyz" "$OCTA" "$W/o.xyz"
run_case special/output_no_extension default refuse - "$OCTA" "$W/o_noext" "$OCTA" "$W/o_noext"
cp "$OCTA" "$W/same.off"
run_case special/output_equals_input default any same "$W/same.off" "$W/same.off" "$W/same.off" "$W/same.off"
cp "$CORPUS/converted/elephant_negative_indices.obj" "$W/same_ele.obj"
run_case special/output_equals_input_obj stats any same "$W/same_ele.obj" "$W/same_ele.obj" --stats "$W/same_ele.obj" "$W/same_ele.obj"
long=$(printf 'a%.0s' $(seq 1 246)).off   # 250 bytes: a legal file name
run_case special/output_name_250_bytes default accept closed "$OCTA" "$W/$long" "$OCTA" "$W/$long"
long2=$(printf 'b%.0s' $(seq 1 251)).off  # 255 bytes: the longest legal name
run_case special/output_name_255_bytes default accept closed "$OCTA" "$W/$long2" "$OCTA" "$W/$long2"
weird="$W/we\"ird\\na"$'\n'"me.off"
run_case special/output_name_quote_backslash_newline stats accept closed "$OCTA" "$weird" --stats "$OCTA" "$weird"
weird_in="$W/in\"put\\"$'\n'"x.off"
cp "$OCTA" "$weird_in"
run_case special/input_name_quote_backslash_newline stats accept closed "$weird_in" "$W/o_weird_in.ply" --stats "$weird_in" "$W/o_weird_in.ply"
dash="$W/-starts-with-dash.off"; cp "$OCTA" "$dash"
run_case special/input_name_starting_with_dash default any closed "$dash" "$W/o_dash.off" -- "$dash" "$W/o_dash.off"
utf="$W/ünïcödé ✓ name.off"; cp "$OCTA" "$utf"
run_case special/utf8_and_space_names stats accept closed "$utf" "$W/ø ütf.ply" --stats "$utf" "$W/ø ütf.ply"
ln -sf /dev/zero "$W/devzero.off"; ln -sf /dev/zero "$W/devzero.ply"; ln -sf /dev/zero "$W/devzero.obj"; ln -sf /dev/zero "$W/devzero.stl"
for e in off ply obj stl; do
  run_case "special/input_is_dev_zero.$e" default refuse - "$W/devzero.$e" "$W/o_devzero.$e" "$W/devzero.$e" "$W/o_devzero.$e"
done
ln -sf /dev/urandom "$W/urandom.ply"
run_case special/input_is_dev_urandom.ply default refuse - "$W/urandom.ply" "$W/o_urandom.ply" "$W/urandom.ply" "$W/o_urandom.ply"
mkfifo "$W/fifo.off" 2>/dev/null; ( cat "$OCTA" >"$W/fifo.off" & ) 2>/dev/null
run_case special/input_is_fifo default any closed "$W/fifo.off" "$W/o_fifo.off" "$W/fifo.off" "$W/o_fifo.off"
timeout 2 cat "$W/fifo.off" >/dev/null 2>&1; rm -f "$W/fifo.off"   # unblock a writer left waiting
# option bombs: cell sizes far too small or too large must be refused quickly, not run out of memory
run_case special/cell_size_1e-5 default refuse - "$ELE" "$W/o_cs5.off" --cell-size 1e-5 "$ELE" "$W/o_cs5.off"
run_case special/cell_size_1e-300 default refuse - "$ELE" "$W/o_cs300.off" --cell-size 1e-300 "$ELE" "$W/o_cs300.off"
run_case special/cell_size_1e300 default any - "$ELE" "$W/o_csbig.off" --cell-size 1e300 "$ELE" "$W/o_csbig.off"
run_case special/absolute_cell_size_1e-12 default refuse - "$ELE" "$W/o_abs.off" --absolute --cell-size 1e-12 "$ELE" "$W/o_abs.off"
run_case special/cell_size_1e-4_primal default any - "$ELE" "$W/o_cs4.off" --output primal --cell-size 1e-4 "$ELE" "$W/o_cs4.off"
run_case special/target_vertices_1e9 default any - "$ELE" "$W/o_tv.off" --target-vertices 1000000000 "$ELE" "$W/o_tv.off"
run_case special/target_vertices_4 default any - "$ELE" "$W/o_tv4.off" --target-vertices 4 "$ELE" "$W/o_tv4.off"
run_case special/preserve_topology_man default any - "$MAN" "$W/o_pt.off" --preserve-topology "$MAN" "$W/o_pt.off"
run_case special/topology_report_unwritable default any - "$MAN" "$W/o_tr.off" --topology-report "$W/no/such/dir/r.off" "$MAN" "$W/o_tr.off"
run_case special/topology_report_same_as_output default any - "$MAN" "$W/o_trs.off" --topology-report "$W/o_trs.off" "$MAN" "$W/o_trs.off"
run_case special/color_map_without_colors default refuse - "$OCTA" "$W/o_cm.ply" --map position-normal-color "$OCTA" "$W/o_cm.ply"
run_case special/view_map_without_camera default refuse - "$OCTA" "$W/o_vm.off" --map view "$OCTA" "$W/o_vm.off"
printf 'eye 0 0 0\ntarget 0 0 0\nviewport 640 480\n' >"$W/cam_degenerate.txt"
run_case special/view_map_degenerate_camera default refuse - "$OCTA" "$W/o_vc.off" --map view --camera "$W/cam_degenerate.txt" "$OCTA" "$W/o_vc.off"
run_case special/camera_is_dev_zero default refuse - "$OCTA" "$W/o_vz.off" --map view --camera /dev/zero "$OCTA" "$W/o_vz.off"
run_case special/gauss_map_default_elephant default any - "$ELE" "$W/o_gm.off" --map gauss "$ELE" "$W/o_gm.off"
run_case special/gauss_map_default_sphere default any closed "$CORPUS/cgal/data/meshes/sphere.off" "$W/o_gms.off" --map gauss "$CORPUS/cgal/data/meshes/sphere.off" "$W/o_gms.off"
run_case special/position_normal_default_bunny default any closed "$CORPUS/cgal/data/meshes/bunny00.off" "$W/o_pn.off" --map position-normal "$CORPUS/cgal/data/meshes/bunny00.off" "$W/o_pn.off"
run_case special/position_normal_gradient_colors default any closed "$CORPUS/converted/elephant_colorfn.off" "$W/o_pncg.ply" --map position-normal-color-gradient "$CORPUS/converted/elephant_colorfn.off" "$W/o_pncg.ply"
run_case special/relax_1000 default any closed "$ELE" "$W/o_rx.off" --relax 1000 "$ELE" "$W/o_rx.off"
run_case special/sharp_angle_0_position_normal default any - "$ELE" "$W/o_sa.off" --map position-normal --sharp-angle 0 "$ELE" "$W/o_sa.off"
run_case special/colors_through_sharp_angle default accept closed,colorfn "$CORPUS/converted/sphere_colorfn.off" "$W/o_csa.ply" --sharp-angle 30 --map position-normal-color "$CORPUS/converted/sphere_colorfn.off" "$W/o_csa.ply"
run_case special/colors_primal_output default accept closed,colorfn "$CORPUS/hostile/ply_unreferenced_vertices_colors.ply" "$W/o_cpo.ply" --output primal "$CORPUS/hostile/ply_unreferenced_vertices_colors.ply" "$W/o_cpo.ply"
run_case special/no_arguments default refuse - - - 
run_case special/three_positionals default refuse - "$OCTA" "$W/o_3.off" "$OCTA" "$W/o_3.off" "$W/o_3b.off"
run_case special/empty_string_args default refuse - "" "$W/o_e.off" "" ""

python3 "$CORPUS/report.py" "$OUTDIR" "$RESULTS" "$BIN_ORIG (md5 $BIN_MD5)"
