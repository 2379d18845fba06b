// range_space_remesh: command-line front end of the Range_space_remeshing package.
//
//   range_space_remesh [options] INPUT OUTPUT
//
// Reads a mesh (OFF, OBJ, PLY, STL), remeshes it by intersecting its image under
// the range map with a uniform grid, and writes the result (same formats).
// Exit status: 0 on success, 2 on bad arguments or unusable input (one line on
// stderr). The output file is written atomically: it never exists half-written,
// and is not created on failure.

#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/View_range_map.h>
#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/Range_space_remeshing/prepare_input.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Range_space_remeshing/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/version.h>

#include "mesh_file_reader.h"
#include "mesh_file_writer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <system_error>
#include <unordered_map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <filesystem>

#include <unistd.h>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Color_map = Mesh::Property_map<Mesh::Vertex_index, CGAL::IO::Color>;
namespace RSR = CGAL::Range_space_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;

const char* usage =
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
    "  --sharp-angle DEG     open the creases (dihedral angle above DEG) with\n"
    "                        zero-area triangles first, so that the normal maps put\n"
    "                        arcs along them (and, unless --placement is given,\n"
    "                        places dual vertices with 'sharp')\n"
    "  --color-weight C      weight of the colour in the colour maps (default 1 for\n"
    "                        position-normal-color, 0.01 for -gradient)\n"
    "  --cell-size H         cell size as a fraction of the input's bounding-box\n"
    "                        diagonal (default 0.01)\n"
    "  --absolute            H is in the map's own units, with the grid origin at 0\n"
    "  --target-vertices N   choose H so that the output has N vertices (within 10%)\n"
    "  --max-vertices N      refuse a cell size whose primal remesh would have more\n"
    "                          than N vertices (default: the library's 10 million, or\n"
    "                          fewer if the available memory (or a container's\n"
    "                          limit) would not hold the run:\n"
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
    "  --preserve-topology   reduce the cell size until the output has the input's\n"
    "                          topology (closed loops, non-disk cells, lost pieces:\n"
    "                          see the manual) and, for the dual, no parallel edges\n"
    "                          (nor faces joined to undo them);\n"
    "                          the cell size used is in --stats\n"
    "  --no-topology-check   skip the topology check (on by default but with\n"
    "                          --seeded, which cannot check it); a warning is printed\n"
    "                          on stderr when the check finds a defect\n"
    "  --topology-report FILE  write the input faces where the topology check found\n"
    "                          defects to FILE, a mesh (.off .obj .ply .stl)\n"
    "  --time-limit S        stop (exit 2, nothing written) if the remesh takes more\n"
    "                          than S seconds\n"
    "  --quiet               no progress line (shown on a terminal for runs over 1 s)\n"
    "  --stats               print one JSON object with counts and times on stdout\n"
    "  --strict              refuse an input that needs repairs instead of repairing it\n"
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

struct Failure
{
  std::string message;
};

[[noreturn]] void fail(const std::string& message) { throw Failure{message}; }

/// CGAL's readers and writers explain failures on std::cerr; the program reports
/// them in its own single line instead, so silence std::cerr while they run.
class Silenced_cerr
{
public:
  Silenced_cerr() : saved_(std::cerr.rdbuf(nullptr)) {}
  ~Silenced_cerr() { std::cerr.rdbuf(saved_); }

private:
  std::streambuf* saved_;
};

struct Options
{
  std::string input, output, map = "identity", output_kind = "dual", placement; // placement: "" until chosen
  double cell_size = 0.01;
  double normal_weight = 0.1;
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
  std::string topology_report; // file of the flagged input faces
  std::vector<RSR::Topology_defect<Mesh::Face_index>>* defects = nullptr; // filled by the check
  long target_vertices = 0;
  std::size_t max_vertices = 0; // --max-vertices; main() sets the default (vertex_cap()) once
  double time_limit = 0;        // seconds; 0: none
  bool quiet = false;
  class Progress_line* progress = nullptr; // set by main()
};

/// Set by Ctrl-C (SIGINT): the progress visitor then cancels the remesh, and the
/// program checks it again after the remesh and before the files are renamed.
volatile std::sig_atomic_t interrupted = 0;

/// Set as the files start to be renamed into place: a Ctrl-C from then on comes too
/// late and is ignored, as the run ends with its files written and exit 0.
volatile std::sig_atomic_t committing = 0;

/// What an interrupted run says on stderr, whenever Ctrl-C came.
constexpr char interrupted_line[] = "range_space_remesh: interrupted: nothing was written\n";
constexpr int interrupted_status = 130; // 128 + SIGINT, as the shells report it

extern "C" void cancel_on_interrupt(int)
{
  if(committing)
    return;
  // while files are written (or at a second Ctrl-C, as when the reading takes long),
  // stop here: remove the temporary files, say so, exit; all async-signal-safe
  if(rsr_io::internal::has_pending_files() || interrupted) {
    rsr_io::internal::remove_pending_files();
    const ssize_t written = ::write(STDERR_FILENO, interrupted_line, sizeof interrupted_line - 1);
    static_cast<void>(written);
    ::_exit(interrupted_status);
  }
  interrupted = 1;
}

/// Thrown where the program checks for a Ctrl-C the remesh did not see.
struct Interrupted
{};

void stop_if_interrupted()
{
  if(interrupted)
    throw Interrupted();
}

/// The program's progress visitor: a progress line on stderr when it is a terminal
/// and the run takes more than a second (not with --quiet), --time-limit, and Ctrl-C,
/// which cancel the run.
class Progress_line
{
public:
  explicit Progress_line(const Options& options)
    : limit_(options.time_limit), show_(!options.quiet && ::isatty(STDERR_FILENO))
  {}

  bool operator()(RSR::Remeshing_stage stage, double fraction)
  {
    if(interrupted)
      return false;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if(limit_ > 0 && elapsed > limit_) {
      timed_out_ = true;
      return false;
    }
    if(show_ && elapsed > 1 && elapsed - last_shown_ >= 0.1) {
      std::fprintf(stderr, "\rrange_space_remesh: %-14s %3d%%", RSR::stage_name(stage), int(100 * fraction));
      std::fflush(stderr);
      last_shown_ = elapsed;
      shown_ = true;
    }
    return true;
  }

  /// Removes the progress line, if one was shown.
  void clear()
  {
    if(shown_)
      std::fputs("\r\033[K", stderr);
    shown_ = false;
  }

  bool timed_out() const { return timed_out_; }
  double limit() const { return limit_; }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double limit_;
  bool show_;
  double last_shown_ = 0;
  bool shown_ = false, timed_out_ = false;
};

/// `text` between quotes, with its control characters (a newline) escaped: a message
/// quoting it stays one line.
std::string quoted(const std::string& text)
{
  std::string out = "'";
  for(const unsigned char c : text) {
    if(c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", unsigned(c));
      out += escaped;
    } else {
      out += char(c);
    }
  }
  return out + "'";
}

/// Whether `text` is a decimal number: an optional sign, digits with an optional
/// fraction (or a fraction alone), an optional exponent; nothing else (no spaces, no
/// hexadecimal, no inf or nan).
bool is_decimal_number(const char* text)
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
double parse_number(const std::string& option, const char* text)
{
  if(!is_decimal_number(text))
    fail(option + " expects a decimal number (such as 0.01, 5 or 1e-3), got " + quoted(text));
  const double value = std::strtod(text, nullptr); // the "C" locale: the program sets none
  if(!std::isfinite(value))
    fail(option + " expects a finite number, got " + quoted(text));
  return value;
}

Options parse_arguments(int argc, char** argv)
{
  Options options;
  std::vector<std::string> positional;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    auto value = [&]() -> const char* {
      if(a + 1 >= argc)
        fail(arg + " expects a value");
      return argv[++a];
    };
    if((arg == "--help" || arg == "-h" || arg == "--version") && argc > 2)
      fail(arg + " takes no other argument (got " + quoted(a > 1 ? argv[1] : argv[2]) + ")");
    if(arg == "--help" || arg == "-h") {
      std::cout << usage;
      std::exit(EXIT_SUCCESS);
    } else if(arg == "--version") {
      std::cout << "range_space_remesh " RANGE_SPACE_REMESHING_VERSION_STR " (CGAL " CGAL_VERSION_STR ")\n";
      std::exit(EXIT_SUCCESS);
    } else if(arg == "--map") {
      options.map = value();
      if(options.map != "identity" && options.map != "gauss" && options.map != "position-normal" &&
         options.map != "position-normal-color" && options.map != "position-normal-color-gradient" &&
         options.map != "view")
        fail("unknown map '" + options.map +
             "' (available: identity, gauss, position-normal, position-normal-color, "
             "position-normal-color-gradient, view)");
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
        fail("unknown output '" + options.output_kind + "' (available: dual, primal)");
    } else if(arg == "--placement") {
      options.placement = value();
      if(options.placement != "qem" && options.placement != "sharp" && options.placement != "average")
        fail("unknown placement '" + options.placement + "' (available: qem, sharp, average)");
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
      fail("unknown option " + quoted(arg) + " (see --help)");
    } else {
      positional.push_back(arg);
    }
  }
  if(positional.size() != 2)
    fail("expected INPUT and OUTPUT (see --help)");
  options.input = positional[0];
  options.output = positional[1];
  if(options.placement.empty())
    options.placement = options.sharp_angle >= 0 ? "sharp" : "qem";
  return options;
}

bool is_supported_format(const std::string& path)
{
  const std::string ext = rsr_io::extension_of(path);
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl";
}

/// Reads a camera file (see --help); sets the depth weight to the pixels per unit
/// of a lateral step at the target's distance.
RSR::Camera read_camera(const std::string& path, double& depth_weight)
{
  // a few lines of text: refuse what is not a small regular file (/dev/zero would
  // be one endless line)
  std::error_code error;
  if(!std::filesystem::is_regular_file(path, error) || std::filesystem::file_size(path, error) > 65536 || error)
    fail("cannot read the camera file '" + path + "' (not a regular file of at most 64 KB)");
  std::ifstream in(path);
  if(!in)
    fail("cannot read the camera file '" + path + "'");
  std::array<double, 3> eye{}, target{}, up = {{0, 1, 0}};
  double fov = 60, width = 0, height = 0;
  bool has_eye = false, has_target = false;
  std::string line;
  for(int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string key;
    if(!(words >> key))
      continue;
    auto numbers = [&](int count) {
      std::vector<double> values(count);
      for(double& x : values)
        if(!(words >> x) || !std::isfinite(x))
          fail("camera file '" + path + "', line " + std::to_string(number) + ": '" + key + "' expects " +
               std::to_string(count) + " finite number(s)");
      std::string extra;
      if(words >> extra)
        fail("camera file '" + path + "', line " + std::to_string(number) + ": unexpected '" + extra + "'");
      return values;
    };
    if(key == "eye" || key == "target" || key == "up") {
      const auto v = numbers(3);
      (key == "eye" ? eye : key == "target" ? target : up) = {{v[0], v[1], v[2]}};
      has_eye = has_eye || key == "eye";
      has_target = has_target || key == "target";
    } else if(key == "fov") {
      fov = numbers(1)[0];
    } else if(key == "viewport") {
      const auto v = numbers(2);
      width = v[0];
      height = v[1];
    } else {
      fail("camera file '" + path + "', line " + std::to_string(number) + ": unknown keyword '" + key + "'");
    }
  }
  if(!has_eye || !has_target || !(width > 0))
    fail("camera file '" + path + "' needs eye, target and viewport lines");
  try {
    const RSR::Camera camera = RSR::make_look_at_camera(eye, target, up, fov, width, height);
    const double distance = std::sqrt(CGAL::square(eye[0] - target[0]) + CGAL::square(eye[1] - target[1]) +
                                      CGAL::square(eye[2] - target[2]));
    depth_weight = height / 2 / std::tan(fov * M_PI / 360) / distance;
    return camera;
  } catch(const RSR::Remeshing_error& e) {
    fail("camera file '" + path + "': " + e.what());
  }
}

/// The input mesh and what it took to get it.
struct Input
{
  Mesh mesh;
  RSR::Input_repair_statistics repairs;
  double read_ms = 0, repair_ms = 0;
};

/// The mesh's vertex colours ("v:color"), if it has them.
std::optional<Color_map> find_vertex_colors(const Mesh& mesh)
{
#if CGAL_VERSION_NR >= 1060000000 // Surface_mesh::property_map() returns an optional since CGAL 6
  return mesh.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color");
#else
  const auto [map, found] = mesh.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color");
  return found ? std::optional<Color_map>(map) : std::nullopt;
#endif
}

/// Gives the vertices of `mesh` the colours of the soup's points at their positions:
/// the repair only merges points that coincide and copies points, so each vertex
/// sits where some point of the file is (the first point there gives the colour).
void add_colors_by_position(const rsr_io::Polygon_soup& soup, Mesh& mesh)
{
  using Position = std::array<double, 3>;
  struct Hash
  {
    std::size_t operator()(const Position& p) const
    {
      std::size_t h = 0;
      for(double x : p)
        h = h * 1000003u ^ std::hash<double>()(x);
      return h;
    }
  };
  std::unordered_map<Position, std::size_t, Hash> point_at;
  point_at.reserve(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    point_at.emplace(soup.points[i], i);
  auto colors = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(auto v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    const auto found = point_at.find({{p.x(), p.y(), p.z()}});
    if(found != point_at.end()) {
      const auto& c = soup.colors[found->second];
      colors[v] = CGAL::IO::Color(c[0], c[1], c[2]);
    }
  }
}

/// Reads INPUT into a triangle mesh (see rsr_io::read_mesh_file): repaired into an
/// oriented 2-manifold unless --strict, polygons triangulated, vertex colours kept.
Input read_input(const std::string& path, bool strict)
{
  Input input;
  const auto start = std::chrono::steady_clock::now();
  rsr_io::Polygon_soup soup;
  try {
    soup = rsr_io::read_mesh_file(path);
  } catch(const rsr_io::Read_error& e) {
    fail(e.what());
  }
  const auto read = std::chrono::steady_clock::now();
  std::vector<K::Point_3> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  try {
    input.repairs = RSR::prepare_input(points, soup.polygons, input.mesh,
                                       strict ? RSR::Input_repair::REFUSE : RSR::Input_repair::REPAIR);
  } catch(const RSR::Remeshing_error& e) {
    fail("'" + path + "': " + e.what() + (strict ? " (drop --strict to repair it)" : ""));
  }
  if(!soup.colors.empty())
    add_colors_by_position(soup, input.mesh);
  const auto repaired = std::chrono::steady_clock::now();
  input.read_ms = std::chrono::duration<double, std::milli>(read - start).count();
  input.repair_ms = std::chrono::duration<double, std::milli>(repaired - read).count();
  return input;
}

/// One line on stderr when the input needed repairs.
void report_repairs(const std::string& path, const RSR::Input_repair_statistics& r)
{
  if(!r.repaired() && r.removed_isolated_points == 0)
    return;
  std::ostringstream line;
  line << "range_space_remesh: repaired '" << path << "':";
  const std::pair<std::size_t, const char*> counts[] = {
      {r.merged_points, "merged points"},
      {r.removed_isolated_points, "unused points removed"},
      {r.removed_repeated_corners, "repeated corners removed"},
      {r.removed_degenerate_polygons, "degenerate faces removed"},
      {r.removed_duplicate_polygons, "duplicate faces removed"},
      {r.reversed_polygons, "faces flipped"},
      {r.reversed_to_face_outward, "triangles flipped to face outward"},
      {r.non_manifold_edges, "non-manifold edges cut"},
      {r.split_non_manifold_points, "points copied to split non-manifold vertices"}};
  const char* separator = " ";
  for(const auto& [count, what] : counts)
    if(count > 0) {
      line << separator << count << " " << what;
      separator = ", ";
    }
  std::cerr << line.str() << (r.repaired() ? " (--strict refuses such input)" : "") << std::endl;
}

/// With --sharp-angle, the input with zero-area triangles along its creases, so that
/// the normal maps see each side's normal (vertex colours follow the copies).
Mesh with_creases_opened(Mesh input, const Options& options)
{
  if(!(options.sharp_angle >= 0))
    return input;
  Mesh creased;
  RSR::insert_crease_triangles(input, creased, options.sharp_angle);
  const auto colors = find_vertex_colors(input);
  if(colors) { // copies sit at their original's position: match them by position
    std::map<std::array<double, 3>, CGAL::IO::Color> by_position;
    for(auto v : vertices(input))
      by_position[{{input.point(v).x(), input.point(v).y(), input.point(v).z()}}] = (*colors)[v];
    auto copied = creased.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    for(auto v : vertices(creased))
      copied[v] = by_position[{{creased.point(v).x(), creased.point(v).y(), creased.point(v).z()}}];
  }
  return creased;
}

std::size_t components(const Mesh& mesh)
{
  std::vector<std::size_t> ids(num_faces(mesh));
  return PMP::connected_components(
      mesh, CGAL::make_property_map(ids));
}

std::size_t border_cycles(const Mesh& mesh)
{
  std::vector<bool> seen(mesh.number_of_halfedges(), false);
  std::size_t cycles = 0;
  for(auto h : halfedges(mesh)) {
    if(!is_border(h, mesh) || seen[h.idx()])
      continue;
    ++cycles;
    for(auto g : CGAL::halfedges_around_face(h, mesh))
      seen[g.idx()] = true;
  }
  return cycles;
}

/// The primal remesh, or the whole dual pipeline, with the named parameters `np`
/// (cell size, seeding and, but for the identity, the range map).
template <class NamedParameters>
RSR::Remesh_statistics run(const Mesh& input, const NamedParameters& np, const Options& options, Mesh& output)
{
  // the input's vertex colours, if it has them, are sampled onto the output
  constexpr bool colors =
      !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_color_map_t>::value;
  auto np_out = [&output] {
    return CGAL::parameters::vertex_color_map(
        output.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first);
  };
  RSR::Remesh_statistics stats;
  if(options.output_kind == "primal") {
    if constexpr(colors)
      stats.primal = RSR::primal_remesh(input, output, np, np_out());
    else
      stats.primal = RSR::primal_remesh(input, output, np);
    stats.time_total_ms = stats.primal.time_total_ms;
    return stats;
  }
  const auto placement = options.placement == "average" ? RSR::Dual_placement::AVERAGE
                         : options.placement == "sharp" ? RSR::Dual_placement::SHARP_FEATURES
                                                        : RSR::Dual_placement::QEM;
  const auto np_all =
      np.quad_collapse(options.collapse).dual_placement(placement).number_of_relaxation_steps(options.relax);
  if constexpr(colors)
    return RSR::remesh(input, output, np_all, np_out());
  else
    return RSR::remesh(input, output, np_all);
}

/// `run` with the input's vertex colours added to `np`, if it has any.
template <class NamedParameters>
RSR::Remesh_statistics run_with_colors(const Mesh& input, const NamedParameters& np, const Options& options,
                                       Mesh& output)
{
  if(const auto colors = find_vertex_colors(input))
    return run(input, np.vertex_color_map(*colors), options, output);
  return run(input, np, options, output);
}

/// The input's vertex normals for the normal-based maps: from a table computed in one
/// pass over the faces for the complete scan, which maps every vertex (about ten times
/// cheaper than reading each vertex's star on its own), lazily for --seeded, which
/// maps only the vertices the arcs reach.
class Input_normals
{
public:
  using key_type = Mesh::Vertex_index;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Input_normals(const Mesh& input, bool all_at_once) : lazy_(input)
  {
    if(!all_at_once)
      return;
    table_ = std::make_shared<std::vector<value_type>>(input.num_vertices()); // removed ones included: indices
    RSR::compute_vertex_normals(input, boost::make_iterator_property_map(
                                           table_->begin(), get(boost::vertex_index, input)));
  }

  friend value_type get(const Input_normals& map, key_type v)
  {
    return map.table_ ? (*map.table_)[std::size_t(v)] : get(map.lazy_, v);
  }

private:
  RSR::Lazy_vertex_normal_map<Mesh> lazy_;
  std::shared_ptr<std::vector<value_type>> table_; // shared by the maps' copies
};

/// The topology visitor of the program: keeps the defects.
struct Defect_collector
{
  std::vector<RSR::Topology_defect<Mesh::Face_index>>* defects;
  void operator()(const RSR::Topology_defect<Mesh::Face_index>& defect) const { defects->push_back(defect); }
};

/// The first number in the file (0 if none: "max", a missing file).
double number_in_file(const char* path)
{
  std::ifstream in(path);
  double x = 0;
  return in >> x ? x : 0;
}

/// The memory this process can still take, in bytes: Linux' MemAvailable, or less
/// inside a container whose memory limit (cgroup v2, else v1) is lower; 0 if unknown.
double available_memory()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  double kilobytes = 0, available = 0;
  while(meminfo >> key >> kilobytes >> unit)
    if(key == "MemAvailable:") {
      available = kilobytes * 1024;
      break;
    }
  const std::pair<const char*, const char*> limits[] = {
      {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
      {"/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes"}};
  for(const auto& [limit_file, usage_file] : limits) {
    const double limit = number_in_file(limit_file); // no limit: "max" (0 here) or about 2^63
    if(limit > 0 && limit < 1e18) {
      const double left = (std::max)(limit - number_in_file(usage_file), 1.0);
      if(available == 0 || left < available)
        available = left;
    }
  }
  return available;
}

/// The cap on the primal remesh's vertices: --max-vertices, or the library's default
/// lowered so that the run fits in three quarters of the available memory. A cell size
/// far too small is then refused at once with a message, where it would otherwise run
/// for minutes and end killed for want of memory. Bytes per primal vertex as measured
/// on refined_elephant with 3.9 million of them (peak resident size, input included).
std::size_t vertex_cap(const Options& options)
{
  if(options.max_vertices > 0)
    return options.max_vertices;
  const double bytes_per_vertex = options.output_kind == "primal" ? 400 : 1300;
  const double fitting = 0.75 * available_memory() / bytes_per_vertex;
  std::size_t cap = RSR::default_maximum_number_of_vertices;
  if(fitting > 0 && fitting < double(cap))
    cap = (std::max)(std::size_t(fitting), std::size_t(100000));
  return cap;
}

/// Refuses a --target-vertices above the cap `cap`, which no cell size could give
/// without exceeding it: the search would only run in vain.
void check_target_vertices(const Options& options, std::size_t cap)
{
  if(options.target_vertices > 0 && std::size_t(options.target_vertices) > cap)
    fail("--target-vertices " + std::to_string(options.target_vertices) + " is above the cap of " +
         std::to_string(cap) + " output vertices (" +
         (options.max_vertices > 0 ? "--max-vertices" : "the default for the available memory") +
         "): ask for fewer, or raise the cap with --max-vertices");
}

/// Remeshes with the map of the options, at cell size `h` or, with --target-vertices,
/// at the one the library finds from it. In relative mode (length_unit = the
/// bounding-box diagonal) the weights are scaled so that a cell of size H bounds
/// positions by H diagonals and normals by H / W (Gauss map: H, in units of the unit
/// cube).
RSR::Remesh_statistics remesh(const Mesh& input, const Input_normals& normals, double h, const Options& options,
                              Mesh& output)
{
  const auto seeding =
      options.seeded ? RSR::Seeding_method::SEEDED : RSR::Seeding_method::COMPLETE_SCAN;
  if(options.seeded && options.preserve_topology)
    fail("--preserve-topology needs the complete scan: drop --seeded");
  options.defects->clear();
  Progress_line* progress = options.progress;
  const auto np = RSR::parameters::grid_spacing(h)
                      .number_of_target_vertices(std::size_t(options.target_vertices)) // 0: none
                      .seeding_method(seeding)
                      .maximum_number(options.max_vertices)
                      .check_topology(options.check_topology && !options.seeded)
                      .preserve_topology(options.preserve_topology)
                      .topology_visitor(Defect_collector{options.defects})
                      .progress_visitor([progress](RSR::Remeshing_stage stage, double fraction) {
                        return (*progress)(stage, fraction);
                      });
  const auto points = get(CGAL::vertex_point, input);
  if(options.map == "gauss")
    return run_with_colors(input, np.range_map(RSR::Gauss_range_map<Input_normals>(normals, options.length_unit)),
                           options, output);
  if(options.map == "position-normal")
    return run_with_colors(input,
                           np.range_map(RSR::Position_normal_range_map(points, normals, 1.0,
                                                                       options.normal_weight * options.length_unit)),
                           options, output);
  if(options.map == "position-normal-color" || options.map == "position-normal-color-gradient") {
    const auto found = find_vertex_colors(input);
    if(!found)
      fail("--map " + options.map + " needs vertex colours: give a PLY or COFF input with colours");
    const double unit = options.length_unit, wn = options.normal_weight * unit;
    const bool gradient = options.map == "position-normal-color-gradient";
    // gradients of sharp colour edges reach 1 / (edge length): a smaller default
    const double wc = options.color_weight >= 0 ? options.color_weight : (gradient ? 0.01 : 1.0);
    if(options.map == "position-normal-color")
      return run_with_colors(
          input, np.range_map(RSR::Position_normal_color_range_map(points, normals, *found, 1.0, wn, wc * unit)),
          options, output);
    // gradient magnitudes are colour per length: one more length unit
    const RSR::Color_gradient_magnitude_map<Mesh, Color_map> gradients(input, *found);
    return run_with_colors(
        input,
        np.range_map(RSR::Position_normal_color_range_map(points, normals, gradients, 1.0, wn, wc * unit * unit)),
        options, output);
  }
  if(options.map == "view")
    return run_with_colors(input,
                           np.range_map(RSR::View_range_map<boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>(
                               get(CGAL::vertex_point, input), options.camera, options.depth_weight)),
                           options, output);
  return run_with_colors(input, np, options, output);
}

/// The input faces where the topology check found defects, as a mesh.
Mesh flagged_faces(const Mesh& input, const std::vector<RSR::Topology_defect<Mesh::Face_index>>& defects)
{
  std::set<Mesh::Face_index> flagged;
  for(const auto& defect : defects)
    flagged.insert(defect.input_faces.begin(), defect.input_faces.end());
  Mesh report;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> copy;
  for(Mesh::Face_index f : flagged) {
    std::vector<Mesh::Vertex_index> corners;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(halfedge(f, input), input)) {
      auto found = copy.find(v);
      if(found == copy.end())
        found = copy.emplace(v, report.add_vertex(input.point(v))).first;
      corners.push_back(found->second);
    }
    if(report.add_face(corners) == Mesh::null_face()) // a face against the orientation of the others:
      report.add_face(std::vector<Mesh::Vertex_index>(corners.rbegin(), corners.rend())); // keep it anyway
  }
  return report;
}

/// One line on stderr when the output's topology may differ from the input's.
void warn_about_topology(const RSR::Remesh_statistics& all, const Options& options,
                         const std::vector<RSR::Topology_defect<Mesh::Face_index>>& defects)
{
  const RSR::Statistics& s = all.primal;
  const bool dual = options.output_kind != "primal";
  if(!s.topology_checked || (dual ? all.topology_preserved() : s.topology_preserved()))
    return;
  std::cerr << "range_space_remesh: warning: the remesh may not have the input's topology ("
            << s.closed_loops << " closed loops, " << s.non_disk_cells << " non-disk cells, " << s.lost_components
            << " lost components, " << s.uncrossed_border_cycles << " lost border cycles, "
            << s.dropped_pieces + (dual ? all.dual.dropped_pieces : 0) << " dropped pieces; Euler characteristic "
            << s.input_euler_characteristic << " -> " << s.output_euler_characteristic << ", "
            << defects.size() << " defects); use --preserve-topology or a smaller cell size" << std::endl;
}

/// Where the run's time went outside the remesher.
struct Io_times
{
  double read_ms = 0, repair_ms = 0, write_ms = 0;
};

void print_stats(const Options& options, const Mesh& input, const Mesh& output, const RSR::Remesh_statistics& all,
                 double h, const RSR::Input_repair_statistics& repairs, const Io_times& io)
{
  using nlohmann::json;
  const RSR::Statistics& s = all.primal;
  std::map<std::size_t, std::size_t> valences;
  for(auto v : vertices(output))
    ++valences[degree(v, output)];
  std::size_t quads = 0;
  for(auto f : faces(output))
    quads += (degree(f, output) == 4);
  // file names may hold any byte: replace what is not UTF-8 rather than fail
  const auto error_handler = json::error_handler_t::replace;
  json j;
  j["input"] = options.input;
  j["output"] = options.output;
  j["map"] = options.map;
  j["D"] = options.map == "position-normal" ? 6 : options.map.rfind("position-normal-color", 0) == 0 ? 9 : 3;
  j["normal_weight"] = options.map.rfind("position-normal", 0) == 0 ? options.normal_weight : 0.;
  j["cell_size"] = h;
  j["seeding"] = options.seeded ? "seeded" : "complete";
  j["output_kind"] = options.output_kind;
  j["placement"] = options.placement;
  j["collapse"] = options.collapse;
  j["relaxation_steps"] = options.relax;
  j["triangulated"] = repairs.triangulated_polygons > 0;
  j["input_vertices"] = num_vertices(input);
  j["input_faces"] = num_faces(input);
  j["input_components"] = components(input);
  j["output_vertices"] = num_vertices(output);
  j["output_edges"] = num_edges(output);
  j["output_faces"] = num_faces(output);
  j["output_components"] = components(output);
  j["mapped_vertices"] = s.mapped_vertices;
  j["visited_faces"] = s.visited_faces;
  j["intersection_vertices"] = s.intersection_vertices;
  j["digons"] = s.digons;
  j["non_simple_faces"] = s.non_simple_faces;
  j["dropped_pieces"] = s.dropped_pieces;
  j["input_border_cycles"] = border_cycles(input);
  j["output_border_cycles"] = border_cycles(output);
  j["boundary_digons"] = s.boundary_digons;
  j["boundary_corners"] = s.boundary_corners;
  j["uncrossed_border_cycles"] = s.uncrossed_border_cycles;
  j["quads"] = quads;
  j["non_quads"] = num_faces(output) - quads;
  j["joined_triangle_pairs"] = all.dual.joined_triangle_pairs;
  j["dual_dropped_pieces"] = all.dual.dropped_pieces;
  j["removed_pinches"] = all.dual.removed_pinches;
  j["joined_parallel_edges"] = all.dual.joined_parallel_edges;
  j["collapsed_quads"] = all.collapse.collapsed_quads;
  j["removed_doublets"] = all.collapse.removed_doublets;
  j["rotated_edges"] = all.collapse.rotated_edges;
  j["neutral_rotations"] = all.collapse.neutral_rotations;
  j["untangle"] = {{"folded_before", all.untangle.folded_before},
                   {"non_convex_before", all.untangle.non_convex_before},
                   {"folded_after", all.untangle.folded_after},
                   {"non_convex_after", all.untangle.non_convex_after},
                   {"moves", all.untangle.moves},
                   {"rounds", all.untangle.rounds}};
  j["cell_size_used"] = s.cell_size;
  j["input_repairs"] = {{"repaired", repairs.repaired()},
                        {"merged_points", repairs.merged_points},
                        {"removed_isolated_points", repairs.removed_isolated_points},
                        {"removed_repeated_corners", repairs.removed_repeated_corners},
                        {"removed_degenerate_faces", repairs.removed_degenerate_polygons},
                        {"removed_duplicate_faces", repairs.removed_duplicate_polygons},
                        {"flipped_faces", repairs.reversed_polygons},
                        {"flipped_to_face_outward", repairs.reversed_to_face_outward},
                        {"non_manifold_edges", repairs.non_manifold_edges},
                        {"split_non_manifold_points", repairs.split_non_manifold_points},
                        {"triangulated_faces", repairs.triangulated_polygons}};
  j["topology"] = {{"checked", s.topology_checked},
                   {"preserved", options.output_kind == "primal" ? s.topology_preserved() : all.topology_preserved()},
                   {"closed_loops", s.closed_loops},
                   {"harmless_loops", s.harmless_loops},
                   {"non_disk_cells", s.non_disk_cells},
                   {"lost_components", s.lost_components},
                   {"input_euler_characteristic", s.input_euler_characteristic},
                   {"primal_euler_characteristic", s.output_euler_characteristic},
                   {"refinements", s.topology_refinements}};
  json histogram = json::object();
  for(const auto& [valence, count] : valences)
    histogram[std::to_string(valence)] = count;
  j["valence_histogram"] = histogram;
  j["time_ms"] = {{"read", io.read_ms},         {"repair", io.repair_ms},
                  {"seeding", s.time_seeding_ms}, {"tracing", s.time_tracing_ms},
                  {"faces", s.time_faces_ms},     {"topology", s.time_topology_ms},
                  {"output", s.time_output_ms},   {"dual", all.dual.time_ms},
                  {"collapse", all.collapse.time_ms}, {"relaxation", all.time_relaxation_ms},
                  {"untangle", all.untangle.time_ms},
                  {"total", all.time_total_ms},   {"write", io.write_ms}};
  std::cout << j.dump(-1, ' ', false, error_handler) << std::endl;
}

/// Whether two paths name the same file: the same name, the same canonical path (the
/// file may not exist yet), or the same existing file under another name (a hard link).
bool same_file(const std::string& a, const std::string& b)
{
  namespace fs = std::filesystem;
  std::error_code a_error, b_error, equivalent_error;
  const fs::path canonical_a = fs::weakly_canonical(fs::absolute(a, a_error), a_error);
  const fs::path canonical_b = fs::weakly_canonical(fs::absolute(b, b_error), b_error);
  return a == b || (!a_error && !b_error && canonical_a == canonical_b) || fs::equivalent(a, b, equivalent_error);
}

/// Refuses an OUTPUT that would overwrite INPUT (the input would be lost for a remesh
/// of it), and a report that would overwrite INPUT or OUTPUT.
void check_output_paths(const Options& options)
{
  if(same_file(options.output, options.input))
    fail("OUTPUT '" + options.output + "' would overwrite INPUT; write the remesh to another file");
  if(options.topology_report.empty())
    return;
  for(const std::string& other : {options.input, options.output})
    if(same_file(options.topology_report, other))
      fail("--topology-report '" + options.topology_report + "' would overwrite '" + other + "'");
}

} // namespace

int main(int argc, char** argv)
{
  // CGAL warnings (e.g. a polygon the constrained triangulation cannot handle) are
  // dealt with by the program; keep stderr to the one-line error contract.
  CGAL::set_warning_handler([](const char*, const char*, const char*, int, const char*) {});
  rsr_io::remove_temporary_files_on_signals();
  std::signal(SIGINT, cancel_on_interrupt);
  try {
    Options options = parse_arguments(argc, argv);
    if(!is_supported_format(options.output))
      fail("cannot write '" + options.output + "': unsupported format (use .off .obj .ply .stl)");
    if(!options.topology_report.empty() && !is_supported_format(options.topology_report))
      fail("cannot write '" + options.topology_report + "': unsupported format (use .off .obj .ply .stl)");
    check_output_paths(options);
    check_target_vertices(options, vertex_cap(options)); // before any work
    std::vector<RSR::Topology_defect<Mesh::Face_index>> defects;
    options.defects = &defects;
    Io_times io;
    Input read = read_input(options.input, options.strict);
    io.read_ms = read.read_ms;
    io.repair_ms = read.repair_ms;
    const Mesh input = with_creases_opened(std::move(read.mesh), options);
    // once, the input read: the runs of --target-vertices and --preserve-topology share it
    const std::size_t cap = vertex_cap(options);
    check_target_vertices(options, cap); // the memory left may have lowered the default cap
    options.max_vertices = cap;

    double h = options.cell_size;
    if(!options.absolute) {
      const CGAL::Bbox_3 box = PMP::bbox(input);
      const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
      double diagonal = std::sqrt(dx * dx + dy * dy + dz * dz);
      if(!(diagonal > 0) || !std::isfinite(diagonal)) // squares out of range (coordinates near 1e300, 1e-300)
        diagonal = std::hypot(std::hypot(dx, dy), dz);
      if(!(diagonal > 0))
        fail("the input's bounding box is a single point");
      h *= diagonal;
      options.length_unit = diagonal;
    }
    if(options.map == "view") {
      if(options.camera_file.empty())
        fail("--map view needs --camera FILE");
      options.camera = read_camera(options.camera_file, options.depth_weight);
      if(!options.absolute) // H: a fraction of the viewport's diagonal
        h = options.cell_size * std::hypot(options.camera.width, options.camera.height);
    }
    const bool uses_normals = options.map == "gauss" || options.map.rfind("position-normal", 0) == 0;
    const Input_normals normals(input, uses_normals && !options.seeded);
    Mesh output;
    Progress_line progress(options);
    options.progress = &progress;
    RSR::Remesh_statistics stats;
    try {
      stats = remesh(input, normals, h, options, output);
    } catch(const RSR::Remeshing_cancelled&) {
      progress.clear();
      if(interrupted)
        throw;
      std::ostringstream message;
      message << "the time limit of " << progress.limit() << " s was reached: nothing was written";
      fail(message.str());
    }
    progress.clear();
    stop_if_interrupted(); // after the remesh's last report
    if(options.target_vertices > 0) // the size found
      h = stats.primal.cell_size;
    if(num_faces(output) == 0)
      fail("the remesh is empty: at this cell size the surface is not resolved (" +
           std::to_string(stats.primal.dropped_pieces + stats.dual.dropped_pieces) +
           " degenerate pieces dropped); use a smaller cell size");
    if(!CGAL::is_valid_polygon_mesh(output))
      fail("internal error: the remesh is not a valid polygon mesh; please report it");
    if(stats.dual.parallel_edges > 0)
      fail("at this cell size the dual has " + std::to_string(stats.dual.parallel_edges) +
           " pair(s) of parallel edges, which a mesh file cannot store; use a smaller cell size "
           "or --output primal");

    // every file is written under a temporary name first, then all are renamed
    const auto write_start = std::chrono::steady_clock::now();
    rsr_io::Output_files files;
    const rsr_io::Write_options write_options{options.binary, 17};
    try {
      Silenced_cerr silence; // CGAL's writers explain failures on std::cerr
      const auto colors = find_vertex_colors(output);
      files.add(output, options.output, colors ? &*colors : nullptr, write_options);
      if(!options.topology_report.empty())
        files.add(flagged_faces(input, defects), options.topology_report, static_cast<const Color_map*>(nullptr),
                  write_options);
      stop_if_interrupted(); // a Ctrl-C from here on comes too late: the files are written
      committing = 1;
      files.commit();
    } catch(const rsr_io::Write_error& e) {
      fail(e.what());
    }
    io.write_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - write_start).count();
    report_repairs(options.input, read.repairs);
    warn_about_topology(stats, options, defects);
    if(options.stats)
      print_stats(options, input, output, stats, h, read.repairs, io);
    return EXIT_SUCCESS;
  } catch(const Failure& f) {
    std::cerr << "range_space_remesh: " << f.message << std::endl;
  } catch(const Interrupted&) {
    std::cerr << interrupted_line << std::flush;
    return interrupted_status;
  } catch(const RSR::Remeshing_error& e) {
    if(e.kind() == RSR::Remeshing_error::Kind::CANCELLED) {
      std::cerr << interrupted_line << std::flush;
      return interrupted_status;
    }
    const bool capped = e.kind() == RSR::Remeshing_error::Kind::OUTPUT_TOO_LARGE;
    std::cerr << "range_space_remesh: " << e.what()
              << (capped ? " (use a larger --cell-size, or raise the cap with --max-vertices)" : "") << std::endl;
  } catch(const std::bad_alloc&) {
    std::cerr << "range_space_remesh: out of memory" << std::endl;
  } catch(const std::exception& e) { // one line, whatever the message (CGAL's assertions have several)
    const std::string message = e.what();
    std::cerr << "range_space_remesh: " << message.substr(0, message.find('\n')) << std::endl;
  }
  return 2;
}
