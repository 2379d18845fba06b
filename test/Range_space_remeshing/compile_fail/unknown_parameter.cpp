// Must not compile: relax_on_tangent_planes() does not read number_of_iterations (its
// steps are number_of_relaxation_steps), so the parameter would be silently ignored.
// RSR_CONTROL: the same call with the parameter it reads, which must compile.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>
#include <CGAL/Surface_mesh.h>

int main()
{
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
#ifdef RSR_CONTROL
  CGAL::Range_space_remeshing::relax_on_tangent_planes(mesh, CGAL::parameters::number_of_relaxation_steps(2));
#else
  CGAL::Range_space_remeshing::relax_on_tangent_planes(mesh, CGAL::parameters::number_of_iterations(2));
#endif
}
