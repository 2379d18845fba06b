// Remeshes an icosahedron with the whole pipeline and checks the result is a valid,
// closed, all-quad mesh: proves the installed headers and the exported target work.
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/version_macros.h>

#include <iostream>

int main()
{
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  Mesh icosahedron, quads;
  CGAL::make_icosahedron(icosahedron, Mesh::Point(0, 0, 0), 1.0);
  const auto stats = CGAL::Range_space_remeshing::remesh(icosahedron, quads, CGAL::parameters::grid_spacing(0.2));
  const bool ok = num_faces(quads) > 20 && stats.dual.non_quads == 0 && CGAL::is_valid_polygon_mesh(quads) &&
                  CGAL::is_closed(quads);
  std::cout << "consumer: " << num_faces(quads) << " quads from the installed package (CGAL " << CGAL_VERSION_STR << ")"
            << std::endl;
  return ok ? 0 : 1;
}
