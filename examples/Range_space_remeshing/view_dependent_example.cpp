// View-dependent remesh: the map is the position in pixels for a camera, so faces are
// bounded in screen size; faces far from the camera come out larger in space.
#include <CGAL/Range_space_remeshing/View_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Mesh input;
  if(!read_example_input(argc, argv, input))
    return EXIT_FAILURE;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = bbox_diagonal(input);
  const std::array<double, 3> centre = {{0.5 * (box.xmin() + box.xmax()), 0.5 * (box.ymin() + box.ymax()),
                                         0.5 * (box.zmin() + box.zmax())}};
  // a 1024 x 768 view from one diagonal away, looking at the centre
  const std::array<double, 3> eye = {{centre[0] + diagonal, centre[1] + 0.3 * diagonal, centre[2] + 0.5 * diagonal}};
  const RSR::Camera camera = RSR::make_look_at_camera(eye, centre, {{0, 0, 1}}, 45, 1024, 768);
  const RSR::View_range_map<Mesh::Property_map<Mesh::Vertex_index, K::Point_3>> f(input.points(), camera);

  Mesh quads;
  try {
    // faces of at most 16 pixels across on screen
    const auto stats = RSR::remesh(input, quads, RSR::parameters::range_map(f).grid_spacing(16.));
    std::cout << num_faces(input) << " triangles -> " << num_faces(quads) << " quads of at most 16 px in "
              << stats.time_total_ms << " ms" << std::endl;
  } catch(const RSR::Remeshing_error& e) { // e.g. a vertex behind the camera
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("view.off", quads) ? EXIT_SUCCESS : EXIT_FAILURE;
}
