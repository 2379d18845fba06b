// Benchmark of the primal contouring (map + tracing + faces + output), identity map,
// single thread. For each mesh, the cell size is chosen so that the output has
// about 25 % of the input's vertex count; then the median of repeated runs after a
// warm-up is reported, for the complete scan and the seeded traversal.
//
//   contour_benchmark [--runs N] MESH.off...
//
// Prints a Markdown table on stdout.

#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/dualize.h>
#include <CGAL/Range_space_remeshing/primal_remesh.h>
#include <CGAL/Range_space_remeshing/quad_collapse.h>
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>

#include "benchmark_support.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;
using namespace benchmark_support;

namespace {

struct Measure
{
  double median_total = 0, median_wall = 0;
  RSR::Statistics stats; // of the median run
};

RSR::Statistics run_once(const Mesh& input, double h, RSR::Seeding_method seeding, double& wall_ms,
                         bool check_topology = false)
{
  Mesh output;
  const auto start = std::chrono::steady_clock::now();
  const auto stats = RSR::primal_remesh(
      input, output,
      RSR::parameters::check_topology(check_topology).grid_spacing(h).seeding_method(seeding));
  wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

Measure measure(const Mesh& input, double h, RSR::Seeding_method seeding, int runs, bool check_topology = false)
{
  double wall;
  run_once(input, h, seeding, wall, check_topology); // warm-up
  std::vector<std::pair<double, RSR::Statistics>> results;
  std::vector<double> walls;
  for(int r = 0; r < runs; ++r) {
    const auto stats = run_once(input, h, seeding, wall, check_topology);
    results.emplace_back(stats.time_total_ms, stats);
    walls.push_back(wall);
  }
  std::sort(results.begin(), results.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::sort(walls.begin(), walls.end());
  Measure m;
  m.median_total = results[results.size() / 2].first;
  m.stats = results[results.size() / 2].second;
  m.median_wall = walls[walls.size() / 2];
  return m;
}

/// Cell size giving about `target` output vertices (within 3 %), complete scan.
double identity_cell_size_for(const Mesh& input, std::size_t target)
{
  return benchmark_support::cell_size_for(
      [&](double h) {
        double wall;
        return run_once(input, h, RSR::Seeding_method::COMPLETE_SCAN, wall).output_vertices;
      },
      0.01 * bbox_diagonal(input), target);
}

/// The cost of the topology check (complete scan): median contouring time without
/// and with it, and the check's own time in the median run with it.
void measure_topology_check(const std::string& name, const Mesh& input, double h, int runs)
{
  const Measure plain = measure(input, h, RSR::Seeding_method::COMPLETE_SCAN, runs);
  const Measure checked = measure(input, h, RSR::Seeding_method::COMPLETE_SCAN, runs, true);
  const auto& s = checked.stats;
  char line[512];
  std::snprintf(line, sizeof(line), "| %s | %.5g | %zu | %.2f | %.2f | %.2f | %.1f %% | %s | %zu | %zu | %zu |",
                name.c_str(), h, s.output_vertices, plain.median_total, checked.median_total, s.time_topology_ms,
                100. * s.time_topology_ms / plain.median_total, s.topology_preserved() ? "yes" : "no",
                s.harmless_loops, s.closed_loops, s.non_disk_cells);
  std::cout << line << std::endl;
}

/// RMS and maximum of the distances from points sampled on `from` to `to`.
std::pair<double, double> sampled_distance(const Mesh& from, const Mesh& to, std::size_t samples)
{
  Mesh a = from, b = to;
  triangulate_all_faces(a);
  triangulate_all_faces(b);
  return rms_and_max_distance(a, b, samples);
}

double valence_4_percent(const Mesh& m)
{
  std::size_t valence_4 = 0;
  for(auto v : vertices(m))
    valence_4 += (degree(v, m) == 4);
  return 100. * double(valence_4) / double(num_vertices(m));
}

/// The stages after the contouring, on the primal at cell size h: median times of
/// dualize(), collapse_quads() and one relaxation iteration, and the quality of the
/// result (dual + collapse + 3 relaxation iterations).
void measure_dual(const std::string& name, const Mesh& input, double h, int runs, double contour_ms)
{
  Mesh primal;
  auto normals = primal.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  RSR::primal_remesh(input, primal, CGAL::parameters::grid_spacing(h),
                     CGAL::parameters::vertex_normal_map(normals));
  std::vector<double> dual_ms, collapse_ms, relax_ms;
  Mesh quads;
  RSR::Dual_statistics dual_stats;
  RSR::Collapse_statistics collapse_stats;
  double dual_valence_4 = 0;
  for(int r = 0; r <= runs; ++r) {
    Mesh q;
    auto planes = q.add_property_map<Mesh::Vertex_index, RSR::Tangent_planes>("v:planes").first;
    auto qn = q.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
    dual_stats = RSR::dualize(primal, q, RSR::parameters::dual_placement(RSR::Dual_placement::QEM).vertex_normal_map(normals),
                              RSR::parameters::vertex_tangent_planes_map(planes).vertex_normal_map(qn));
    dual_valence_4 = valence_4_percent(q);
    collapse_stats = RSR::collapse_quads(
        q, RSR::parameters::vertex_tangent_planes_map(planes).vertex_normal_map(qn));
    const double relax = RSR::relax_on_tangent_planes(q, RSR::parameters::vertex_tangent_planes_map(planes).number_of_relaxation_steps(1).vertex_normal_map(qn));
    if(r > 0) { // the first run is the warm-up
      dual_ms.push_back(dual_stats.time_ms);
      collapse_ms.push_back(collapse_stats.time_ms);
      relax_ms.push_back(relax);
    }
    if(r == runs) {
      RSR::relax_on_tangent_planes(q, RSR::parameters::vertex_tangent_planes_map(planes).number_of_relaxation_steps(2).vertex_normal_map(qn));
      quads = q; // 3 iterations in all
    }
  }
  const double diagonal = bbox_diagonal(input);
  const auto forward = sampled_distance(quads, input, 200000);
  const auto backward = sampled_distance(input, quads, 200000);
  const double pipeline = median(dual_ms) + median(collapse_ms) + 3 * median(relax_ms);
  char line[512];
  std::snprintf(line, sizeof(line),
                "| %s | %zu | %zu | %.2f | %zu | %.2f | %.2f | %.2f | %.0f %% | %.1f %% | %.1f %% | %.3g | %.3g |",
                name.c_str(), num_faces(quads), dual_stats.non_quads, median(dual_ms),
                collapse_stats.collapsed_quads, median(collapse_ms), median(relax_ms), pipeline,
                100 * pipeline / contour_ms, dual_valence_4, valence_4_percent(quads),
                forward.first / diagonal, std::max(forward.second, backward.second) / diagonal);
  std::cout << line << std::endl;
}

/// The cost of the dimension: primal contouring under the identity (D = 3), position +
/// normal (D = 6, normal weight 0.5 diagonals) and position + normal + colour (D = 9,
/// colours generated from the position: three bands per axis), each at about `target`
/// output vertices; median time per output vertex and per output face (the issue's
/// measure: a higher D gives fewer faces for as many vertices).
void measure_dimensions(const std::string& name, Mesh input, std::size_t target, int runs)
{
  const double diagonal = bbox_diagonal(input);
  auto colors = input.add_property_map<Mesh::Vertex_index, std::array<double, 3>>("v:rgb").first;
  for(auto v : vertices(input)) {
    const auto& p = input.point(v);
    colors[v] = {{0.5 + 0.5 * std::sin(6 * M_PI * p.x() / diagonal), 0.5 + 0.5 * std::sin(6 * M_PI * p.y() / diagonal),
                  0.5 + 0.5 * std::sin(6 * M_PI * p.z() / diagonal)}};
  }
  // the complete scan maps every vertex: normals in one pass over the faces, timed with the run
  auto normals = input.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  const RSR::Position_normal_range_map f6(input.points(), normals, 1.0, 0.5 * diagonal);
  const RSR::Position_normal_color_range_map f9(input.points(), normals, colors, 1.0, 0.5 * diagonal, 0.2 * diagonal);
  // returns the total; `normals_ms` receives the part spent on the input's normals
  auto timed = [&](double h, int d, std::size_t& vertices, std::size_t& faces, double& normals_ms) {
    Mesh output;
    const auto start = std::chrono::steady_clock::now();
    if(d > 3)
      RSR::compute_vertex_normals(input, normals);
    normals_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const auto stats =
        d == 9   ? RSR::primal_remesh(input, output, RSR::parameters::range_map(f9).grid_spacing(h))
        : d == 6 ? RSR::primal_remesh(input, output, RSR::parameters::range_map(f6).grid_spacing(h))
                 : RSR::primal_remesh(input, output, CGAL::parameters::grid_spacing(h));
    vertices = stats.output_vertices;
    faces = stats.output_faces;
    return normals_ms + stats.time_total_ms;
  };
  // The three dimensions are timed in rounds, one run of each per round, so that a
  // ratio compares runs made milliseconds apart. The benchmark machine's speed drifts:
  // the median of the same series measured a few minutes apart differed by up to 1.7x,
  // which three series one after the other would report as a cost of the dimension.
  // One dimension's runs, and per round its cost per output vertex and per output face
  // over D = 3's, with and without the pass that computes the input's normals.
  struct Series
  {
    int dimension;
    double cell_size = 0;
    std::size_t vertices = 0, faces = 0;
    std::vector<double> times, normal_times, vertex_ratio, vertex_ratio_without_normals, face_ratio,
        face_ratio_without_normals;
  };
  std::array<Series, 3> series = {{{3}, {6}, {9}}};
  double normals_ms = 0;
  for(Series& s : series) {
    s.cell_size = benchmark_support::cell_size_for(
        [&](double h) {
          timed(h, s.dimension, s.vertices, s.faces, normals_ms);
          return s.vertices;
        },
        0.01 * diagonal, target);
    timed(s.cell_size, s.dimension, s.vertices, s.faces, normals_ms); // warm-up
  }
  struct Costs
  {
    double per_vertex, per_vertex_without_normals, per_face, per_face_without_normals;
  };
  for(int r = 0; r < runs; ++r) {
    std::array<Costs, 3> costs;
    for(int k = 0; k < 3; ++k) {
      Series& s = series[k];
      const double ms = timed(s.cell_size, s.dimension, s.vertices, s.faces, normals_ms);
      s.times.push_back(ms);
      s.normal_times.push_back(normals_ms);
      costs[k] = {ms / double(s.vertices), (ms - normals_ms) / double(s.vertices), ms / double(s.faces),
                  (ms - normals_ms) / double(s.faces)};
    }
    for(int k = 0; k < 3; ++k) {
      Series& s = series[k];
      s.vertex_ratio.push_back(costs[k].per_vertex / costs[0].per_vertex);
      s.vertex_ratio_without_normals.push_back(costs[k].per_vertex_without_normals /
                                               costs[0].per_vertex_without_normals);
      s.face_ratio.push_back(costs[k].per_face / costs[0].per_face);
      s.face_ratio_without_normals.push_back(costs[k].per_face_without_normals / costs[0].per_face_without_normals);
    }
  }
  for(const Series& s : series) {
    const double ms = median(s.times);
    char line[256];
    std::snprintf(line, sizeof(line), "| %s | %d | %zu | %zu | %.2f | %.2f | %.0f | %.2f | %.2f | %.2f | %.2f |",
                  name.c_str(), s.dimension, s.vertices, s.faces, ms, median(s.normal_times),
                  1e6 * ms / double(s.vertices), median(s.vertex_ratio), median(s.vertex_ratio_without_normals),
                  median(s.face_ratio), median(s.face_ratio_without_normals));
    std::cout << line << std::endl;
  }
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 15;
  std::vector<std::string> files;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--runs" && a + 1 < argc)
      runs = std::max(5, std::atoi(argv[++a]));
    else
      files.push_back(arg);
  }
  if(files.empty()) {
    std::cerr << "usage: contour_benchmark [--runs N] MESH.off..." << std::endl;
    return 2;
  }

  std::cout << "Primal contouring alone, identity map, cell size for about 25 % of the input's vertices, "
               "complete scan and seeded traversal:\n\n";
  std::cout << "| mesh | triangles | vertices | mode | cell size | output vertices | output faces "
               "| mapped vertices | visited faces | tracing steps | seeding ms | tracing ms | faces ms | output ms | total ms "
               "(median of " << runs << ") |\n"
            << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<std::tuple<std::string, Mesh, double, double>> duals;
  for(const std::string& file : files) {
    Mesh input;
    if(!CGAL::IO::read_polygon_mesh(file, input) || num_faces(input) == 0) {
      std::cerr << "cannot read " << file << std::endl;
      return 2;
    }
    const double h = identity_cell_size_for(input, num_vertices(input) / 4);
    std::string name = file.substr(file.find_last_of('/') + 1);
    for(auto seeding : {RSR::Seeding_method::COMPLETE_SCAN, RSR::Seeding_method::SEEDED}) {
      const Measure m = measure(input, h, seeding, runs);
      const auto& s = m.stats;
      char line[512];
      std::snprintf(line, sizeof(line),
                    "| %s | %zu | %zu | %s | %.5g | %zu | %zu | %zu | %zu | %zu | %.2f | %.2f | %.2f | %.2f | **%.2f** |",
                    name.c_str(), num_faces(input), num_vertices(input),
                    seeding == RSR::Seeding_method::SEEDED ? "seeded" : "complete", h,
                    s.output_vertices, s.output_faces, s.mapped_vertices, s.visited_faces,
                    s.tracing_steps, s.time_seeding_ms,
                    s.time_tracing_ms, s.time_faces_ms, s.time_output_ms, m.median_total);
      std::cout << line << std::endl;
      if(seeding == RSR::Seeding_method::COMPLETE_SCAN)
        duals.emplace_back(name, input, h, m.median_total);
    }
  }
  std::cout << "\nDual (QEM placement), quad collapse and relaxation on the same primal remeshes; "
               "distances after scaling to unit bounding-box diagonal, RMS from the quads to the "
               "input, Hausdorff two-sided (200,000 samples each way), of the final quads:\n\n"
            << "| mesh | quads | non-quads | dual ms | collapses | collapse ms | 1 relaxation ms "
               "| dual + collapse + 3 relaxations ms | vs contouring | valence 4 (dual) "
               "| valence 4 (final) | RMS | Hausdorff |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const auto& [name, input, h, contour_ms] : duals)
    measure_dual(name, input, h, runs, contour_ms);
  std::cout << "\nThe cost of the topology check (`check_topology(true)`, complete scan, same cell sizes; "
               "check ms: its own time in the median run, share: of the contouring without it):\n\n"
            << "| mesh | cell size | output vertices | contouring ms | with the check ms | check ms | share "
               "| topology preserved | harmless loops | closed loops | non-disk cells |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n";
  for(const auto& [name, input, h, contour_ms] : duals)
    measure_topology_check(name, input, h, runs);
  std::cout << "\nThe cost of the dimension D (complete scan, same output size; D = 6: position and "
               "normal, normal weight 0.5 bounding-box diagonals; D = 9: and colours generated from the "
               "position, colour weight 0.2 diagonals; at D = 6 and 9 the total includes the input's vertex "
               "normals, computed in one pass over the faces by `compute_vertex_normals()`):\n\n"
            << "| mesh | D | output vertices | output faces | total ms | of which normals ms | ns per output vertex "
               "| per output vertex, / D = 3 (median of the rounds' ratios) | the same, normals given "
               "(as the colours are) | per output face, / D = 3 | the same, normals given |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const auto& [name, input, h, contour_ms] : duals)
    measure_dimensions(name, input, num_vertices(input) / 4, runs);
  return 0;
}
