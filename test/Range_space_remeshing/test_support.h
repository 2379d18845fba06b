// Shared by the tests: analytic meshes generated in code, and the invariants of
// the primal remesh (DESIGN.md) checked on a run.
#ifndef RANGE_SPACE_REMESHING_TEST_SUPPORT_H
#define RANGE_SPACE_REMESHING_TEST_SUPPORT_H

#include <CGAL/Range_space_remeshing/primal_remesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/version.h>
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/AABB_traits_3.h> // CGAL 6 deprecates AABB_traits (a warning) for this
#else
#include <CGAL/AABB_traits.h>
#endif
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace test {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace RSR = CGAL::Range_space_remeshing;

inline int failures = 0;

#define CHECK(condition)                                                                   \
  do {                                                                                    \
    if(!(condition)) {                                                                    \
      std::cerr << __FILE__ << ":" << __LINE__ << ": CHECK failed: " #condition << std::endl; \
      ++test::failures;                                                                   \
    }                                                                                     \
  } while(0)

#define CHECK_EQ(a, b)                                                                     \
  do {                                                                                    \
    const auto va_ = (a);                                                                 \
    const auto vb_ = (b);                                                                 \
    if(!(va_ == vb_)) {                                                                   \
      std::cerr << __FILE__ << ":" << __LINE__ << ": CHECK_EQ failed: " #a " = " << va_      \
                << ", " #b " = " << vb_ << std::endl;                                      \
      ++test::failures;                                                                   \
    }                                                                                     \
  } while(0)

inline int report(const char* name)
{
  std::cout << name << ": " << (failures == 0 ? "all checks passed" : "FAILED") << " ("
            << failures << " failures)" << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// ------------------------------------------------------------------ meshes

/// Sphere: an icosahedron, Loop-subdivided, projected on the sphere.
inline Mesh make_sphere(double radius, int subdivisions, Point center = Point(0, 0, 0))
{
  Mesh m;
  CGAL::make_icosahedron(m, Point(0, 0, 0), 1.0);
  CGAL::Subdivision_method_3::Loop_subdivision(
      m, CGAL::parameters::number_of_iterations(subdivisions));
  for(auto v : vertices(m)) {
    const auto p = m.point(v) - CGAL::ORIGIN;
    m.point(v) = center + radius * p / std::sqrt(p.squared_length());
  }
  return m;
}

/// Ellipsoid: the sphere scaled by (a, b, c).
inline Mesh make_ellipsoid(double a, double b, double c, int subdivisions)
{
  Mesh m = make_sphere(1.0, subdivisions);
  for(auto v : vertices(m)) {
    const Point p = m.point(v);
    m.point(v) = Point(a * p.x(), b * p.y(), c * p.z());
  }
  return m;
}

/// Torus of radius R whose tube radius at the angle u around the axis is tube(u),
/// tessellated by an nu x nv grid of split quads.
template <class Tube>
Mesh make_torus_with_tube(double R, const Tube& tube, int nu, int nv)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv, r = tube(u);
      vs.push_back(m.add_vertex(Point((R + r * std::cos(v)) * std::cos(u),
                                      (R + r * std::cos(v)) * std::sin(u), r * std::sin(v))));
    }
  auto id = [&](int i, int j) { return vs[((i + nu) % nu) * nv + (j + nv) % nv]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j) {
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return m;
}

/// Torus of radii R > r, tessellated by an nu x nv grid of split quads.
inline Mesh make_torus(double R, double r, int nu, int nv)
{
  return make_torus_with_tube(R, [r](double) { return r; }, nu, nv);
}

/// Boundary of a union of unit voxels (integer corners), each square split in two
/// triangles, oriented outwards. The voxel set must have a manifold boundary.
inline Mesh make_voxel_surface(const std::set<std::array<int, 3>>& voxels, double scale = 1.0)
{
  Mesh m;
  std::map<std::array<int, 3>, Mesh::Vertex_index> index;
  auto vertex = [&](const std::array<int, 3>& c) {
    auto it = index.find(c);
    if(it != index.end())
      return it->second;
    auto v = m.add_vertex(Point(scale * c[0], scale * c[1], scale * c[2]));
    index.emplace(c, v);
    return v;
  };
  for(const auto& cell : voxels)
    for(int axis = 0; axis < 3; ++axis)
      for(int dir : {-1, 1}) {
        std::array<int, 3> neighbour = cell;
        neighbour[axis] += dir;
        if(voxels.count(neighbour))
          continue;
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        std::array<std::array<int, 3>, 4> c;
        for(int corner = 0; corner < 4; ++corner) {
          c[corner] = cell;
          c[corner][axis] += (dir > 0 ? 1 : 0);
        }
        c[1][a] += 1;
        c[2][a] += 1;
        c[2][b] += 1;
        c[3][b] += 1;
        // (a, b, axis) is a right-handed frame: ccw seen from +axis
        if(dir < 0)
          std::swap(c[1], c[3]);
        m.add_face(vertex(c[0]), vertex(c[1]), vertex(c[2]));
        m.add_face(vertex(c[0]), vertex(c[2]), vertex(c[3]));
      }
  return m;
}

/// An n x n x n cube made of unit squares with integer coordinates.
inline Mesh make_lattice_cube(int n)
{
  std::set<std::array<int, 3>> voxels;
  for(int x = 0; x < n; ++x)
    for(int y = 0; y < n; ++y)
      for(int z = 0; z < n; ++z)
        voxels.insert({x, y, z});
  return make_voxel_surface(voxels);
}

/// A smooth genus-2 surface: a plate of 5 x 3 voxels with two holes, Loop-subdivided.
inline Mesh make_genus_2(int subdivisions)
{
  std::set<std::array<int, 3>> voxels;
  for(int x = 0; x < 5; ++x)
    for(int y = 0; y < 3; ++y)
      if(!(y == 1 && (x == 1 || x == 3)))
        voxels.insert({x, y, 0});
  Mesh m = make_voxel_surface(voxels);
  CGAL::Subdivision_method_3::Loop_subdivision(
      m, CGAL::parameters::number_of_iterations(subdivisions));
  return m;
}

inline long euler_characteristic(const Mesh& m)
{
  return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
}

/// The property map `name` of `m`, which the test expects to be there (it stops
/// otherwise): `Surface_mesh::property_map()` returns a (map, found) pair in CGAL 5,
/// an std::optional since CGAL 6.
template <class I, class T>
Mesh::Property_map<I, T> existing_property_map(const Mesh& m, const std::string& name)
{
  const auto found = m.property_map<I, T>(name);
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
  if(found)
    return *found;
#else
  if(found.second)
    return found.first;
#endif
  std::cerr << "no property map '" << name << "'" << std::endl;
  std::exit(1);
}

inline std::size_t number_of_components(Mesh& m)
{
  auto fcc = m.add_property_map<Mesh::Face_index, std::size_t>("f:cc_test").first;
  const std::size_t n = CGAL::Polygon_mesh_processing::connected_components(m, fcc);
  m.remove_property_map(fcc);
  return n;
}

inline double bbox_diagonal(const Mesh& m)
{
  const auto b = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

/// Signed volume enclosed by a closed polygon mesh (faces fanned from their first vertex).
inline double signed_volume(const Mesh& m)
{
  double volume = 0;
  for(auto f : faces(m)) {
    std::vector<Point> p;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      p.push_back(m.point(v));
    for(std::size_t i = 1; i + 1 < p.size(); ++i)
      volume += CGAL::to_double(CGAL::cross_product(p[i] - CGAL::ORIGIN, p[i + 1] - CGAL::ORIGIN) *
                                (p[0] - CGAL::ORIGIN)) / 6.;
  }
  return volume;
}

/// Distance from `mesh` to `reference` as METRO measures it: points sampled uniformly
/// on `mesh` (triangulated copy), each to its closest point on `reference` (AABB
/// tree); lengths in units of the reference's bounding-box diagonal.
struct Distance { double rms = 0, max = 0; };

/// A triangulated copy: CGAL's triangulation, or, where it fails (zero-area faces, as
/// the crease strips of a mesh prepared by insert_crease_triangles() give), a fan.
inline Mesh triangulated(const Mesh& mesh)
{
  Mesh triangles = mesh;
  if(CGAL::Polygon_mesh_processing::triangulate_faces(triangles))
    return triangles;
  Mesh fans;
  std::vector<Mesh::Vertex_index> copy_of(num_vertices(triangles));
  for(auto v : vertices(triangles))
    copy_of[v] = fans.add_vertex(triangles.point(v));
  for(auto f : faces(triangles)) {
    std::vector<Mesh::Vertex_index> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, triangles), triangles))
      corners.push_back(copy_of[v]);
    for(std::size_t i = 1; i + 1 < corners.size(); ++i)
      fans.add_face(corners[0], corners[i], corners[i + 1]);
  }
  return fans;
}

#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits_3<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
#else
using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
#endif

inline Distance distance_to(const Mesh& reference, const Mesh& mesh, std::size_t samples = 100000)
{
  const Mesh triangles = triangulated(mesh);
  const double area = CGAL::Polygon_mesh_processing::area(triangles);
  std::vector<Point> points;
  CGAL::Polygon_mesh_processing::sample_triangle_mesh(
      triangles, std::back_inserter(points),
      CGAL::parameters::number_of_points_per_area_unit(double(samples) / area)
          .do_sample_vertices(false).do_sample_edges(false).random_seed(7));
  Triangle_tree tree(faces(reference).first, faces(reference).second, reference);
  tree.accelerate_distance_queries();
  const double diagonal = bbox_diagonal(reference);
  Distance d;
  for(const Point& p : points) {
    const double d2 = CGAL::to_double(tree.squared_distance(p));
    d.rms += d2;
    d.max = std::max(d.max, std::sqrt(d2));
  }
  d.rms = std::sqrt(d.rms / double(points.size())) / diagonal;
  d.max /= diagonal;
  return d;
}

/// The largest distance from a triangle mesh `from` to `to`, over a barycentric grid of
/// (k + 1)(k + 2) / 2 points on each triangle, in units of `to`'s bounding-box diagonal.
/// Unlike distance_to()'s random samples, which did not repeat from run to run here, the
/// same for the same meshes.
inline double largest_grid_distance(const Mesh& from, const Mesh& to, int k = 8)
{
  Triangle_tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  double d2 = 0;
  for(auto f : faces(from)) {
    std::vector<Point> c;
    for(auto v : CGAL::vertices_around_face(halfedge(f, from), from))
      c.push_back(from.point(v));
    for(int a = 0; a <= k; ++a)
      for(int b = 0; a + b <= k; ++b)
        d2 = std::max(d2, CGAL::to_double(tree.squared_distance(CGAL::barycenter(c[0], k - a - b, c[1], a, c[2], b))));
  }
  return std::sqrt(d2) / bbox_diagonal(to);
}

// ------------------------------------------------------------------ maps

/// f(p) = (x, y, z) followed by what `extra(p, x)` writes into x (it may also
/// overwrite the first three coordinates).
template <int D, class Extra>
struct Appended_map
{
  using key_type = Mesh::Vertex_index;
  using value_type = std::array<double, D>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  const Mesh* mesh;
  Extra extra;

  friend value_type get(const Appended_map& map, key_type v)
  {
    const Point& p = map.mesh->point(v);
    value_type x;
    x[0] = p.x(); x[1] = p.y(); x[2] = p.z();
    map.extra(p, x);
    return x;
  }
};

template <int D, class Extra>
Appended_map<D, Extra> appended(const Mesh& m, Extra extra) { return {&m, extra}; }

// ------------------------------------------------------------------ invariants

/// Checks, on the intermediate structures, that every primal face lies in one
/// closed grid cell. The vertex cells come from the exact predicates.
struct Cell_checker
{
  std::size_t faces_checked = 0;
  std::size_t faces_outside = 0;

  template <class Tracer, class Complex>
  void operator()(Tracer& tracer, const Complex& complex)
  {
    constexpr int D = Tracer::D;
    const auto& vertices = tracer.intersection_vertices();
    const auto& halfedges = complex.halfedges();
    for(std::uint32_t first : complex.face_halfedges()) {
      if(first == Complex::none)
        continue;
      // allowed lower corners per axis, intersected over the face's vertices
      std::array<std::int64_t, D> low, high;
      low.fill(std::numeric_limits<std::int64_t>::min());
      high.fill(std::numeric_limits<std::int64_t>::max());
      std::uint32_t h = first;
      do {
        const auto& v = vertices[halfedges[h].target];
        for(int q = 0; q < D; ++q) {
          std::int64_t lo = v.cell[q], hi = v.cell[q];
          if(q == v.i || q == v.j)
            lo = v.cell[q] - 1; // on the grid plane: either neighbouring cell
          low[q] = std::max(low[q], lo);
          high[q] = std::min(high[q], hi);
        }
        h = halfedges[h].next;
      } while(h != first);
      bool inside = true;
      for(int q = 0; q < D; ++q)
        inside = inside && low[q] <= high[q];
      ++faces_checked;
      if(!inside)
        ++faces_outside;
    }
  }
};

/// Number of border cycles (holes) of a polygon mesh.
template <class PolygonMesh>
std::size_t number_of_border_cycles(const PolygonMesh& m)
{
  std::set<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> walked;
  std::size_t cycles = 0;
  for(auto h : halfedges(m))
    if(is_border(h, m) && walked.insert(h).second) {
      ++cycles;
      for(auto g : CGAL::halfedges_around_face(h, m))
        walked.insert(g);
    }
  return cycles;
}

/// Edges joining the same two vertices as another edge, counted by vertex pairs.
template <class PolygonMesh>
std::size_t number_of_parallel_edges(const PolygonMesh& m)
{
  std::set<std::pair<std::size_t, std::size_t>> ends;
  for(auto e : edges(m)) {
    const std::size_t u = std::size_t(source(e, m)), v = std::size_t(target(e, m));
    ends.insert({(std::min)(u, v), (std::max)(u, v)});
  }
  return num_edges(m) - ends.size();
}

/// Runs the primal remesh with `np` and checks every invariant that does not depend
/// on resolution: valid manifold with the input's border cycles (but those no grid
/// hyperplane crosses), valences, simple faces, one cell per face.
template <class NP>
RSR::Statistics remesh_and_check(const Mesh& input, Mesh& output, const NP& np)
{
  Cell_checker cells;
  const RSR::Statistics stats = RSR::internal::primal_remesh_impl(
      input, output, np, CGAL::parameters::default_values(), std::ref(cells));
  CHECK(CGAL::is_valid_polygon_mesh(output));
  // the seeded traversal may miss pieces, and uncrossed cycles it did not see
  const bool seeded = CGAL::parameters::choose_parameter(
                          CGAL::parameters::get_parameter(np, CGAL::internal_np::seeding_method),
                          RSR::Seeding_method::COMPLETE_SCAN) == RSR::Seeding_method::SEEDED;
  if(stats.dropped_pieces == 0 && !seeded)
    CHECK_EQ(number_of_border_cycles(output),
             number_of_border_cycles(input) - stats.uncrossed_border_cycles);
  if(seeded)
    CHECK(number_of_border_cycles(output) + stats.uncrossed_border_cycles <= number_of_border_cycles(input));
  CHECK_EQ(cells.faces_outside, std::size_t(0));
  CHECK_EQ(cells.faces_checked, num_faces(output));
  CHECK_EQ(stats.output_vertices, num_vertices(output));
  CHECK_EQ(stats.output_faces, num_faces(output));
  // Valence 4 inside and 3 on the border everywhere, except the digon merges (-1 at
  // both ends), the chords of split faces (+1 at both ends) and the corners (2).
  long deficit = 0;
  for(auto v : vertices(output))
    deficit += (CGAL::is_border(v, output) ? 3 : 4) - long(CGAL::halfedges_around_target(v, output).size());
  CHECK_EQ(deficit, 2 * long(stats.digons + stats.boundary_digons) - 2 * long(stats.non_simple_faces) +
                        long(stats.boundary_corners) + 2 * long(stats.split_parallel_edges));
  // faces are simple polygons
  std::size_t non_simple = 0;
  for(auto f : faces(output)) {
    std::set<Mesh::Vertex_index> seen;
    std::size_t degree = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, output), output)) {
      seen.insert(v);
      ++degree;
    }
    non_simple += (seen.size() != degree || degree < 3);
  }
  CHECK_EQ(non_simple, std::size_t(0));
  CHECK_EQ(stats.parallel_edges, number_of_parallel_edges(output));
  return stats;
}

/// Combinatorial fingerprint of a mesh: the sorted faces as vertex-index cycles.
inline std::string fingerprint(const Mesh& m)
{
  std::ostringstream out;
  out << num_vertices(m) << ' ' << num_edges(m) << ' ' << num_faces(m) << '\n';
  for(auto f : faces(m)) {
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      out << std::size_t(v) << ' ';
    out << '\n';
  }
  return out.str();
}

} // namespace test

#endif
