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
//  * doublets: vertices inside the surface of valence 2 (two faces sharing two edges);
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
#include <CGAL/Range_space_remeshing/smooth_vertex_normals.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include "benchmark_support.h"
#include "output_measures.h"

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
using namespace output_measures;

namespace {

// ---------------------------------------------------------------------------------
// The runs

constexpr double normal_weight = 0.1;      // bounding-box diagonals per unit of normal: the program's default
constexpr std::size_t normal_smoothing = 8; // rounds of averaging the normals: the program's default
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
      .refine_around_defects(true)
      .quad_collapse(true)
      .dual_placement(RSR::Dual_placement::QEM)
      .number_of_relaxation_steps(3);
}

/// Remeshes `model` with `map` ("identity" or "position-normal") into `output`; the
/// position-normal map reads a table of vertex normals computed in one pass and
/// averaged, as the program's complete scan does, and that work is part of the run.
void remesh_with_map(const Model& model, const std::string& map, std::size_t target, Mesh& output)
{
  if(map == "identity") {
    RSR::remesh(model.mesh, output, program_parameters(model, target));
    return;
  }
  auto normals = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), model.mesh);
  RSR::compute_vertex_normals(model.mesh, normals);
  RSR::smooth_vertex_normals(model.mesh, normals, RSR::parameters::number_of_iterations(normal_smoothing));
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
               "doublets | input topology | topology of the output | ms |\n"
               "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|---:|\n";
}

void print_markdown_row(const Run& r)
{
  const Shape& s = r.shape;
  std::cout << "| " << r.model << " | " << r.map << " | " << r.input_vertices << " | "
            << (r.target > 0 ? std::to_string(r.target) : "–") << " | ";
  if(!r.error.empty()) {
    std::cout << "no output: " << r.error << " | | | | | | | | " << describe(r.input_topology) << " | | "
              << fixed(r.ms, 0) << " |\n";
    return;
  }
  std::cout << r.output_vertices
            << (r.target > 0 ? " (" + fixed(percent(r.output_vertices, r.target) - 100, 1) + " %)" : "") << " | "
            << fixed(percent(s.interior_valence_4, s.interior_vertices), 1) << " % | "
            << (s.border_vertices > 0 ? fixed(percent(s.border_valence_3, s.border_vertices), 1) + " %" : "–")
            << " | " << s.bad_quads << " (" << fixed(percent(s.bad_quads, s.quads), 2) << " %) | "
            << fixed(s.angle_p1, 1) << "° | " << fixed(s.angle_min, 1) << "° | " << s.non_quads << " | "
            << s.interior_valence_2 << " | " << describe(r.input_topology) << " | "
            << topology_change(r.input_topology, r.output_topology) << " | "
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
            << ", \"doublets\": " << s.interior_valence_2
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
