// The relaxation takes back a move that makes a quad non-convex (a dart) without
// folding it (issue 39): a 2 x 2 grid of quads whose centre is pulled towards the
// far corner of one quad; that quad's corner at the centre turns reflex, its area
// stays positive. The old check (folded faces only) kept the move.
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <vector>

int main()
{
  using K = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  namespace RI = CGAL::Range_space_remeshing::internal;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  std::vector<RI::Vec3> position, normal, next;
  for(int y = 0; y < 3; ++y)
    for(int x = 0; x < 3; ++x) {
      v.push_back(mesh.add_vertex(K::Point_3(x, y, 0)));
      position.push_back({{double(x), double(y), 0}});
      normal.push_back({{0, 0, 1}});
    }
  for(int y = 0; y < 2; ++y)
    for(int x = 0; x < 2; ++x)
      mesh.add_face(v[3 * y + x], v[3 * y + x + 1], v[3 * y + x + 4], v[3 * y + x + 3]);
  const RI::Face_corners fc(mesh, get(CGAL::vertex_index, mesh), num_vertices(mesh));
  int failures = 0;
  // Moves the centre to `to`, lets the check take moves back, and says whether it stayed.
  auto kept = [&](const RI::Vec3& to) {
    next = position;
    next[4] = to;
    RI::keep_faces_unfolded(fc, position, normal, next);
    return next[4] != position[4];
  };
  auto expect = [&](bool ok, const char* what) {
    if(!ok) {
      std::cerr << what << "\n";
      ++failures;
    }
  };
  // the dart: the top-right quad's corner at the centre is reflex, its area positive
  expect(!kept({{1.9, 1.9, 0}}), "a move that makes a quad non-convex was kept");
  // a fold: the centre beyond the far corner
  expect(!kept({{2.5, 2.5, 0}}), "a move that folds a quad was kept");
  // a harmless move stays
  expect(kept({{1.2, 1.1, 0}}), "a move that keeps every quad convex was taken back");
  if(failures == 0)
    std::cout << "test_relaxation_convexity: all checks passed\n";
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
