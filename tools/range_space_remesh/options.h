// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: the command line. The usage text (--help), the options it
// parses into, and the parser of numbers, which accepts only plain decimals.
// test_command_line.cmake reads this file: every option named here in quotes must be in
// the usage text.

#ifndef RANGE_SPACE_REMESHING_TOOLS_OPTIONS_H
#define RANGE_SPACE_REMESHING_TOOLS_OPTIONS_H

#include "failure.h"
#include "map_registry.h"
#include "mesh_types.h"

#include <CGAL/Range_space_remeshing/View_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace rsr_program {

class Progress_line;

inline const char* const usage =
    "usage: range_space_remesh [options] INPUT OUTPUT\n"
    "\n"
    "Remeshes the triangle mesh INPUT (closed or with border) by intersecting its\n"
    "image under a map f with a uniform grid of cell size H in the range space, and\n"
    "writes OUTPUT (which may not be INPUT).\n"
    "Formats (by extension): .off .obj .ply .stl. Polygonal input is triangulated.\n"
    "Input that is not an oriented 2-manifold (STL soups, non-manifold vertices or\n"
    "edges, inconsistent orientation, duplicate or degenerate faces) is repaired\n"
    "first with CGAL's polygon soup repair; one line on stderr says what changed.\n"
    "\n"
    "options:\n"
    "  --map NAME            the map f:\n"
    "                          identity (the default): the position, D = 3: a\n"
    "                          uniform remesh\n"
    "                          position-normal: position and unit normal (times W),\n"
    "                          D = 6: faces small where the surface bends, each\n"
    "                          face's normals vary by at most H / W\n"
    "                          gauss: the normal pushed onto the unit cube, D = 3:\n"
    "                          faces bounded in normal variation only (anisotropic)\n"
    "                          position-normal-color: position, normal and vertex\n"
    "                          colour (r, g, b in [0, 1], times C), D = 9: each\n"
    "                          face's colours vary by at most H / C per channel\n"
    "                          position-normal-color-gradient: the paper's R^9, with\n"
    "                          the colour gradients' magnitudes (per diagonal)\n"
    "                        Vertex colours of PLY and COFF inputs go to the output\n"
    "                        (written to PLY and OFF outputs) whatever the map.\n"
    "                        Texture coordinates of PLY (s t, u v, texture_u\n"
    "                        texture_v) and OBJ (vt) inputs go to PLY (s t) and OBJ\n"
    "                        (vt) outputs. Where a file gives one position several\n"
    "                        colours or UVs (a sharp colour change, a texture seam),\n"
    "                        a closed surface is opened there as a crease and each\n"
    "                        side keeps its own; on a surface with a border the\n"
    "                        colours are blended and the UVs dropped (said).\n"
    "                          view: pixel coordinates for the camera of --camera,\n"
    "                          and depth: faces bounded on the screen; H is a\n"
    "                          fraction of the viewport's diagonal (pixels with\n"
    "                          --absolute)\n"
    "  --camera FILE         the camera of --map view, a text file of lines\n"
    "                          eye X Y Z / target X Y Z / up X Y Z (default 0 1 0)\n"
    "                          fov DEGREES (vertical, default 60) / viewport W H\n"
    "                        ('#' starts a comment); depth counts as many pixels\n"
    "                        per unit as a lateral step at the target's distance\n"
    "  --normal-weight W     weight of the normal in the position-normal maps\n"
    "                        (default 0.1; 0: the identity's uniform remesh)\n"
    "  --normal-smoothing K  the maps with normals read each vertex's normal averaged\n"
    "                        K times with its neighbours' (default 8; 0: the\n"
    "                        normals of the faces around it only): the bound on the\n"
    "                        normal part holds for these normals. Averaging drops\n"
    "                        the steps of the normal between a scan's or a coarse\n"
    "                        mesh's facets, which no cell resolves and which change\n"
    "                        the topology. Needs every vertex's normal: 0 with\n"
    "                        --seeded unless given\n"
    "  --sharp-angle DEG     open the creases (dihedral angle above DEG) with\n"
    "                        zero-area triangles first, so that the normal maps put\n"
    "                        arcs along them (and, unless --placement is given,\n"
    "                        places dual vertices with 'sharp'); closed surfaces only\n"
    "  --color-weight C      weight of the colour in the colour maps (default 1 for\n"
    "                        position-normal-color, 0.01 for -gradient)\n"
    "  --cell-size H         cell size as a fraction of the input's bounding-box\n"
    "                        diagonal (default 0.01)\n"
    "  --absolute            H is in the map's own units, with the grid origin at 0\n"
    "  --target-vertices N   choose H so that the output has N vertices (within 10%)\n"
    "  --max-vertices N      refuse a cell size whose primal remesh would have more\n"
    "                          than N vertices (default: the library's 10 million, or\n"
    "                          fewer if the available memory (or a container's\n"
    "                          or ulimit's limit) would not hold the run:\n"
    "                          about 1.3 KB per vertex, 0.4 KB with --output primal)\n"
    "  --output KIND         dual (the default): all quads, one vertex per grid-cell\n"
    "                        piece of the surface; primal: the pieces themselves as\n"
    "                        polygons, every vertex of valence 4\n"
    "  --placement NAME      where dual vertices go: qem (the default: closest to the\n"
    "                        tangent planes of the piece's vertices), sharp (the\n"
    "                        same, keeping corners and creases the planes pin) or\n"
    "                        average\n"
    "  --collapse            collapse dual quads and rotate edges where that makes\n"
    "                        valences more regular (the default)\n"
    "  --no-collapse         keep the dual as it is\n"
    "  --relax K             K relaxation iterations of the dual (default 3, 0: none)\n"
    "  --seeded              seeded traversal from one face per component: maps only\n"
    "                        the triangles the arcs cross (sublinear), may miss pieces\n"
    "  --preserve-topology   make sure the output has the input's topology (closed\n"
    "                          loops, non-disk cells, lost pieces: see the manual)\n"
    "                          and, for the dual, no parallel edges (nor faces joined\n"
    "                          to undo them): where refining the cells around the\n"
    "                          defects (the default) does not, reduce the cell size;\n"
    "                          the cell size used is in --stats\n"
    "  --allow-topology-change  do not refine the cells around topology defects\n"
    "                          (they are refined by default, up to twice the\n"
    "                          output's vertices); the check still warns\n"
    "  --no-topology-check   skip the topology check (on by default but with\n"
    "                          --seeded, which cannot check it), and so the\n"
    "                          refinement around defects; a warning is printed\n"
    "                          on stderr when the check finds a defect\n"
    "  --topology-report FILE  write the input faces where the topology check found\n"
    "                          defects to FILE, a mesh (.off .obj .ply .stl); not with\n"
    "                          --seeded or --no-topology-check\n"
    "  --time-limit S        stop (exit 2, nothing written) if the remesh takes more\n"
    "                          than S seconds (default: none, but 60 for the whole\n"
    "                          run with --preserve-topology)\n"
    "  --quiet               no progress line (shown on a terminal for runs over 1 s)\n"
    "  --stats               print one JSON object with counts and times on stdout\n"
    "  --strict              refuse an input that needs repairs instead of repairing it;\n"
    "                          points at one position are kept apart, not merged\n"
    "  --ascii               write PLY and STL as text (default: binary)\n"
    "  --help                print this help and exit (the only argument)\n"
    "  --version             print the program's and CGAL's versions and exit (the\n"
    "                          only argument)\n"
    "  --                    ends the options: INPUT and OUTPUT may start with '-'\n"
    "Numbers are decimal: an optional sign, digits with an optional fraction, an\n"
    "optional exponent (0.01, +5, 1e-3); no spaces, hexadecimal, inf or nan.\n"
    "\n"
    "exit status: 0 on success, 2 on bad arguments, unusable input or the time limit,\n"
    "130 when interrupted (Ctrl-C); no file is written unless the status is 0.\n";

struct Options
{
  /// What the command line asks for: a remesh, or only the usage text or the version.
  enum class Request { REMESH, HELP, VERSION };
  Request request = Request::REMESH;
  std::string input, output, output_kind = "dual", placement; // placement: "" until chosen
  const Range_map* map = &default_range_map();
  double cell_size = 0.01;
  double normal_weight = 0.1;
  int normal_smoothing = -1; // negative: the default (0 with --seeded)
  double color_weight = -1; // negative: the map's default
  double sharp_angle = -1;   // negative: no crease preprocessing
  double length_unit = 1; // the bounding-box diagonal in relative mode
  std::string camera_file;
  RSR::Camera camera;
  double depth_weight = 0; // view map: pixels per unit of depth, from the camera file
  int relax = 3;
  bool absolute = false, seeded = false, stats = false, collapse = true;
  bool strict = false, binary = true;
  bool check_topology = true, preserve_topology = false;
  bool allow_topology_change = false; // no magnification around the defects
  std::string topology_report; // file of the flagged input faces
  std::vector<RSR::Topology_defect<Mesh::Face_index>>* defects = nullptr; // filled by the check
  long target_vertices = 0;
  std::size_t max_vertices = 0; // --max-vertices; main() sets the default (vertex_cap()) once
  double time_limit = 0;        // seconds; 0: none
  bool default_time_limit = false; // time_limit is --preserve-topology's default
  bool quiet = false;
  class Progress_line* progress = nullptr; // set by main()
};

/// --normal-smoothing's default: rounds of averaging each normal with its neighbours'.
constexpr int default_normal_smoothing = 8;

/// --time-limit's default with --preserve-topology, in seconds.
constexpr double preserve_topology_time_limit = 60;

/// Whether `text` is a decimal number: an optional sign, digits with an optional
/// fraction (or a fraction alone), an optional exponent; nothing else (no spaces, no
/// hexadecimal, no inf or nan).
inline bool is_decimal_number(const char* text)
{
  const auto digits = [&text] {
    const char* start = text;
    while(*text >= '0' && *text <= '9')
      ++text;
    return text != start;
  };
  if(*text == '+' || *text == '-')
    ++text;
  bool mantissa = digits();
  if(*text == '.') {
    ++text;
    mantissa = digits() || mantissa;
  }
  if(!mantissa)
    return false;
  if(*text == 'e' || *text == 'E') {
    ++text;
    if(*text == '+' || *text == '-')
      ++text;
    if(!digits())
      return false;
  }
  return *text == '\0';
}

/// The value of an option's number (see is_decimal_number()), which must be finite.
inline double parse_number(const std::string& option, const char* text)
{
  if(!is_decimal_number(text))
    fail(option + " expects a decimal number (such as 0.01, 5 or 1e-3), got " + quote(text));
  const double value = std::strtod(text, nullptr); // the "C" locale: the program sets none
  if(!std::isfinite(value))
    fail(option + " expects a finite number, got " + quote(text));
  return value;
}

/// Refuses options that would be silently ignored: a setting of a map other than the
/// chosen one, and a cell size beside --target-vertices, which chooses it.
inline void refuse_ignored_options(const Options& options, const std::set<std::string>& given)
{
  const std::string map = quote(options.map->name);
  if(given.count("--camera") && !options.map->uses_camera)
    fail("--camera is for --map view; the map " + map + " has no camera");
  if(given.count("--normal-weight") && !options.map->uses_normal_weight)
    fail("--normal-weight is for the maps with normals (position-normal...); the map " + map + " has none");
  if(given.count("--normal-smoothing") && !options.map->uses_normals)
    fail("--normal-smoothing is for the maps with normals (position-normal...); the map " + map + " has none");
  if(given.count("--color-weight") && !options.map->uses_colors)
    fail("--color-weight is for the maps with colours (position-normal-color...); the map " + map + " has none");
  if(given.count("--preserve-topology") && given.count("--allow-topology-change"))
    fail("--preserve-topology and --allow-topology-change exclude each other");
  if(given.count("--cell-size") && given.count("--target-vertices"))
    fail("--cell-size and --target-vertices exclude each other: --target-vertices chooses the cell size");
  if(!options.topology_report.empty() && (options.seeded || !options.check_topology))
    fail(std::string("--topology-report needs the topology check, which ") +
         (options.seeded ? "--seeded cannot run" : "--no-topology-check skips"));
}

inline Options parse_arguments(int argc, char** argv)
{
  Options options;
  std::vector<std::string> positional;
  std::set<std::string> given; // the options met, for refuse_ignored_options()
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    given.insert(arg);
    auto value = [&]() -> const char* {
      if(a + 1 >= argc)
        fail(arg + " expects a value");
      return argv[++a];
    };
    if((arg == "--help" || arg == "-h" || arg == "--version") && argc > 2)
      fail(arg + " takes no other argument (got " + quote(a > 1 ? argv[1] : argv[2]) + ")");
    if(arg == "--help" || arg == "-h" || arg == "--version") { // the only argument: main() answers it
      options.request = arg == "--version" ? Options::Request::VERSION : Options::Request::HELP;
      return options;
    } else if(arg == "--map") {
      const std::string name = value();
      options.map = find_range_map(name);
      if(!options.map)
        fail("unknown map " + quote(name) + " (available: " + range_map_names() + ")");
    } else if(arg == "--sharp-angle") {
      options.sharp_angle = parse_number(arg, value());
      if(!(options.sharp_angle >= 0 && options.sharp_angle <= 180))
        fail("--sharp-angle expects an angle between 0 and 180 degrees");
    } else if(arg == "--camera") {
      options.camera_file = value();
    } else if(arg == "--color-weight") {
      options.color_weight = parse_number(arg, value());
      if(!(options.color_weight >= 0) || options.color_weight > 1e6)
        fail("--color-weight must be between 0 and 10^6");
    } else if(arg == "--normal-weight") {
      options.normal_weight = parse_number(arg, value());
      if(!(options.normal_weight >= 0) || options.normal_weight > 1e6)
        fail("--normal-weight must be between 0 and 10^6");
    } else if(arg == "--normal-smoothing") {
      const double k = parse_number(arg, value());
      if(!(k >= 0) || k != std::floor(k) || k > 1000)
        fail("--normal-smoothing expects an integer between 0 and 1000");
      options.normal_smoothing = int(k);
    } else if(arg == "--cell-size") {
      options.cell_size = parse_number(arg, value());
      if(!(options.cell_size > 0))
        fail("--cell-size must be positive");
    } else if(arg == "--absolute") {
      options.absolute = true;
    } else if(arg == "--target-vertices") {
      const double n = parse_number(arg, value());
      if(!(n >= 4) || n != std::floor(n) || n > 1e9)
        fail("--target-vertices expects an integer between 4 and 10^9");
      options.target_vertices = long(n);
    } else if(arg == "--max-vertices") {
      const double n = parse_number(arg, value());
      if(!(n >= 1) || n != std::floor(n) || n > 1e10)
        fail("--max-vertices expects an integer between 1 and 10^10");
      options.max_vertices = std::size_t(n);
    } else if(arg == "--output") {
      options.output_kind = value();
      if(options.output_kind != "primal" && options.output_kind != "dual")
        fail("unknown output " + quote(options.output_kind) + " (available: dual, primal)");
    } else if(arg == "--placement") {
      options.placement = value();
      if(options.placement != "qem" && options.placement != "sharp" && options.placement != "average")
        fail("unknown placement " + quote(options.placement) + " (available: qem, sharp, average)");
    } else if(arg == "--relax") {
      const double k = parse_number(arg, value());
      if(!(k >= 0) || k != std::floor(k) || k > 1000)
        fail("--relax expects an integer between 0 and 1000");
      options.relax = int(k);
    } else if(arg == "--collapse" || arg == "--no-collapse") {
      options.collapse = arg == "--collapse";
    } else if(arg == "--seeded") {
      options.seeded = true;
    } else if(arg == "--preserve-topology") {
      options.preserve_topology = true;
    } else if(arg == "--allow-topology-change") {
      options.allow_topology_change = true;
    } else if(arg == "--no-topology-check") {
      options.check_topology = false;
    } else if(arg == "--topology-report") {
      options.topology_report = value();
    } else if(arg == "--time-limit") {
      options.time_limit = parse_number(arg, value());
      if(!(options.time_limit > 0) || options.time_limit > 1e9)
        fail("--time-limit expects a number of seconds above 0 and at most 10^9");
    } else if(arg == "--quiet") {
      options.quiet = true;
    } else if(arg == "--stats") {
      options.stats = true;
    } else if(arg == "--strict") {
      options.strict = true;
    } else if(arg == "--ascii") {
      options.binary = false;
    } else if(arg == "--") { // what follows are file names, even if they start with '-'
      positional.insert(positional.end(), argv + a + 1, argv + argc);
      break;
    } else if(!arg.empty() && arg[0] == '-' && arg != "-") {
      fail("unknown option " + quote(arg) + " (see --help)");
    } else {
      positional.push_back(arg);
    }
  }
  if(positional.size() != 2)
    fail("expected INPUT and OUTPUT (see --help)");
  refuse_ignored_options(options, given);
  options.input = positional[0];
  options.output = positional[1];
  if(options.placement.empty())
    options.placement = options.sharp_angle >= 0 ? "sharp" : "qem";
  // the seeded traversal reads only the normals of the vertices it reaches
  if(options.normal_smoothing < 0)
    options.normal_smoothing = options.seeded ? 0 : default_normal_smoothing;
  // each refinement of --preserve-topology can take longer than all before it
  if(options.preserve_topology && !given.count("--time-limit")) {
    options.time_limit = preserve_topology_time_limit;
    options.default_time_limit = true;
  }
  return options;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_OPTIONS_H
