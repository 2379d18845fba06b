// The first remesh: a triangle mesh in, quads out, every parameter at its default (a
// cell of 1% of the bounding-box diagonal), with a progress line and the error kinds.
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Mesh input, quads;
  if(!read_example_input(argc, argv, input)) // argv[1], or a sphere
    return EXIT_FAILURE;
  try {
    const RSR::Remesh_statistics stats = RSR::remesh(input, quads);
    std::cout << num_faces(input) << " triangles -> " << num_faces(quads) << " quads, cell size "
              << stats.primal.cell_size << ", " << stats.time_total_ms << " ms" << std::endl;

    // the same at about 2,000 vertices, telling how far it is
    RSR::remesh(input, quads,
                RSR::parameters::number_of_target_vertices(2000).progress_visitor(
                    [](RSR::Remeshing_stage stage, double done) {
                      std::cout << "  " << RSR::stage_name(stage) << " " << int(100 * done) << "%\n";
                      return true; // false would cancel: RSR::Remeshing_cancelled is thrown
                    }));
    std::cout << num_vertices(quads) << " vertices" << std::endl;
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return e.kind() == RSR::Remeshing_error::Kind::BAD_INPUT ? 2 : EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("remesh.off", quads) ? EXIT_SUCCESS : EXIT_FAILURE;
}
