// A sizing field: the remesh finer where the user asks. The field here is 4 at the
// input's highest vertex, falling smoothly to 1 about a fifth of the diagonal away (2.1
// at that distance): the map's cells there are up to a quarter as large, and the remesh
// up to four times finer in each direction. Larger means finer (not a target edge
// length, as in CGAL's isotropic remeshing). The field is any readable property map
// vertex -> positive double (a curvature, a distance to a feature, a user-painted
// scalar); the map may be any range map, here the identity. `sizing_field` comes with
// remesh.h; Sized_range_map.h has the map it makes, for use as a range_map.
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <boost/property_map/function_property_map.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

int main(int argc, char** argv)
{
  Mesh input;
  if(!read_example_input(argc, argv, input))
    return EXIT_FAILURE;
  const double diagonal = bbox_diagonal(input);
  Mesh::Vertex_index top = *vertices(input).begin();
  for(auto v : vertices(input))
    if(input.point(v).z() > input.point(top).z())
      top = v;
  const K::Point_3 centre = input.point(top);
  const double radius = 0.2 * diagonal;
  auto near_the_top = [&](const K::Point_3& p) { return CGAL::squared_distance(p, centre) < radius * radius; };
  const auto sizing = boost::make_function_property_map<Mesh::Vertex_index>([&](Mesh::Vertex_index v) {
    const double d = std::sqrt(CGAL::squared_distance(input.point(v), centre)) / radius;
    return 1 + 3 * std::exp(-d * d * d * d);
  });

  const auto np = RSR::parameters::grid_spacing(0.03 * diagonal);
  Mesh uniform, sized;
  try {
    RSR::remesh(input, uniform, np);
    RSR::remesh(input, sized, np.sizing_field(sizing));
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << "cannot remesh: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  for(const auto& [name, quads] : {std::make_pair("uniform", &uniform), std::make_pair("sized", &sized)}) {
    std::size_t near = 0;
    for(auto v : vertices(*quads))
      near += near_the_top(quads->point(v));
    std::cout << name << ": " << num_vertices(*quads) << " vertices, " << near << " of them within "
              << radius << " of the top" << std::endl;
  }
  if(!CGAL::IO::write_polygon_mesh("sized.off", sized))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}
