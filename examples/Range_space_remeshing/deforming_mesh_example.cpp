// Interactive use: a mesh twisting about its vertical axis, remeshed from scratch
// every frame with the whole pipeline. The seeded traversal only maps the vertices
// the arcs need, so a frame costs far less than a pass over the input; and the input
// is copied once in spatial order, so that the walks across it read memory that is
// near (which pays from a few frames on).
#include <CGAL/Range_space_remeshing/copy_in_spatial_order.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>
#include <cstdlib>

#include "example_input.h"

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace RSR = CGAL::Range_space_remeshing;

/// The rest shape twisted about the vertical axis through (cx, cy): a vertex point
/// map computed on demand, so that the remesher reads only the vertices it needs and
/// no frame pays for moving the whole mesh.
struct Twisted_points
{
  using key_type = Mesh::Vertex_index;
  using value_type = K::Point_3;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const Mesh* rest;
  double angle_per_height, cx, cy;
  friend value_type get(const Twisted_points& f, key_type v)
  {
    const K::Point_3& p = f.rest->point(v);
    const double a = f.angle_per_height * p.z(), c = std::cos(a), s = std::sin(a);
    const double x = p.x() - f.cx, y = p.y() - f.cy;
    return {f.cx + c * x - s * y, f.cy + s * x + c * y, p.z()};
  }
};

int main(int argc, char** argv)
{
  Mesh as_read;
  if(!read_example_input(argc, argv, as_read))
    return EXIT_FAILURE;
  Mesh rest;
  try {
    RSR::copy_in_spatial_order(as_read, rest);
  } catch(const RSR::Remeshing_error& e) {
    std::cerr << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(rest);
  const double height = box.zmax() - box.zmin(), h = 0.02 * bbox_diagonal(rest);
  const int frames = 10;
  const auto start = std::chrono::steady_clock::now();
  std::size_t quads_in_last_frame = 0;
  for(int frame = 0; frame < frames; ++frame) {
    const Twisted_points twisted{&rest, (height > 0 ? 1.5 / height : 0.) * frame / frames,
                             0.5 * (box.xmin() + box.xmax()), 0.5 * (box.ymin() + box.ymax())};
    Mesh quads;
    try {
      // the identity map of the twisted points: a uniform remesh of this frame's shape
      RSR::remesh(rest, quads,
                  RSR::parameters::vertex_point_map(twisted).grid_spacing(h).seeding_method(
                      RSR::Seeding_method::SEEDED));
    } catch(const RSR::Remeshing_error& e) {
      std::cerr << "frame " << frame << ": " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    quads_in_last_frame = num_faces(quads);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << frames << " frames of about " << quads_in_last_frame << " quads: " << frames / seconds
            << " frames per second" << std::endl;
  return quads_in_last_frame > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
