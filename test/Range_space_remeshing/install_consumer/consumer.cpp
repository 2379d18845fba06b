// A program outside the tree, built against the installed package: remeshes an
// icosahedron with the two chains of named parameters of the manual (any order, the
// package's and CGAL's parameters mixed) and checks the results are valid, closed,
// all-quad meshes, the same for both; then cancels a run halfway through its progress
// reports and checks the cancellation is clean.
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Range_space_remeshing/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version_macros.h>

#include <cstddef>
#include <iostream>

namespace RSR = CGAL::Range_space_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

bool is_closed_quad_mesh(const Mesh& quads, const RSR::Remesh_statistics& stats)
{
  return num_faces(quads) > 20 && stats.dual.non_quads == 0 && CGAL::is_valid_polygon_mesh(quads) &&
         CGAL::is_closed(quads);
}

int main()
{
  Mesh sphere;
  CGAL::make_icosahedron(sphere, Mesh::Point(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(sphere, CGAL::parameters::number_of_iterations(2));
  const auto vpm = get(CGAL::vertex_point, sphere);
  const auto f = RSR::make_position_normal_range_map(sphere, 1.0, 0.3);

  Mesh first, second;
  const auto first_stats = RSR::remesh(
      sphere, first, RSR::parameters::grid_spacing(0.2).range_map(f).preserve_topology(true).vertex_point_map(vpm));
  const auto second_stats = RSR::remesh(sphere, second,
                                        RSR::parameters::vertex_point_map(vpm)
                                            .dual_placement(RSR::Dual_placement::QEM)
                                            .range_map(f)
                                            .grid_spacing(0.2)
                                            .preserve_topology(true));
  bool ok = is_closed_quad_mesh(first, first_stats) && is_closed_quad_mesh(second, second_stats) &&
            num_faces(first) == num_faces(second);

  // how many reports a whole run gives, then the same run stopped at half of them
  std::size_t reports = 0;
  Mesh whole;
  RSR::remesh(sphere, whole, RSR::parameters::grid_spacing(0.1).progress_visitor([&](RSR::Remeshing_stage, double) {
    ++reports;
    return true;
  }));
  std::size_t heard = 0;
  bool cancelled = false;
  Mesh stopped = whole; // emptied by the cancellation
  try {
    RSR::remesh(sphere, stopped, RSR::parameters::grid_spacing(0.1).progress_visitor([&](RSR::Remeshing_stage, double) {
      return ++heard < reports / 2;
    }));
  } catch(const RSR::Remeshing_cancelled& e) {
    cancelled = e.kind() == RSR::Remeshing_error::Kind::CANCELLED;
  }
  ok = ok && reports >= 6 && cancelled && heard == reports / 2 && num_faces(stopped) == 0 &&
       num_vertices(stopped) == 0;

  std::cout << "consumer: Range_space_remeshing " << RANGE_SPACE_REMESHING_VERSION_STR << " (CGAL "
            << CGAL_VERSION_STR << "): " << num_faces(first) << " quads by both chains; a run of " << reports
            << " reports cancelled after " << heard << (cancelled ? ", output empty" : ", NOT cancelled") << std::endl;
  return ok ? 0 : 1;
}
