// Must not compile, with one message: a range map whose values are CGAL points, not
// std::array<double, D>. RSR_CONTROL: the same map with array values, which compiles.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

struct Point_map
{
  using key_type = Mesh::Vertex_index;
#ifdef RSR_CONTROL
  using value_type = std::array<double, 3>;
#else
  using value_type = K::Point_3;
#endif
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const Mesh* mesh;
  friend value_type get(const Point_map& m, key_type v)
  {
    const K::Point_3& p = m.mesh->point(v);
    return value_type{p.x(), p.y(), p.z()};
  }
};

int main()
{
  Mesh in, out;
  CGAL::Range_space_remeshing::remesh(in, out, CGAL::Range_space_remeshing::parameters::range_map(Point_map{&in}));
}
