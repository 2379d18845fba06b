// Uniform remesh of a closed triangle mesh: the identity map, a cell size of 2 %
// of the bounding-box diagonal, output normals sampled from the input.
#include <CGAL/Range_space_remeshing/primal_remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Mesh input;
  if(argc > 1) {
    if(!CGAL::IO::read_polygon_mesh(argv[1], input) || !CGAL::is_triangle_mesh(input)) {
      std::cerr << "cannot read a triangle mesh from " << argv[1] << std::endl;
      return EXIT_FAILURE;
    }
  } else {
    CGAL::make_icosahedron(input, K::Point_3(0, 0, 0), 1.0); // fallback input
  }

  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                    CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));

  Mesh remesh;
  auto normals = remesh.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  try {
    // The map defaults to the identity; any property map vertex -> std::array<double, D>
    // can be passed with RSR::parameters::range_map(f).
    const RSR::Statistics stats = RSR::primal_remesh(
        input, remesh, RSR::parameters::grid_spacing(0.02 * diagonal),
        CGAL::parameters::vertex_normal_map(normals));
    std::cout << num_vertices(input) << " input vertices -> " << stats.output_vertices
              << " vertices, " << stats.output_faces << " faces in " << stats.time_total_ms
              << " ms" << std::endl;
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("remesh.off", remesh) ? EXIT_SUCCESS : EXIT_FAILURE;
}
