// The whole pipeline with position + normal in R^6 (dual with QEM placement, quad
// collapse, relaxation), at three normal weights: from uniform (weight 0: the
// position alone) to anisotropic (the normal dominates where the surface curves).
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <string>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Mesh input;
  if(!read_example_input(argc, argv, input))
    return EXIT_FAILURE;
  const double h = 0.02 * bbox_diagonal(input);
  for(double normal_weight : {0.0, 0.02, 0.05}) {
    // weights in length units: a normal weight W lets the normal turn by h / W per face
    const auto f = RSR::make_position_normal_range_map(input, 1.0, normal_weight * bbox_diagonal(input));
    Mesh quads;
    try {
      // the package's own named parameters take the pack they extend as last argument
      const auto np = RSR::parameters::range_map(f)
                          .grid_spacing(h)
                          .dual_placement(RSR::Dual_placement::QEM)
                          .quad_collapse(true)
                          .number_of_relaxation_steps(3);
      const auto stats = RSR::remesh(input, quads, np);
      std::cout << "normal weight " << normal_weight << ": " << num_faces(quads) << " quads ("
                << stats.collapse.collapsed_quads << " collapsed) in " << stats.time_total_ms << " ms"
                << std::endl;
    } catch(const RSR::Remeshing_error& e) {
      std::cerr << "cannot remesh: " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    if(!CGAL::IO::write_polygon_mesh("anisotropic_" + std::to_string(normal_weight) + ".off", quads))
      return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
