// Any FaceGraph works: the same pipeline on CGAL's Polyhedron_3, in and out.
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <cstdlib>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<K>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Polyhedron input, quads;
  if(!read_example_input(argc, argv, input))
    return EXIT_FAILURE;
  try {
    const auto stats = RSR::remesh(input, quads, RSR::parameters::grid_spacing(0.02 * bbox_diagonal(input)));
    std::cout << input.size_of_facets() << " triangles -> " << quads.size_of_facets() << " quads ("
              << stats.dual.non_quads << " other faces) in " << stats.time_total_ms << " ms" << std::endl;
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  return CGAL::IO::write_polygon_mesh("polyhedron.off", quads) ? EXIT_SUCCESS : EXIT_FAILURE;
}
