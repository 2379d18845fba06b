// attribute_sampling [--runs N] [--fans-up-to N] [MESH...]
// The cost of remesh()'s sampling of vertex attributes: each run remeshes once with
// no attribute and once carrying the input's points as an attribute
// (`vertex_attribute_maps`); the sampling's cost is the difference of the medians.
// Inputs: fans of long thin triangles (a unit square as two fans from opposite
// corners, N = 1,000 to 100,000 triangles each, or up to --fans-up-to; generated here:
// what CAD exports make of a flat face), a unit sphere with a speck 1e7 away (cell
// size 0.05: the speck must not make the sphere's cubes large), then the meshes named. Also the largest distance from a carried point to its
// output vertex's nearest point, which must stay at rounding level. A Markdown table
// on stdout.
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace RSR = CGAL::Range_space_remeshing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Clock = std::chrono::steady_clock;

namespace {

/// The unit square as two fans of `n` slivers each, from (0, 0) to the top side and
/// from (1, 1) to the bottom side, at random abscissas (fixed seed).
Mesh sliver_fans(std::size_t n)
{
  std::mt19937 random(1);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<double> xs = {0., 1.};
  for(std::size_t i = 0; i < n; ++i)
    xs.push_back(uniform(random));
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  Mesh m;
  std::vector<Mesh::Vertex_index> bottom, top;
  for(double x : xs)
    bottom.push_back(m.add_vertex(Point(x, 0, 0)));
  for(double x : xs)
    top.push_back(m.add_vertex(Point(x, 1, 0)));
  for(std::size_t j = 0; j + 1 < top.size(); ++j)
    m.add_face(bottom.front(), top[j + 1], top[j]);
  for(std::size_t i = 0; i + 1 < bottom.size(); ++i)
    m.add_face(top.back(), bottom[i], bottom[i + 1]);
  return m;
}

/// A unit sphere of 81,920 triangles (an icosahedron, Loop-subdivided six times, its
/// points pushed onto the sphere) and a tetrahedron 0.01 across at (1e7, 0, 0).
Mesh sphere_with_far_speck()
{
  Mesh m;
  CGAL::make_icosahedron(m, Point(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(6));
  for(auto v : vertices(m)) {
    const auto x = m.point(v) - CGAL::ORIGIN;
    m.point(v) = CGAL::ORIGIN + x / std::sqrt(x.squared_length());
  }
  CGAL::make_tetrahedron(Point(1e7, 0, 0), Point(1e7 + 0.01, 0, 0), Point(1e7, 0.01, 0), Point(1e7, 0, 0.01), m);
  return m;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double milliseconds_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// `cell_size` 0: the default.
void measure(const std::string& name, const Mesh& input, int runs, double cell_size = 0)
{
  const auto base = RSR::parameters::vertex_point_map(input.points()); // the default, to start a chain
  auto remesh = [&](Mesh& output, const auto& np, const auto&... output_np) {
    if(cell_size > 0)
      RSR::remesh(input, output, np.grid_spacing(cell_size), output_np...);
    else
      RSR::remesh(input, output, np, output_np...);
  };
  std::vector<double> plain, carried;
  std::size_t output_vertices = 0;
  double off = 0;
  for(int run = 0; run < runs; ++run) {
    Mesh quads;
    Clock::time_point start = Clock::now();
    remesh(quads, base);
    plain.push_back(milliseconds_since(start));
    Mesh with;
    auto carried_point = with.add_property_map<Mesh::Vertex_index, Point>("v:carried").first;
    start = Clock::now();
    remesh(with, base.vertex_attribute_maps(input.points()), RSR::parameters::vertex_attribute_maps(carried_point));
    carried.push_back(milliseconds_since(start));
    output_vertices = num_vertices(with);
    off = 0;
    for(auto v : vertices(with)) // the fans are flat: the nearest point is the output point on z = 0
      if(name.rfind("fans", 0) == 0)
        off = (std::max)(off, std::sqrt(CGAL::squared_distance(
                                  get(carried_point, v), Point(with.point(v).x(), with.point(v).y(), 0))));
  }
  char carried_off[32] = "";
  if(name.rfind("fans", 0) == 0)
    std::snprintf(carried_off, sizeof carried_off, "%.1e", off);
  std::printf("| %s | %zu | %zu | %.0f | %.0f | %.0f | %s |\n", name.c_str(), std::size_t(num_faces(input)),
              output_vertices, median(plain), median(carried), median(carried) - median(plain), carried_off);
}

} // namespace

int main(int argc, char** argv)
{
  int runs = 3;
  std::size_t largest_fan = 100000;
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--runs" && i + 1 < argc)
      runs = std::atoi(argv[++i]);
    else if(arg == "--fans-up-to" && i + 1 < argc)
      largest_fan = std::size_t(std::atol(argv[++i]));
    else
      meshes.push_back(arg);
  }
  std::printf("| input | faces | output vertices | remesh (ms) | with attributes (ms) | sampling (ms) | "
              "carried off (fans) |\n|---|---|---|---|---|---|---|\n");
  for(std::size_t n : {1000, 8000, 32000, 100000})
    if(n <= largest_fan)
      measure("fans of " + std::to_string(n) + " slivers", sliver_fans(n), runs);
  measure("sphere, speck 1e7 away", sphere_with_far_speck(), runs, 0.05);
  for(const std::string& path : meshes) {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(path, m) || !CGAL::is_triangle_mesh(m)) {
      std::fprintf(stderr, "attribute_sampling: cannot read %s as a triangle mesh\n", path.c_str());
      return EXIT_FAILURE;
    }
    measure(path.substr(path.find_last_of('/') + 1), m, runs);
  }
  return EXIT_SUCCESS;
}
