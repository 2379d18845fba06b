// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every public header of the package in one translation unit, and the main entry
// points instantiated, compiled with the flags CGAL users build with
// (-Wall -Wextra -Wshadow) and -Werror (test/Range_space_remeshing/CMakeLists.txt):
// a warning in a header fails the build. CGAL's own headers are included as system
// headers there, so their warnings do not count.
#include <CGAL/Range_space_remeshing/Color_range_maps.h>
#include <CGAL/Range_space_remeshing/Gauss_range_map.h>
#include <CGAL/Range_space_remeshing/Identity_range_map.h>
#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>
#include <CGAL/Range_space_remeshing/Range_space_traits.h>
#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Remeshing_stage.h>
#include <CGAL/Range_space_remeshing/Sized_range_map.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/Topology_defect.h>
#include <CGAL/Range_space_remeshing/View_range_map.h>
#include <CGAL/Range_space_remeshing/copy_in_spatial_order.h>
#include <CGAL/Range_space_remeshing/dualize.h>
#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/prepare_input.h>
#include <CGAL/Range_space_remeshing/primal_remesh.h>
#include <CGAL/Range_space_remeshing/quad_collapse.h>
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Range_space_remeshing/smooth_vertex_normals.h>
#include <CGAL/Range_space_remeshing/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <array>
#include <cstring>
#include <iostream>
#include <vector>

namespace RSR = CGAL::Range_space_remeshing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

#define RSR_TEST_STRINGIFY(x) #x
#define RSR_TEST_VERSION(major, minor, patch)                                                      \
  RSR_TEST_STRINGIFY(major) "." RSR_TEST_STRINGIFY(minor) "." RSR_TEST_STRINGIFY(patch)
static_assert(sizeof(RANGE_SPACE_REMESHING_VERSION_STR) ==
                  sizeof(RSR_TEST_VERSION(RANGE_SPACE_REMESHING_VERSION_MAJOR, RANGE_SPACE_REMESHING_VERSION_MINOR,
                                          RANGE_SPACE_REMESHING_VERSION_PATCH)),
              "RANGE_SPACE_REMESHING_VERSION_STR is not MAJOR.MINOR.PATCH");

int main()
{
  const char* expected = RSR_TEST_VERSION(RANGE_SPACE_REMESHING_VERSION_MAJOR, RANGE_SPACE_REMESHING_VERSION_MINOR,
                                          RANGE_SPACE_REMESHING_VERSION_PATCH);
  if(std::strcmp(RANGE_SPACE_REMESHING_VERSION_STR, expected) != 0) {
    std::cerr << "version.h: " << RANGE_SPACE_REMESHING_VERSION_STR << " is not " << expected << std::endl;
    return 1;
  }

  // a soup, prepared into a mesh
  std::vector<K::Point_3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<std::vector<std::size_t>> polygons = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  Mesh tetrahedron;
  RSR::prepare_input(points, polygons, tetrahedron);

  Mesh icosahedron, ordered, quads, quads_position_normal;
  CGAL::make_icosahedron(icosahedron, Mesh::Point(0, 0, 0), 1.0);
  RSR::copy_in_spatial_order(icosahedron, ordered);
  const auto stats = RSR::remesh(ordered, quads, CGAL::parameters::grid_spacing(0.2));
  const auto f = RSR::make_position_normal_range_map(ordered, 1.0, 0.5);
  auto normals = ordered.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
  RSR::compute_vertex_normals(ordered, normals);
  RSR::smooth_vertex_normals(ordered, normals, RSR::parameters::number_of_iterations(std::size_t(2)));
  const auto stats_position_normal =
      RSR::remesh(ordered, quads_position_normal, RSR::parameters::range_map(f).grid_spacing(0.2));

  // the chain, the defaults, the target search and a visitor, then each stage alone
  Mesh with_visitor, primal, dual;
  std::size_t calls = 0;
  RSR::remesh(ordered, with_visitor,
              RSR::parameters::number_of_target_vertices(60).preserve_topology(true).progress_visitor(
                  [&calls](RSR::Remeshing_stage, double) { return ++calls > 0; }));
  RSR::primal_remesh(ordered, primal);
  RSR::dualize(primal, dual);
  RSR::collapse_quads(dual, RSR::parameters::number_of_collapse_passes(2));
  RSR::relax_on_tangent_planes(dual, RSR::parameters::number_of_relaxation_steps(2));

  const bool ok = calls > 0 && num_faces(dual) > 0 && num_faces(tetrahedron) == 4 && num_faces(quads) > 20 && num_faces(quads_position_normal) > 20 &&
                  stats.dual.non_quads == 0 && stats_position_normal.dual.non_quads == 0;
  std::cout << "Range_space_remeshing " << RANGE_SPACE_REMESHING_VERSION_STR << ": " << num_faces(quads) << " and "
            << num_faces(quads_position_normal) << " quads" << std::endl;
  return ok ? 0 : 1;
}
