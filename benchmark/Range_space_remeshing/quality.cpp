// quality [--json] MESH...
// quality [--json] --measure INPUT REMESH   (the same measures of a remesh made elsewhere)
//
// The measuring instrument of issue 39 (output quality): for each mesh and map
// (identity, position + normal), the command-line program's default pipeline (dual
// with QEM placement, quad collapse with edge rotations, 3 relaxation steps, topology
// check on) at a target of 25 % of the input's vertex count, and what its output is
// worth to a user:
//
//  * interior vertices of valence 4, border vertices of valence 3 (the regular ones of
//    a quad mesh's border), each as a share of its own kind;
//  * folded or non-convex quads: min over the quad's corners of
//    (e_next x e_prev) . n / (|e_next| |e_prev|) <= 0, n the quad's unit vector-area
//    normal (the definition); a corner with an edge of length 0, or a quad of
//    vector area 0, scores 0 and counts;
//  * the 1st percentile (nearest rank) and the minimum of the corner angles of all
//    quads: the unsigned angle between the corner's two edges, in degrees;
//  * faces that are not quads;
//  * the output's topology against the input's: Euler characteristic V - E + F,
//    connected components of faces, border cycles;
//  * the vertex count reached and the wall time of the run (input normals included).
//
// Everything is computed here from the output mesh's connectivity and points, none
// of it from the library's statistics: the numbers must judge the library, not repeat
// it. Markdown on stdout (with --json, a JSON array of one object a run instead);
// deterministic but for the time column.

#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace RSR = CGAL::Range_space_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;
using benchmark_support::K;
using benchmark_support::Mesh;
using Point = K::Point_3;
using Vector = K::Vector_3;

namespace {

// ---------------------------------------------------------------------------------
// Corner quality: the one formula every quad is judged by

/// The quad's unit vector-area normal: the vector area of a quadrilateral, (1/2) sum of
/// p_i x p_(i+1), is (1/2) (p2 - p0) x (p3 - p1), here normalised (the difference form
/// does not lose digits to the distance from the origin); the zero vector when the
/// vector area vanishes (a symmetric bow-tie, a quad flat as a segment).
Vector unit_vector_area_normal(const std::array<Point, 4>& quad)
{
  const Vector area = CGAL::cross_product(quad[2] - quad[0], quad[3] - quad[1]);
  const double length = std::sqrt(area.squared_length());
  return length > 0 ? area / length : CGAL::NULL_VECTOR;
}

/// (e_next x e_prev) . n / (|e_next| |e_prev|) at corner i: the sine of the corner's
/// angle, signed by the side of n it turns to; 0 where an edge has length 0.
double corner_quality(const std::array<Point, 4>& quad, int i, const Vector& n)
{
  const Vector e_next = quad[(i + 1) % 4] - quad[i], e_prev = quad[(i + 3) % 4] - quad[i];
  const double lengths = std::sqrt(e_next.squared_length() * e_prev.squared_length());
  return lengths > 0 ? CGAL::cross_product(e_next, e_prev) * n / lengths : 0.;
}

double min_corner_quality(const std::array<Point, 4>& quad)
{
  const Vector n = unit_vector_area_normal(quad);
  double worst = 1;
  for(int i = 0; i < 4; ++i)
    worst = (std::min)(worst, corner_quality(quad, i, n));
  return worst;
}

bool is_folded_or_non_convex(const std::array<Point, 4>& quad) { return min_corner_quality(quad) <= 0; }

/// The score of a square and a 60° rhombus, and the classifier on quads whose answer
/// is known, each also tilted out of the xy plane
/// and with its corners in the opposite order (its normal then points down): the normal
/// must come from the quad, not from an axis. The program must not measure with a
/// broken instrument, so a wrong answer aborts it.
void check_classifier_on_hand_made_quads()
{
  const std::array<Point, 4> convex{{{0, 0, 0}, {2, 0, 0}, {2.5, 1, 0}, {0, 1.5, 0}}};
  const std::array<Point, 4> dart{{{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}}}; // reflex at (0.5, 0.5)
  const std::array<Point, 4> bow_tie{{{0, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 0}}};  // edges 1-2 and 3-0 cross
  const auto tilted = [](std::array<Point, 4> q) {
    for(Point& p : q)
      p = Point(p.x(), 0.6 * p.y() - 0.8 * p.z(), 0.8 * p.y() + 0.6 * p.z());
    return q;
  };
  const auto reversed = [](std::array<Point, 4> q) {
    std::reverse(q.begin(), q.end());
    return q;
  };
  // the score itself: the sine of the smallest corner angle, 1 on a square
  const std::array<Point, 4> square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  const std::array<Point, 4> rhombus_60{{{0, 0, 0}, {2, 0, 0}, {3, std::sqrt(3.), 0}, {1, std::sqrt(3.), 0}}}; // side 2
  bool right = std::abs(min_corner_quality(square) - 1) < 1e-12 &&
               std::abs(min_corner_quality(tilted(rhombus_60)) - std::sqrt(0.75)) < 1e-12;
  for(const auto& [quad, bad] : {std::pair(convex, false), std::pair(dart, true), std::pair(bow_tie, true)})
    for(const auto& seen : {quad, tilted(quad), reversed(quad), reversed(tilted(quad))})
      right = right && is_folded_or_non_convex(seen) == bad;
  if(!right) {
    std::cerr << "quality: the corner-quality check misclassifies a hand-made quad" << std::endl;
    std::abort();
  }
}

// ---------------------------------------------------------------------------------
// Measures of the output mesh

std::array<Point, 4> quad_points(const Mesh& m, Mesh::Face_index f)
{
  std::array<Point, 4> quad;
  int i = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
    quad[i++] = m.point(v);
  return quad;
}

/// The unsigned angle at corner i, in degrees.
double corner_angle(const std::array<Point, 4>& quad, int i)
{
  const Vector e_next = quad[(i + 1) % 4] - quad[i], e_prev = quad[(i + 3) % 4] - quad[i];
  const double lengths = std::sqrt(e_next.squared_length() * e_prev.squared_length());
  return lengths > 0 ? std::acos(std::clamp(e_next * e_prev / lengths, -1., 1.)) * 180 / M_PI : 0.;
}

/// The nearest-rank percentile: the smallest value with at least `percent` % of the
/// values at or below it.
double percentile(std::vector<double> values, double percent)
{
  if(values.empty())
    return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t rank = std::size_t(std::ceil(percent / 100 * double(values.size())));
  return values[rank > 0 ? rank - 1 : 0];
}

struct Shape
{
  std::size_t interior_vertices = 0, interior_valence_4 = 0;
  std::size_t border_vertices = 0, border_valence_3 = 0;
  std::size_t quads = 0, bad_quads = 0, non_quads = 0;
  double angle_p1 = NAN, angle_min = NAN;
};

void count_valences(const Mesh& m, Shape& s)
{
  for(auto v : vertices(m)) {
    if(is_border(v, m)) {
      ++s.border_vertices;
      s.border_valence_3 += degree(v, m) == 3;
    } else {
      ++s.interior_vertices;
      s.interior_valence_4 += degree(v, m) == 4;
    }
  }
}

void measure_faces(const Mesh& m, Shape& s)
{
  std::vector<double> angles;
  for(auto f : faces(m)) {
    if(degree(f, m) != 4) {
      ++s.non_quads;
      continue;
    }
    ++s.quads;
    const auto quad = quad_points(m, f);
    s.bad_quads += is_folded_or_non_convex(quad);
    for(int i = 0; i < 4; ++i)
      angles.push_back(corner_angle(quad, i));
  }
  s.angle_p1 = percentile(angles, 1);
  s.angle_min = angles.empty() ? NAN : *std::min_element(angles.begin(), angles.end());
}

Shape shape_of(const Mesh& m)
{
  Shape s;
  count_valences(m, s);
  measure_faces(m, s);
  return s;
}

struct Topology
{
  long euler = 0;
  std::size_t components = 0, border_cycles = 0;
  bool operator==(const Topology& o) const
  {
    return euler == o.euler && components == o.components && border_cycles == o.border_cycles;
  }
};

std::size_t count_border_cycles(const Mesh& m)
{
  std::vector<bool> seen(m.num_halfedges(), false); // by index, removed halfedges included
  std::size_t cycles = 0;
  for(auto h : halfedges(m)) {
    if(!is_border(h, m) || seen[h.idx()])
      continue;
    ++cycles;
    // a border cycle: the halfedges of the "hole" face, followed by next()
    for(auto g : CGAL::halfedges_around_face(h, m))
      seen[g.idx()] = true;
  }
  return cycles;
}

Topology topology_of(const Mesh& m)
{
  Topology t;
  t.euler = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  t.components = PMP::connected_components(m, component);
  t.border_cycles = count_border_cycles(m);
  return t;
}

std::string describe(const Topology& t)
{
  std::ostringstream out;
  out << "χ " << t.euler << ", " << t.components << " comp., " << t.border_cycles << " border cycles";
  return out.str();
}

/// "kept", or each of χ, components and border cycles that changed, as "before → after".
std::string topology_change(const Topology& in, const Topology& out)
{
  if(in == out)
    return "kept";
  std::ostringstream s;
  const char* separator = "";
  const auto changed = [&](const char* name, long before, long after) {
    if(before != after) {
      s << separator << name << " " << before << " → " << after;
      separator = ", ";
    }
  };
  changed("χ", in.euler, out.euler);
  changed("components", long(in.components), long(out.components));
  changed("border cycles", long(in.border_cycles), long(out.border_cycles));
  return s.str();
}

// ---------------------------------------------------------------------------------
// The runs

constexpr double normal_weight = 0.1;      // bounding-box diagonals per unit of normal: the program's default
constexpr double first_cell_size = 0.01;   // diagonals: the program's default, where its search starts
constexpr double target_fraction = 0.25;   // of the input's vertices

struct Model
{
  std::string name;
  Mesh mesh;
  double diagonal = 0;
  Topology topology;
};

struct Run
{
  std::string model, map, error; // error: why remesh() gave no mesh
  std::size_t input_vertices = 0, target = 0, output_vertices = 0;
  double ms = 0;
  Shape shape;
  Topology input_topology, output_topology;
};

/// The named parameters of the program's default pipeline (see shared_parameters() and run()
/// in tools/range_space_remesh/range_maps.h), without a range map.
auto program_parameters(const Model& model, std::size_t target)
{
  return RSR::parameters::grid_spacing(first_cell_size * model.diagonal)
      .number_of_target_vertices(target)
      .seeding_method(RSR::Seeding_method::COMPLETE_SCAN)
      .check_topology(true)
      .preserve_topology(false)
      .quad_collapse(true)
      .dual_placement(RSR::Dual_placement::QEM)
      .number_of_relaxation_steps(3);
}

/// Remeshes `model` with `map` ("identity" or "position-normal") into `output`; the
/// position-normal map reads a table of vertex normals computed in one pass, as the
/// program's complete scan does, and that pass is part of the run.
void remesh_with_map(const Model& model, const std::string& map, std::size_t target, Mesh& output)
{
  if(map == "identity") {
    RSR::remesh(model.mesh, output, program_parameters(model, target));
    return;
  }
  auto normals = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), model.mesh);
  RSR::compute_vertex_normals(model.mesh, normals);
  const RSR::Position_normal_range_map f(get(CGAL::vertex_point, model.mesh), normals, 1.0,
                                         normal_weight * model.diagonal);
  RSR::remesh(model.mesh, output, program_parameters(model, target).range_map(f));
}

void measure_output(const Mesh& output, Run& r)
{
  r.output_vertices = num_vertices(output);
  r.shape = shape_of(output);
  r.output_topology = topology_of(output);
}

Run measure_run(const Model& model, const std::string& map)
{
  Run r;
  r.model = model.name;
  r.map = map;
  r.input_vertices = num_vertices(model.mesh);
  r.target = std::size_t(target_fraction * double(r.input_vertices));
  r.input_topology = model.topology;
  Mesh output;
  const auto start = std::chrono::steady_clock::now();
  try {
    remesh_with_map(model, map, r.target, output);
  } catch(const RSR::Remeshing_error& e) {
    r.error = e.what();
  }
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  measure_output(output, r);
  return r;
}

/// A remesh made elsewhere (the program's output file, a later version's): the same
/// measures, without a target or a time.
Run measure_file(const Model& model, const std::string& file)
{
  Run r;
  r.model = model.name;
  r.map = "file " + benchmark_support::model_name(file);
  r.input_vertices = num_vertices(model.mesh);
  r.input_topology = model.topology;
  r.ms = NAN;
  Mesh output;
  if(!CGAL::IO::read_polygon_mesh(file, output))
    r.error = "cannot read '" + file + "'";
  measure_output(output, r);
  return r;
}

// ---------------------------------------------------------------------------------
// Output

double percent(std::size_t part, std::size_t whole) { return whole > 0 ? 100. * double(part) / double(whole) : NAN; }

std::string fixed(double x, int digits)
{
  if(std::isnan(x))
    return "–";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, x);
  return text;
}

void print_markdown_header()
{
  std::cout << "| model | map | input vertices | target | output vertices | interior valence 4 | border valence 3 | "
               "folded or non-convex quads | 1st-percentile corner angle | min corner angle | non-quads | "
               "input topology | topology of the output | ms |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|\n";
}

void print_markdown_row(const Run& r)
{
  const Shape& s = r.shape;
  std::cout << "| " << r.model << " | " << r.map << " | " << r.input_vertices << " | "
            << (r.target > 0 ? std::to_string(r.target) : "–") << " | ";
  if(!r.error.empty()) {
    std::cout << "no output: " << r.error << " | | | | | | | " << describe(r.input_topology) << " | | "
              << fixed(r.ms, 0) << " |\n";
    return;
  }
  std::cout << r.output_vertices
            << (r.target > 0 ? " (" + fixed(percent(r.output_vertices, r.target) - 100, 1) + " %)" : "") << " | "
            << fixed(percent(s.interior_valence_4, s.interior_vertices), 1) << " % | "
            << (s.border_vertices > 0 ? fixed(percent(s.border_valence_3, s.border_vertices), 1) + " %" : "–")
            << " | " << s.bad_quads << " (" << fixed(percent(s.bad_quads, s.quads), 2) << " %) | "
            << fixed(s.angle_p1, 1) << "° | " << fixed(s.angle_min, 1) << "° | " << s.non_quads << " | "
            << describe(r.input_topology) << " | " << topology_change(r.input_topology, r.output_topology) << " | "
            << fixed(r.ms, 0) << " |\n";
}

std::string json_string(const std::string& s)
{
  std::string quoted = "\"";
  for(char c : s) {
    if(c == '"' || c == '\\')
      quoted += '\\';
    if(static_cast<unsigned char>(c) < 0x20)
      quoted += ' '; // control characters (an error's newline) as spaces
    else
      quoted += c;
  }
  return quoted + "\"";
}

std::string json_number(double x) { return std::isnan(x) ? "null" : fixed(x, 4); }

std::string json_topology(const Topology& t)
{
  return "{\"euler\": " + std::to_string(t.euler) + ", \"components\": " + std::to_string(t.components) +
         ", \"border_cycles\": " + std::to_string(t.border_cycles) + "}";
}

void print_json_run(const Run& r, bool last)
{
  const Shape& s = r.shape;
  std::cout << "  {\"model\": " << json_string(r.model) << ", \"map\": " << json_string(r.map)
            << ", \"error\": " << (r.error.empty() ? "null" : json_string(r.error))
            << ", \"input_vertices\": " << r.input_vertices << ", \"target_vertices\": " << r.target
            << ", \"output_vertices\": " << r.output_vertices << ", \"interior_vertices\": " << s.interior_vertices
            << ", \"interior_valence_4\": " << s.interior_valence_4 << ", \"border_vertices\": " << s.border_vertices
            << ", \"border_valence_3\": " << s.border_valence_3 << ", \"quads\": " << s.quads
            << ", \"folded_or_non_convex_quads\": " << s.bad_quads << ", \"non_quads\": " << s.non_quads
            << ", \"corner_angle_p1_degrees\": " << json_number(s.angle_p1)
            << ", \"corner_angle_min_degrees\": " << json_number(s.angle_min)
            << ", \"input_topology\": " << json_topology(r.input_topology)
            << ", \"output_topology\": " << json_topology(r.output_topology)
            << ", \"topology_kept\": " << (r.input_topology == r.output_topology ? "true" : "false")
            << ", \"ms\": " << json_number(r.ms) << "}" << (last ? "\n" : ",\n");
}

bool read_model(const std::string& file, Model& model)
{
  if(!benchmark_support::read_triangle_mesh(file, model.mesh, "quality"))
    return false;
  model.name = benchmark_support::model_name(file);
  model.diagonal = benchmark_support::bbox_diagonal(model.mesh);
  model.topology = topology_of(model.mesh);
  return true;
}

constexpr const char* usage = "usage: quality [--json] MESH...\n"
                              "       quality [--json] --measure INPUT REMESH   (a remesh made elsewhere)";

/// The runs of the default table: both maps on every mesh.
bool measure_meshes(const std::vector<std::string>& files, std::vector<Run>& runs)
{
  for(const std::string& file : files) {
    Model model;
    if(!read_model(file, model))
      return false;
    for(const char* map : {"identity", "position-normal"})
      runs.push_back(measure_run(model, map));
  }
  return true;
}

void print_runs(const std::vector<Run>& runs, bool json)
{
  if(json) {
    std::cout << "[\n";
    for(std::size_t i = 0; i < runs.size(); ++i)
      print_json_run(runs[i], i + 1 == runs.size());
    std::cout << "]\n";
    return;
  }
  print_markdown_header();
  for(const Run& r : runs)
    print_markdown_row(r);
}

} // namespace

int main(int argc, char** argv)
{
  check_classifier_on_hand_made_quads();
  bool json = false, measure = false;
  std::vector<std::string> files;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--json")
      json = true;
    else if(arg == "--measure")
      measure = true;
    else if(!arg.empty() && arg[0] == '-') {
      std::cerr << "quality: unknown option '" << arg << "'\n" << usage << std::endl;
      return 2;
    } else
      files.push_back(arg);
  }
  if(files.empty() || (measure && files.size() != 2)) {
    std::cerr << usage << std::endl;
    return 2;
  }
  std::vector<Run> runs;
  if(measure) {
    Model model;
    if(!read_model(files[0], model))
      return 2;
    runs.push_back(measure_file(model, files[1]));
  } else if(!measure_meshes(files, runs))
    return 2;
  print_runs(runs, json);
  return 0;
}
