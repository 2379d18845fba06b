// Remesh by the Gauss map: the grid bounds the normal's variation per face, not its
// size. Flat regions get few large quads, curved ones many small ones, elongated
// along the direction of least curvature.
#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
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
  Mesh input, quads;
  if(!read_example_input(argc, argv, input))
    return EXIT_FAILURE;
  // normals are mapped onto the unit cube, as in the paper: a cell of 0.3 lets the
  // normal turn by about 0.3 radians across a face
  const auto gauss = RSR::make_gauss_range_map(input);
  try {
    const auto stats = RSR::remesh(input, quads, RSR::parameters::range_map(gauss).grid_spacing(0.3));
    std::cout << num_faces(input) << " triangles -> " << num_faces(quads) << " quads in "
              << stats.time_total_ms << " ms" << std::endl;
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("gauss.off", quads) ? EXIT_SUCCESS : EXIT_FAILURE;
}
