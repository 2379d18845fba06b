// sizing_field [--subdivide N] MESH...
// The cost of a sizing field (Sized_range_map): the solve that makes the map, against
// the remesh at 1 % of the diagonal without and with it, and how much finer the output
// is where the field asks (the sizing example's field: 4 within a fifth of the diagonal
// of the highest vertex, 1 far from it). --subdivide N: N Loop subdivisions of each
// input first (4^N times the faces), for the solve's cost on large inputs.
#include "benchmark_support.h"

#include <CGAL/Range_space_remeshing/Sized_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/subdivision_method_3.h>
#include <boost/property_map/function_property_map.hpp>

namespace RSR = CGAL::Range_space_remeshing;
using namespace benchmark_support;

namespace {

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void measure(const std::string& file, int subdivisions)
{
  Mesh m;
  if(!read_triangle_mesh(file, m, "sizing_field"))
    return;
  if(subdivisions > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(subdivisions));
  const double diagonal = bbox_diagonal(m);
  Mesh::Vertex_index top = *vertices(m).begin();
  for(auto v : vertices(m))
    if(m.point(v).z() > m.point(top).z())
      top = v;
  const K::Point_3 centre = m.point(top);
  const double radius = 0.2 * diagonal;
  const auto field = boost::make_function_property_map<Mesh::Vertex_index>([&](Mesh::Vertex_index v) {
    const double d = std::sqrt(CGAL::squared_distance(m.point(v), centre)) / radius;
    return 1 + 3 * std::exp(-d * d * d * d);
  });
  const auto f = RSR::make_identity_range_map(get(CGAL::vertex_point, m));
  auto start = std::chrono::steady_clock::now();
  const auto sized = RSR::make_sized_range_map(m, f, field);
  const double solve_ms = milliseconds_since(start);
  const auto np = RSR::parameters::grid_spacing(0.01 * diagonal);
  auto near = [&](const Mesh& out) {
    std::size_t count = 0;
    for(auto v : vertices(out))
      count += CGAL::squared_distance(out.point(v), centre) < radius * radius;
    return count;
  };
  Mesh uniform, finer;
  start = std::chrono::steady_clock::now();
  RSR::remesh(m, uniform, np);
  const double uniform_ms = milliseconds_since(start);
  start = std::chrono::steady_clock::now();
  RSR::remesh(m, finer, np.range_map(sized));
  const double sized_ms = milliseconds_since(start);
  std::cout << "| " << model_name(file) << (subdivisions > 0 ? " x" + std::to_string(subdivisions) : "") << " | "
            << num_vertices(m) << " | " << solve_ms << " | " << uniform_ms << " | " << sized_ms << " | "
            << num_vertices(uniform) << " (" << near(uniform) << ") | " << num_vertices(finer) << " ("
            << near(finer) << ") |" << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
  int subdivisions = 0;
  std::cout << "| model | input vertices | solve ms | remesh ms | remesh sized ms | output vertices (in the ball) | "
               "sized (in the ball) |\n|---|---:|---:|---:|---:|---:|---:|"
            << std::endl;
  for(int i = 1; i < argc; ++i) {
    if(std::string(argv[i]) == "--subdivide" && i + 1 < argc) {
      subdivisions = std::atoi(argv[++i]);
      continue;
    }
    try {
      measure(argv[i], subdivisions);
    } catch(const RSR::Remeshing_error& e) {
      std::cerr << argv[i] << ": " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
