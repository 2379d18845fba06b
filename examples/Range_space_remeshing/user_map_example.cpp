// A map of your own: position plus a scalar field, into R^4. The field here is a bump
// around a chosen point, so every face bounds its variation as well as its size:
// faces come out small where the field is steep (around the bump's flank) and of
// the cell's size elsewhere. Any readable property map vertex -> std::array<double, D>
// works the same way; the remesher evaluates it only on the vertices it needs.
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

/// vertex -> (x, y, z, height * exp(-|p - centre|^2 / width^2)): a readable property map.
struct Position_and_bump
{
  using key_type = Mesh::Vertex_index;
  using value_type = std::array<double, 4>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  const Mesh* mesh;
  K::Point_3 centre;
  double width, height;

  friend value_type get(const Position_and_bump& f, key_type v)
  {
    const K::Point_3& p = f.mesh->point(v);
    const double bump = f.height * std::exp(-CGAL::squared_distance(p, f.centre) / (f.width * f.width));
    return {{p.x(), p.y(), p.z(), bump}};
  }
};

int main(int argc, char** argv)
{
  Mesh input;
  if(argc > 1) {
    if(!CGAL::IO::read_polygon_mesh(argv[1], input) || !CGAL::is_triangle_mesh(input)) {
      std::cerr << "cannot read a triangle mesh from " << argv[1] << std::endl;
      return EXIT_FAILURE;
    }
  } else { // fallback input: a finely tessellated sphere
    CGAL::make_icosahedron(input, K::Point_3(0, 0, 0), 1.0);
    CGAL::Subdivision_method_3::Loop_subdivision(input, CGAL::parameters::number_of_iterations(4));
  }
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                    CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const double h = 0.03 * diagonal;
  // the bump sits on the first vertex; it rises by 30 cells over about one width
  const Position_and_bump f{&input, input.point(*vertices(input).begin()), 0.2 * diagonal, 30 * h};

  Mesh quads;
  try {
    const auto stats = RSR::remesh(input, quads, RSR::parameters::range_map(f).grid_spacing(h));
    std::cout << num_vertices(input) << " input vertices -> " << num_faces(quads) << " quads ("
              << stats.primal.mapped_vertices << " vertices mapped) in " << stats.time_total_ms << " ms"
              << std::endl;
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  // faces near the bump's flank are smaller: compare the quads' mean area there and far away
  double area_near = 0, area_far = 0;
  int near = 0, far = 0;
  for(auto face : faces(quads)) {
    const auto h0 = halfedge(face, quads);
    const K::Point_3& a = quads.point(source(h0, quads));
    const K::Point_3& c = quads.point(target(next(h0, quads), quads));
    const K::Point_3& b = quads.point(target(h0, quads));
    const K::Point_3& d = quads.point(target(next(next(h0, quads), quads), quads));
    const double area = 0.5 * std::sqrt(CGAL::cross_product(c - a, d - b).squared_length());
    const double r = std::sqrt(CGAL::squared_distance(a, f.centre)) / f.width;
    if(r > 0.5 && r < 1.0) {
      area_near += area;
      ++near;
    } else if(r > 2.5) {
      area_far += area;
      ++far;
    }
  }
  if(near == 0 || far == 0) {
    std::cerr << "the input is too small around the bump to compare" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "mean quad area on the bump's flank: " << area_near / near << ", far from it: " << area_far / far
            << std::endl;
  if(!(area_near / near < 0.5 * area_far / far)) {
    std::cerr << "the bump did not refine the remesh" << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("user_map_remesh.off", quads) ? EXIT_SUCCESS : EXIT_FAILURE;
}
