// The paper's Table 1 on this machine, side by side with the remeshers a CGAL user
// would otherwise reach for, in one run:
//
//  1. for every mesh and n = 3 (identity), 6 (position + normal) and 9 (position +
//     normal + colour, colours generated on the input): the whole pipeline (primal,
//     dual with QEM placement, quad collapse, 3 relaxation steps) at a cell size
//     giving about 25 % of the input's vertex count; ms per stage (median run of N
//     after a warm-up), distances to the input, valence, angles;
//  2. at the vertex count of the n = 6 result (within 3 %): our primal contouring
//     (n = 3), CGAL's isotropic remeshing (3 iterations) and Garland–Heckbert edge
//     collapse, with the speed-up of the whole pipeline over each;
//  3. scaling: the first mesh Loop-subdivided 1x, 2x, 3x, remeshed at a fixed cell
//     size by the complete scan and by the seeded traversal;
//  4. interactive use: a mesh under a time-varying twist, remeshed every frame by the
//     whole pipeline.
//
//   table1 [--runs N] [--peer-runs N] [--no-peers] [--scaling MESH] [--deforming MESH] MESH...
//
// Times are of the algorithms only (no IO, no copies). Distances are METRO-style,
// after scaling to unit bounding-box diagonal: points sampled on each mesh, the
// distance to the other one; RMS is the larger of the two one-sided RMS values,
// Hausdorff the larger of the two maxima; polygons are triangulated first (see
// triangulate_all_faces()). Prints Markdown on stdout.

#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/smooth_vertex_normals.h>
#include <CGAL/Range_space_remeshing/copy_in_spatial_order.h>
#include <CGAL/Range_space_remeshing/primal_remesh.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include "benchmark_support.h"
#include "output_measures.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cstdarg>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMS = CGAL::Surface_mesh_simplification;
using namespace benchmark_support;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* pattern, ...)
{
  char line[1024];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(line, sizeof(line), pattern, args);
  va_end(args);
  return line;
}

// ---------------------------------------------------------------------------------
// Quality

struct Quality
{
  double rms = NAN, hausdorff = NAN; // relative to the input's bounding-box diagonal
  double regular_percent = NAN;      // valence 4 for quads, 6 for triangle meshes
  double min_angle = NAN;            // smallest corner angle of any face, degrees
  output_measures::Shape shape;      // folded faces, non-quads, corner-angle percentile
  std::string topology;              // "kept", or what changed
};

double min_corner_angle(const Mesh& m)
{
  double smallest = 180;
  for(auto h : halfedges(m)) {
    if(is_border(h, m))
      continue;
    const K::Point_3& corner = m.point(target(h, m));
    const K::Vector_3 a = m.point(source(h, m)) - corner, b = m.point(target(next(h, m), m)) - corner;
    const double norms = std::sqrt(a.squared_length() * b.squared_length());
    if(norms > 0)
      smallest = std::min(smallest, std::acos(std::clamp(a * b / norms, -1., 1.)) * 180 / M_PI);
  }
  return smallest;
}

Quality quality(const Mesh& output, const Mesh& input, double diagonal, std::size_t regular_valence)
{
  Quality q;
  if(num_faces(output) == 0)
    return q;
  std::size_t regular = 0;
  for(auto v : vertices(output))
    regular += (degree(v, output) == regular_valence);
  q.regular_percent = 100. * double(regular) / double(num_vertices(output));
  q.min_angle = min_corner_angle(output);
  q.shape = output_measures::shape_of(output);
  q.topology = output_measures::topology_change(output_measures::topology_of(input), output_measures::topology_of(output));
  Mesh triangles = output;
  triangulate_all_faces(triangles);
  const auto forward = rms_and_max_distance(triangles, input, 200000);
  const auto backward = rms_and_max_distance(input, triangles, 200000);
  q.rms = std::max(forward.first, backward.first) / diagonal;
  q.hausdorff = std::max(forward.second, backward.second) / diagonal;
  return q;
}

/// Folded or non-convex quads (folded triangles in a triangle mesh), non-quads, the
/// 1st percentile of the corner angles, the topology against the input's.
std::string shape_columns(const Quality& q)
{
  const auto& s = q.shape;
  const bool quads = s.quads > 0;
  const std::size_t bad = quads ? s.bad_quads : s.folded_triangles, of = quads ? s.quads : s.triangles;
  return format("%zu (%.2f %%) | %s | %.1f° | %s", bad, of > 0 ? 100. * double(bad) / double(of) : 0.,
                quads ? std::to_string(s.non_quads).c_str() : "–", s.angle_p1, q.topology.c_str());
}

std::string quality_columns(const Quality& q)
{
  if(std::isnan(q.rms)) // an empty output
    return format("– | – | %.1f %% | %.1f° | – | – | – | –", q.regular_percent, q.min_angle);
  return format("%.3g | %.3g | %.1f %% | %.1f° | ", q.rms, q.hausdorff, q.regular_percent, q.min_angle) +
         shape_columns(q);
}

/// The header cells of quality_columns().
const char* const quality_header = "RMS | Hausdorff | regular vertices | min angle | folded or non-convex | "
                                   "non-quads | 1st-pct angle | topology |";
const char* const quality_rule = "---:|---:|---:|---:|---:|---:|---:|---|";

/// One face per connected component: the seeds a caller computes once and passes to
/// every frame's seeded traversal.
std::vector<Mesh::Face_index> one_face_per_component(const Mesh& mesh)
{
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t components = PMP::connected_components(mesh, component);
  std::vector<Mesh::Face_index> seeds(components, Mesh::null_face());
  for(auto f : faces(mesh))
    if(seeds[get(component, f)] == Mesh::null_face())
      seeds[get(component, f)] = f;
  return seeds;
}

// ---------------------------------------------------------------------------------
// Our pipeline

/// A remeshing job at cell size h: fills `output`, returns its statistics.
using Pipeline = std::function<RSR::Remesh_statistics(double h, Mesh& output)>;

struct Pipeline_result
{
  double h = 0;
  RSR::Remesh_statistics stats; // of the run with the median total time
  double best_total_ms = 0;     // the fastest run: this machine is noisy
  Mesh output;
};

Pipeline_result time_pipeline(const Pipeline& pipeline, double h, int runs)
{
  Pipeline_result result;
  result.h = h;
  pipeline(h, result.output); // warm-up
  std::vector<RSR::Remesh_statistics> all;
  for(int r = 0; r < runs; ++r) {
    Mesh output;
    all.push_back(pipeline(h, output));
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.time_total_ms < b.time_total_ms; });
  result.stats = all[all.size() / 2];
  result.best_total_ms = all.front().time_total_ms;
  return result;
}

/// Colours for the n = 9 rows: smooth bands, three per bounding-box diagonal along
/// each axis, so that the colour varies everywhere (there is no coloured mesh among
/// CGAL's samples).
Mesh::Property_map<Mesh::Vertex_index, std::array<double, 3>> generate_colors(Mesh& m, double diagonal)
{
  auto colors = m.add_property_map<Mesh::Vertex_index, std::array<double, 3>>("v:rgb").first;
  for(auto v : vertices(m)) {
    const auto& p = m.point(v);
    colors[v] = {{0.5 + 0.5 * std::sin(6 * M_PI * p.x() / diagonal), 0.5 + 0.5 * std::sin(6 * M_PI * p.y() / diagonal),
                  0.5 + 0.5 * std::sin(6 * M_PI * p.z() / diagonal)}};
  }
  return colors;
}

constexpr double normal_weight = 0.1; // bounding-box diagonals per unit of normal (the CLI's default)
constexpr std::size_t normal_smoothing = 8; // rounds of averaging the normals (the CLI's default)
constexpr double color_weight = 0.1;  // bounding-box diagonals per unit of colour

// ---------------------------------------------------------------------------------
// Peers

double isotropic_remeshing_ms(const Mesh& input, double edge_length, Mesh& output)
{
  output = input;
  const auto start = Clock::now();
  PMP::isotropic_remeshing(faces(output), edge_length, output, CGAL::parameters::number_of_iterations(3));
  const double ms = ms_since(start);
  output.collect_garbage();
  return ms;
}

double garland_heckbert_ms(const Mesh& input, std::size_t target_vertices, Mesh& output)
{
  output = input;
  const auto start = Clock::now();
  // a collapse removes one vertex and three edges (two on a border): stop at the edge
  // count of the target vertex count
  const std::size_t removed = num_vertices(input) > target_vertices ? num_vertices(input) - target_vertices : 0;
  const std::size_t edges_left = num_edges(input) > 3 * removed ? num_edges(input) - 3 * removed : 1;
  SMS::Count_stop_predicate<Mesh> stop(edges_left);
  SMS::GarlandHeckbert_plane_policies<Mesh, K> policies(output);
  SMS::edge_collapse(output, stop,
                     CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  const double ms = ms_since(start);
  output.collect_garbage();
  return ms;
}

struct Peer_row
{
  std::string method;
  std::size_t vertices = 0;
  double ms = 0, best_ms = 0;
  Quality q;
};

std::vector<Peer_row> run_peers(const Mesh& input, std::size_t target, int runs, double diagonal)
{
  std::vector<Peer_row> rows;
  { // isotropic remeshing: edge length for `target` vertices, ~2 equilateral triangles per vertex
    Mesh output;
    double length = std::sqrt(2 * PMP::area(input) / (std::sqrt(3.) * double(target)));
    length = cell_size_for(
        [&](double l) {
          isotropic_remeshing_ms(input, l, output);
          return num_vertices(output);
        },
        length, target);
    std::vector<double> times;
    for(int r = 0; r < runs; ++r)
      times.push_back(isotropic_remeshing_ms(input, length, output));
    rows.push_back({"CGAL isotropic_remeshing, 3 iterations", num_vertices(output), median(times),
                    *std::min_element(times.begin(), times.end()),
                    quality(output, input, diagonal, 6)});
  }
  { // Garland–Heckbert: the target is reached by construction
    Mesh output;
    garland_heckbert_ms(input, target, output); // warm-up
    std::vector<double> times;
    for(int r = 0; r < runs; ++r)
      times.push_back(garland_heckbert_ms(input, target, output));
    rows.push_back({"CGAL edge_collapse, Garland–Heckbert plane quadrics", num_vertices(output), median(times),
                    *std::min_element(times.begin(), times.end()),
                    quality(output, input, diagonal, 6)});
  }
  return rows;
}

// ---------------------------------------------------------------------------------
// Tables

struct Model
{
  std::string name;
  Mesh mesh;
  double diagonal = 0;
};

/// Table 1: returns, per model, the n = 6 result (for the peers).
std::vector<Pipeline_result> table_pipeline(std::vector<Model>& models, int runs, std::vector<double>& identity_h)
{
  std::cout << "## Whole pipeline\n\n"
               "Primal contouring, dual (QEM placement), quad collapse, 3 relaxation steps; cell size for about 25 % "
               "of the input's vertices; median of "
            << runs
            << " runs after a warm-up (stage times of the median run; best: the fastest run, as timings on this "
               "shared machine drift by up to 2x from minute to minute). n = 6: position and normal (normal weight 0.1 bounding-box diagonals); "
               "n = 9: and colour (colour weight 0.1 diagonals, colours generated on the input). At n = 6 and 9 the "
               "contour time includes the input's vertex normals (`compute_vertex_normals()`, one pass over the "
               "faces, then 8 rounds of `smooth_vertex_normals()`, the program's default, run every time).\n\n"
               "| model | n | input triangles | cell size (diagonals) | primal vertices | output quads | contour ms | "
               "dual ms | collapse ms | relax ms | **total ms** | best ms | "
            << quality_header << "\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" << quality_rule
            << "\n";
  std::vector<Pipeline_result> six;
  for(Model& model : models) {
    Mesh& input = model.mesh;
    auto colors = generate_colors(input, model.diagonal);
    // the complete scan maps every vertex: normals in one pass over the faces, not lazily,
    // given to the remesher too (the output's normals are interpolated from them)
    auto normals = input.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
    const RSR::Position_normal_range_map f6(input.points(), normals, 1.0, normal_weight * model.diagonal);
    const RSR::Position_normal_color_range_map f9(input.points(), normals, colors, 1.0,
                                                  normal_weight * model.diagonal, color_weight * model.diagonal);
    for(int n : {3, 6, 9}) {
      const Pipeline pipeline = [&, n](double h, Mesh& output) {
        if(n == 3)
          return RSR::remesh(input, output, CGAL::parameters::grid_spacing(h));
        const auto start = Clock::now();
        RSR::compute_vertex_normals(input, normals);
        RSR::smooth_vertex_normals(input, normals, CGAL::parameters::number_of_iterations(normal_smoothing));
        const double normals_ms = ms_since(start);
        RSR::Remesh_statistics s =
            n == 6
                ? RSR::remesh(input, output, RSR::parameters::range_map(f6).grid_spacing(h).vertex_normal_map(normals))
                : RSR::remesh(input, output, RSR::parameters::range_map(f9).grid_spacing(h).vertex_normal_map(normals));
        s.primal.time_total_ms += normals_ms; // part of mapping the input
        s.time_total_ms += normals_ms;
        return s;
      };
      const double h = cell_size_for(
          [&](double h) {
            Mesh output;
            pipeline(h, output);
            return num_vertices(output);
          },
          0.01 * model.diagonal, num_vertices(input) / 4);
      Pipeline_result r = time_pipeline(pipeline, h, runs);
      const auto& s = r.stats;
      std::cout << format("| %s | %d | %zu | %.4f | %zu | %zu | %.2f | %.2f | %.2f | %.2f | **%.2f** | %.2f | ",
                          model.name.c_str(), n, num_faces(input), h / model.diagonal, s.primal.output_vertices,
                          num_faces(r.output), s.primal.time_total_ms, s.dual.time_ms, s.collapse.time_ms,
                          s.time_relaxation_ms, s.time_total_ms, r.best_total_ms)
                << quality_columns(quality(r.output, input, model.diagonal, 4)) << " |" << std::endl;
      if(n == 3)
        identity_h.push_back(h);
      if(n == 6)
        six.push_back(std::move(r));
    }
    input.remove_property_map(colors);
    input.remove_property_map(normals);
  }
  return six;
}

void table_peers(const std::vector<Model>& models, const std::vector<Pipeline_result>& six, int runs,
                 int peer_runs)
{
  std::cout << "\n## Against the peers, at the same output vertex count\n\n"
               "Ours: the whole pipeline at n = 6 from the table above, and the primal contouring alone (n = 3) at "
               "the cell size giving the same vertex count. Peers: median of "
            << peer_runs
            << " runs after a warm-up, one thread. Speed-up: the peer's median time over our whole pipeline's "
               "(best: the fastest run, a steadier figure on this shared machine). Regular "
               "vertices: valence 4 in quad meshes, 6 in triangle meshes. Distances of polygon meshes: of "
               "their triangulation by PMP (quads split along a diagonal, larger faces filled as holes in 3-D), "
               "where a face it cannot triangulate (a non-planar polygon whose projection crosses itself: a few "
               "primal polygons, and faces the dual joins) is a fan from one corner. Folded or non-convex: "
               "quads by the corner criterion of issue 39 (`output_measures.h`), triangles whose normal is "
               "against the sum of their edge neighbours'; the % is of the quads (triangles); 1st-pct angle: "
               "the 1st percentile of the quads' (triangles') corner angles; topology: Euler characteristic, "
               "components and border cycles against the input's.\n\n"
               "| model | method | output vertices | ms | best ms | speed-up | "
            << quality_header << "\n|---|---|---:|---:|---:|---:|" << quality_rule << "\n";
  for(std::size_t i = 0; i < models.size(); ++i) {
    const Model& model = models[i];
    const Mesh& input = model.mesh;
    const std::size_t target = num_vertices(six[i].output);
    const double ours = six[i].stats.time_total_ms;
    std::cout << format("| %s | ours: whole pipeline, n = 6 | %zu | **%.2f** | %.2f | 1 | ", model.name.c_str(), target,
                        ours, six[i].best_total_ms)
              << quality_columns(quality(six[i].output, input, model.diagonal, 4)) << " |" << std::endl;

    const Pipeline primal_only = [&](double h, Mesh& output) {
      RSR::Remesh_statistics s;
      s.primal = RSR::primal_remesh(input, output, CGAL::parameters::grid_spacing(h));
      s.time_total_ms = s.primal.time_total_ms;
      return s;
    };
    const double h = cell_size_for(
        [&](double h) {
          Mesh output;
          return primal_only(h, output).primal.output_vertices;
        },
        six[i].h, target);
    const Pipeline_result primal = time_pipeline(primal_only, h, runs);
    std::cout << format("| %s | ours: primal contouring only, n = 3 | %zu | **%.2f** | %.2f | %.1f | ",
                        model.name.c_str(), num_vertices(primal.output), primal.stats.time_total_ms,
                        primal.best_total_ms, ours / primal.stats.time_total_ms)
              << quality_columns(quality(primal.output, input, model.diagonal, 4)) << " |" << std::endl;

    for(const Peer_row& row : run_peers(input, target, peer_runs, model.diagonal))
      std::cout << format("| %s | %s | %zu | %.0f | %.0f | **%.0f×** | ", model.name.c_str(), row.method.c_str(),
                          row.vertices, row.ms, row.best_ms, row.ms / ours)
                << quality_columns(row.q) << " |" << std::endl;
  }
}

#if defined(CGAL_LINKED_WITH_TBB)
/// Whether two meshes are the same, vertex numbering and positions included.
bool identical(const Mesh& a, const Mesh& b)
{
  if(num_vertices(a) != num_vertices(b) || num_faces(a) != num_faces(b))
    return false;
  for(auto v : vertices(a))
    if(a.point(v) != b.point(v))
      return false;
  for(auto f : faces(a)) {
    auto ha = halfedge(f, a), hb = halfedge(f, b);
    for(std::size_t c = 0; c < degree(f, a); ++c, ha = next(ha, a), hb = next(hb, b))
      if(target(ha, a) != target(hb, b))
        return false;
  }
  return true;
}

void table_parallel(const std::vector<Model>& models, const std::vector<double>& identity_h, int runs)
{
  std::cout << "\n## Parallel complete scan\n\n"
               "`primal_remesh<CGAL::Parallel_tag>()` (TBB, all "
            << std::thread::hardware_concurrency()
            << " threads of this machine) against the sequential one, identity map, at the cell size of the n = 3 "
               "row above: the vertices are mapped, the faces recorded and the exact tests run on all threads, the "
               "tracing stays sequential. Median of "
            << runs << " runs of each, interleaved.\n\n"
               "| model | output vertices | sequential ms | sequential scan ms | parallel ms | parallel scan ms | "
               "speed-up | same output |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
  for(std::size_t i = 0; i < models.size(); ++i) {
    const Mesh& input = models[i].mesh;
    const auto np = CGAL::parameters::grid_spacing(identity_h[i]);
    std::vector<double> sequential, sequential_scan, parallel, parallel_scan;
    Mesh a, b;
    RSR::primal_remesh<CGAL::Sequential_tag>(input, a, np); // warm-up, and the outputs compared
    RSR::primal_remesh<CGAL::Parallel_tag>(input, b, np);
    for(int r = 0; r < runs; ++r) {
      Mesh x, y;
      const auto s = RSR::primal_remesh<CGAL::Sequential_tag>(input, x, np);
      const auto p = RSR::primal_remesh<CGAL::Parallel_tag>(input, y, np);
      sequential.push_back(s.time_total_ms);
      sequential_scan.push_back(s.time_seeding_ms);
      parallel.push_back(p.time_total_ms);
      parallel_scan.push_back(p.time_seeding_ms);
    }
    std::cout << format("| %s | %zu | %.2f | %.2f | %.2f | %.2f | %.2f | %s |", models[i].name.c_str(),
                        num_vertices(a), median(sequential), median(sequential_scan), median(parallel),
                        median(parallel_scan), median(sequential) / median(parallel), identical(a, b) ? "yes" : "NO")
              << std::endl;
  }
}
#endif

/// The same jobs on a copy of each input stored in spatial order
/// (`copy_in_spatial_order()`): the contouring at n = 3 and the whole pipeline at n = 6,
/// at the cell sizes of the first table, the two orders interleaved run by run.
void table_input_order(const std::vector<Model>& models, const std::vector<double>& identity_h,
                       const std::vector<Pipeline_result>& six, int runs)
{
  std::cout << "\n## Input order\n\n"
               "The same inputs stored in spatial order: faces along a Hilbert curve through their centroids, "
               "vertices in the order those faces first use them (`copy_in_spatial_order()`; the same surface and "
               "points, made once, its time in the second column). "
               "Primal contouring at n = 3 and whole pipeline at n = 6 at the cell sizes of the first table; "
               "median of "
            << runs
            << " runs of each order, interleaved. The remeshers leave their input's order as it is: the tracing "
               "walks from triangle to neighbouring triangle, and reads their records where the input's numbering "
               "puts them.\n\n"
               "| model | reordering ms (once) | contouring n = 3, file order ms | spatial order ms | speed-up | "
               "pipeline n = 6, file order ms | spatial order ms | speed-up | same counts |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for(std::size_t i = 0; i < models.size(); ++i) {
    const Mesh& file_order = models[i].mesh;
    const auto start = Clock::now();
    Mesh spatial_order;
    RSR::copy_in_spatial_order(file_order, spatial_order);
    const double reordering_ms = ms_since(start);
    Mesh inputs[2] = {file_order, std::move(spatial_order)};
    // the normals as in the first table: computed in each timed run, given to the remesher
    using Normals = Mesh::Property_map<Mesh::Vertex_index, K::Vector_3>;
    const Normals normals[2] = {inputs[0].add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first,
                                inputs[1].add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first};
    std::vector<double> contour[2], pipeline[2];
    std::size_t primal_vertices[2] = {0, 0};
    for(int r = 0; r <= runs; ++r) // run 0: the warm-up
      for(int k = 0; k < 2; ++k) {
        const Mesh& input = inputs[k];
        Mesh primal, quads;
        const auto p = RSR::primal_remesh(input, primal, CGAL::parameters::grid_spacing(identity_h[i]));
        const RSR::Position_normal_range_map f6(input.points(), normals[k], 1.0, normal_weight * models[i].diagonal);
        const auto pipeline_start = Clock::now();
        RSR::compute_vertex_normals(input, normals[k]);
        RSR::smooth_vertex_normals(input, normals[k], CGAL::parameters::number_of_iterations(normal_smoothing));
        RSR::remesh(input, quads,
                    RSR::parameters::range_map(f6).grid_spacing(six[i].h).vertex_normal_map(normals[k]));
        const double pipeline_ms = ms_since(pipeline_start);
        primal_vertices[k] = num_vertices(primal);
        if(r == 0)
          continue;
        contour[k].push_back(p.time_total_ms);
        pipeline[k].push_back(pipeline_ms);
      }
    const double c0 = median(contour[0]), c1 = median(contour[1]), p0 = median(pipeline[0]), p1 = median(pipeline[1]);
    std::cout << format("| %s | %.1f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s |", models[i].name.c_str(),
                        reordering_ms, c0, c1, c0 / c1, p0, p1, p0 / p1,
                        primal_vertices[0] == primal_vertices[1] && num_faces(inputs[0]) == num_faces(inputs[1])
                            ? "yes"
                            : "NO")
              << std::endl;
  }
}

/// Least-squares slope of log(y) against log(x).
double exponent(const std::vector<double>& x, const std::vector<double>& y)
{
  double mx = 0, my = 0;
  for(std::size_t i = 0; i < x.size(); ++i) {
    mx += std::log(x[i]) / double(x.size());
    my += std::log(y[i]) / double(y.size());
  }
  double sxy = 0, sxx = 0;
  for(std::size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += CGAL::square(std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

void table_scaling(const Model& base, int runs)
{
  const double h = 0.01 * base.diagonal;
  std::cout << "\n## Scaling with the input size\n\n"
            << base.name << " Loop-subdivided, primal contouring at a fixed cell size (0.01 bounding-box "
            << "diagonals, identity map), median of " << runs
            << " runs after a warm-up. Complete: the scan of every triangle. Seeded: the traversal from one seed "
               "per component, found by a pass over the connectivity (no map evaluation). Given seeds: the same "
               "traversal from one face per component passed by `seed_faces()` (what a caller remeshing frame "
               "after frame does): only the triangles the arcs cross are visited.\n\n"
               "| subdivisions | input triangles | output vertices | complete ms | seeded ms | given seeds ms | "
               "mapped vertices (complete) | mapped vertices (seeded) | visited triangles (seeded) |\n"
               "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  Mesh mesh = base.mesh;
  std::vector<double> sizes, visited;
  std::array<std::vector<double>, 3> times_of_mode;
  for(int level = 0; level <= 3; ++level) {
    if(level > 0)
      CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
    const std::vector<Mesh::Face_index> seeds = one_face_per_component(mesh);
    std::array<RSR::Statistics, 3> stats;
    for(int mode = 0; mode < 3; ++mode) {
      const auto seeding = mode == 0 ? RSR::Seeding_method::COMPLETE_SCAN : RSR::Seeding_method::SEEDED;
      const auto np = RSR::parameters::grid_spacing(h).seeding_method(seeding);
      std::vector<double> times;
      for(int r = 0; r <= runs; ++r) {
        Mesh output;
        stats[mode] = mode == 2 ? RSR::primal_remesh(mesh, output, np.seed_faces(seeds))
                                : RSR::primal_remesh(mesh, output, np);
        if(r > 0) // the first run is the warm-up
          times.push_back(stats[mode].time_total_ms);
      }
      times_of_mode[mode].push_back(median(times));
    }
    std::cout << format("| %d | %zu | %zu | %.1f | %.1f | %.1f | %zu | %zu | %zu |", level, num_faces(mesh),
                        stats[2].output_vertices, times_of_mode[0].back(), times_of_mode[1].back(),
                        times_of_mode[2].back(), stats[0].mapped_vertices, stats[2].mapped_vertices,
                        stats[2].visited_faces)
              << std::endl;
    sizes.push_back(double(num_faces(mesh)));
    visited.push_back(double(stats[2].visited_faces));
  }
  std::cout << format("\nGrowth exponents e (time or count ∝ input triangles^e, least squares over the four "
                      "sizes): complete scan %.2f, seeded %.2f, given seeds %.2f; triangles the seeded traversal "
                      "visits %.2f (the arcs cross about sqrt(4) = 2 times more triangles per subdivision: 0.5).\n",
                      exponent(sizes, times_of_mode[0]), exponent(sizes, times_of_mode[1]),
                      exponent(sizes, times_of_mode[2]), exponent(sizes, visited));
}

/// The rest shape twisted about the vertical axis: points computed on demand, so that
/// a frame reads only the vertices the remesher needs.
struct Twisted_points
{
  using key_type = Mesh::Vertex_index;
  using value_type = K::Point_3;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const Mesh* rest;
  double angle_per_height, cx, cy;
  friend value_type get(const Twisted_points& f, key_type v)
  {
    const K::Point_3& p = f.rest->point(v);
    const double a = f.angle_per_height * p.z(), c = std::cos(a), s = std::sin(a);
    const double x = p.x() - f.cx, y = p.y() - f.cy;
    return {f.cx + c * x - s * y, f.cy + s * x + c * y, p.z()};
  }
};

void table_deforming(const Model& model)
{
  std::cout << "\n## Interactive use\n\n"
            << model.name
            << " twisting about its vertical axis (up to 1.5 radians over its height), remeshed from scratch every "
               "frame by the whole pipeline (identity map); 60 frames. Given seeds: one face per component, found "
               "once before the first frame and passed to every frame by `seed_faces()`. Spatial order: the input "
               "stored once in spatial order before the first frame (see the input order table).\n\n"
               "| cell size (diagonals) | input order | seeding | quads per frame | ms per frame | frames per second |\n"
               "|---:|---|---|---:|---:|---:|\n";
  const CGAL::Bbox_3 box = PMP::bbox(model.mesh);
  const double height = box.zmax() - box.zmin();
  const int frames = 60;
  Mesh spatial_order;
  RSR::copy_in_spatial_order(model.mesh, spatial_order);
  const Mesh inputs[2] = {model.mesh, std::move(spatial_order)};
  for(double cell : {0.02, 0.01})
    for(int order = 0; order < 2; ++order) {
      const Mesh& input = inputs[order];
      const std::vector<Mesh::Face_index> seeds = one_face_per_component(input); // once, for all frames
      for(int mode = 0; mode < 3; ++mode) {
        const auto seeding = mode == 0 ? RSR::Seeding_method::COMPLETE_SCAN : RSR::Seeding_method::SEEDED;
        std::size_t quads = 0;
        const auto start = Clock::now();
        for(int frame = 0; frame < frames; ++frame) {
          const Twisted_points twisted{&input, 1.5 / height * frame / frames, 0.5 * (box.xmin() + box.xmax()),
                                       0.5 * (box.ymin() + box.ymax())};
          const auto np = RSR::parameters::vertex_point_map(twisted)
                              .grid_spacing(cell * model.diagonal)
                              .seeding_method(seeding);
          Mesh output;
          if(mode == 2)
            RSR::remesh(input, output, np.seed_faces(seeds));
          else
            RSR::remesh(input, output, np);
          quads += num_faces(output);
        }
        const double ms = ms_since(start) / frames;
        const char* modes[] = {"complete", "seeded", "given seeds"};
        std::cout << format("| %.2f | %s | %s | %zu | %.1f | %.0f |", cell, order == 0 ? "file" : "spatial",
                            modes[mode], quads / frames, ms, 1000 / ms)
                  << std::endl;
      }
    }
}

bool read_model(const std::string& file, Model& model)
{
  if(!read_triangle_mesh(file, model.mesh, "table1"))
    return false;
  model.name = model_name(file);
  model.diagonal = bbox_diagonal(model.mesh);
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 11, peer_runs = 5;
  bool peers = true;
  std::string scaling, deforming;
  std::vector<std::string> files;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--runs" && a + 1 < argc)
      runs = std::max(5, std::atoi(argv[++a]));
    else if(arg == "--peer-runs" && a + 1 < argc)
      peer_runs = std::max(1, std::atoi(argv[++a]));
    else if(arg == "--no-peers")
      peers = false;
    else if(arg == "--scaling" && a + 1 < argc)
      scaling = argv[++a];
    else if(arg == "--deforming" && a + 1 < argc)
      deforming = argv[++a];
    else if(!arg.empty() && arg[0] == '-') {
      std::cerr << "table1: unknown option '" << arg << "'" << std::endl;
      return 2;
    } else
      files.push_back(arg);
  }
  if(files.empty() && scaling.empty() && deforming.empty()) {
    std::cerr << "usage: table1 [--runs N] [--peer-runs N] [--no-peers] [--scaling MESH] [--deforming MESH] "
                 "MESH..."
              << std::endl;
    return 2;
  }
  std::vector<Model> models(files.size());
  for(std::size_t i = 0; i < files.size(); ++i)
    if(!read_model(files[i], models[i]))
      return 2;
  std::cout << format("Memory latency at the start: %.0f ns (a load the caches do not hold: pointer chase through "
                      "64 MB; it changes with the load of this shared machine, and the timings with it).\n\n",
                      memory_latency_ns());
  if(!models.empty()) {
    std::vector<double> identity_h;
    const auto six = table_pipeline(models, runs, identity_h);
#if defined(CGAL_LINKED_WITH_TBB)
    table_parallel(models, identity_h, runs);
#endif
    if(peers)
      table_peers(models, six, runs, peer_runs);
    table_input_order(models, identity_h, six, runs);
  }
  if(!scaling.empty()) {
    Model model;
    if(!read_model(scaling, model))
      return 2;
    table_scaling(model, std::max(5, runs / 2));
  }
  if(!deforming.empty()) {
    Model model; // a fresh one: reading into a mesh appends to it
    if(!read_model(deforming, model))
      return 2;
    table_deforming(model);
  }
  std::cout << format("\nMemory latency at the end: %.0f ns.\n", memory_latency_ns());
  return 0;
}
