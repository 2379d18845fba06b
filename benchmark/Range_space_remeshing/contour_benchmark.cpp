// Benchmark of the primal contouring (map + tracing + faces + output), identity map,
// single thread. For each mesh, the cell size is chosen so that the output has
// about 25 % of the input's vertex count; then the median of repeated runs after a
// warm-up is reported, for the complete scan and the seeded traversal.
//
//   contour_benchmark [--runs N] MESH.off...
//
// Prints a Markdown table on stdout.

#include <CGAL/Range_space_remeshing/primal_remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

namespace {

struct Measure
{
  double median_total = 0, median_wall = 0;
  RSR::Statistics stats; // of the median run
};

RSR::Statistics run_once(const Mesh& input, double h, RSR::Seeding_method seeding, double& wall_ms)
{
  Mesh output;
  const auto start = std::chrono::steady_clock::now();
  const auto stats = RSR::primal_remesh(
      input, output, CGAL::parameters::grid_spacing(h).seeding_method(seeding));
  wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

Measure measure(const Mesh& input, double h, RSR::Seeding_method seeding, int runs)
{
  double wall;
  run_once(input, h, seeding, wall); // warm-up
  std::vector<std::pair<double, RSR::Statistics>> results;
  std::vector<double> walls;
  for(int r = 0; r < runs; ++r) {
    const auto stats = run_once(input, h, seeding, wall);
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

/// Cell size giving about `target` output vertices (within 3 %).
double cell_size_for(const Mesh& input, std::size_t target)
{
  const auto box = CGAL::Polygon_mesh_processing::bbox(input);
  double h = 0.01 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                              CGAL::square(box.ymax() - box.ymin()) +
                              CGAL::square(box.zmax() - box.zmin()));
  for(int iteration = 0; iteration < 20; ++iteration) {
    double wall;
    const auto stats = run_once(input, h, RSR::Seeding_method::COMPLETE_SCAN, wall);
    const double ratio = double(stats.output_vertices) / double(target);
    if(std::abs(ratio - 1) < 0.03)
      break;
    h *= std::sqrt(ratio);
  }
  return h;
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

  std::cout << "| mesh | triangles | vertices | mode | cell size | output vertices | output faces "
               "| mapped vertices | visited faces | tracing steps | seeding ms | tracing ms | faces ms | output ms | total ms "
               "(median of " << runs << ") |\n"
            << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& file : files) {
    Mesh input;
    if(!CGAL::IO::read_polygon_mesh(file, input) || num_faces(input) == 0) {
      std::cerr << "cannot read " << file << std::endl;
      return 2;
    }
    const double h = cell_size_for(input, num_vertices(input) / 4);
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
    }
  }
  return 0;
}
