// Vertex attributes carried to the output (internal/Vertex_attributes.h): texture
// coordinates (`vertex_texture_map`) and user maps (`vertex_attribute_maps`).
//
// Two kinds of checks:
// * exact ones, with the input's positions as the attribute: a position is linear on
//   the flat input triangles and the dual with the average placement puts a vertex at
//   the weighted mean of the same corners, so an output vertex's attribute must be its
//   own position (up to rounding) if and only if the weights and the corners they go
//   with are right;
// * analytic ones, with the spherical texture coordinates of a sphere, compared with
//   the analytic UVs of the output points away from the seam and the poles, within
//   the interpolation error bound of the input's edge length (primal; in remesh(), at
//   the nearest input point of an output vertex, where the attributes are sampled).
#include "test_support.h"

#include <CGAL/Range_space_remeshing/dualize.h>
#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/Range_space_remeshing/remesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/Position_normal_range_map.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

using namespace test;
namespace params = RSR::parameters;
using UV = K::Point_2;
using Vertex = Mesh::Vertex_index;
using Halfedge = Mesh::Halfedge_index;

/// The spherical texture coordinates of the direction of p.
UV analytic_uv(const Point& p)
{
  const double r = std::sqrt(CGAL::to_double((p - CGAL::ORIGIN).squared_length()));
  return UV(std::atan2(p.y(), p.x()) / (2 * CGAL_PI) + 0.5, std::acos(p.z() / r) / CGAL_PI);
}

/// The input's UVs, one per vertex.
Mesh::Property_map<Vertex, UV> add_uvs(Mesh& m)
{
  auto uvs = m.add_property_map<Vertex, UV>("v:uv").first;
  for(Vertex v : vertices(m))
    uvs[v] = analytic_uv(m.point(v));
  return uvs;
}

double longest_edge(const Mesh& m)
{
  double longest = 0;
  for(auto e : edges(m))
    longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m)))));
  return longest;
}

double distance_to_axis(const Point& p) { return std::sqrt(p.x() * p.x() + p.y() * p.y()); }

/// Whether the input triangles within `reach` of p may straddle the seam (the
/// half-plane y = 0, x <= 0, where u jumps from 1 to 0) or come near the poles
/// (distance to the z axis below 3 reach, where the bounds below blow up).
bool near_seam_or_pole(const Point& p, double reach)
{
  return (p.x() <= reach && std::abs(p.y()) <= reach) || distance_to_axis(p) < 3 * reach;
}

/// Largest error of the output UVs against the analytic ones, each divided by its
/// bound `bound(p)`: at most 1 if every UV is within its bound. Counts the vertices
/// compared in `compared`.
template <class UVMap, class Bound>
double worst_uv_error_ratio(const Mesh& out, UVMap uvs, double reach, const Bound& bound, std::size_t& compared)
{
  double worst = 0;
  compared = 0;
  for(Vertex v : vertices(out)) {
    const Point& p = out.point(v);
    if(near_seam_or_pole(p, reach))
      continue;
    const UV expected = analytic_uv(p), got = get(uvs, v);
    const double error = (std::max)(std::abs(got.x() - expected.x()), std::abs(got.y() - expected.y()));
    worst = (std::max)(worst, error / bound(p));
    ++compared;
  }
  return worst;
}

/// The largest distance between the attribute `carried` of an output vertex and its
/// position, over the output.
template <class PointMap>
double worst_position_mismatch(const Mesh& out, PointMap carried)
{
  double worst = 0;
  for(Vertex v : vertices(out))
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(get(carried, v), out.point(v))));
  return worst;
}

// Linear interpolation over a triangle of f with Hessian norm at most M errs by at most
// M e^2 / 2 at a point within e of every corner (Taylor at the point: the gradient
// terms cancel in the barycentric sum). For u = atan2(y, x) / 2pi the Hessian norm is
// 1 / (2 pi rho^2), rho the distance to the z axis; for v = theta / pi it is at most
// 2 / (pi r rho) <= 2 / (pi rho^2) near the unit sphere; over the triangle rho >= rho(p) - e.
double primal_uv_bound(const Point& p, double e)
{
  const double rho = distance_to_axis(p) - e;
  return (2 / (CGAL_PI * rho * rho)) * e * e / 2;
}

/// Primal: UVs (a CGAL 2-D point) within the interpolation bound, and the positions
/// carried as a user attribute (CGAL 3-D points, with a second, std::array one) equal
/// to the output points.
void test_primal()
{
  Mesh sphere = make_sphere(1.0, 5);
  const auto uvs = add_uvs(sphere);
  const double e = longest_edge(sphere);
  auto positions = std::make_tuple(sphere.points(), sphere.add_property_map<Vertex, std::array<double, 3>>("v:a").first);
  for(Vertex v : vertices(sphere))
    std::get<1>(positions)[v] = {{sphere.point(v).x(), sphere.point(v).y(), sphere.point(v).z()}};

  Mesh out;
  auto out_uvs = out.add_property_map<Vertex, UV>("v:uv").first;
  auto out_points = out.add_property_map<Vertex, Point>("v:carried_point").first;
  auto out_arrays = out.add_property_map<Vertex, std::array<double, 3>>("v:carried_array").first;
  RSR::primal_remesh(sphere, out, params::grid_spacing(0.07).vertex_texture_map(uvs).vertex_attribute_maps(positions),
                     params::vertex_texture_map(out_uvs).vertex_attribute_maps(std::make_tuple(out_points, out_arrays)));
  CHECK(num_vertices(out) > 1000);

  const double position_error = worst_position_mismatch(out, out_points);
  double array_error = 0;
  for(Vertex v : vertices(out))
    array_error = (std::max)(array_error, std::abs(out_arrays[v][0] - out.point(v).x()) +
                                              std::abs(out_arrays[v][1] - out.point(v).y()) +
                                              std::abs(out_arrays[v][2] - out.point(v).z()));
  std::size_t compared = 0;
  const double ratio = worst_uv_error_ratio(out, out_uvs, e, [e](const Point& p) { return primal_uv_bound(p, e); },
                                            compared);
  std::cout << "primal: " << num_vertices(out) << " vertices, input edge " << e << ", position carried off by "
            << position_error << " (array " << array_error << "), UV error / bound " << ratio << " over "
            << compared << " vertices" << std::endl;
  CHECK(position_error < 1e-12);
  CHECK(array_error < 1e-12);
  CHECK(compared > num_vertices(out) / 2);
  CHECK(ratio <= 1);
}

/// The sphere without the faces below z = -0.5: a border for the dual's chain vertices.
Mesh make_cap()
{
  Mesh m = make_sphere(1.0, 4);
  std::vector<Mesh::Face_index> below;
  for(auto f : faces(m)) {
    bool all_below = true;
    for(Vertex v : CGAL::vertices_around_face(halfedge(f, m), m))
      all_below = all_below && m.point(v).z() < -0.5;
    if(all_below)
      below.push_back(f);
  }
  for(auto f : below)
    CGAL::Euler::remove_face(halfedge(f, m), m);
  m.collect_garbage();
  return m;
}

/// Dual: with the average placement, a dual vertex is the weighted mean of the primal
/// vertices whose attributes it mixes (face corners, or the ends of a border edge).
void test_dual()
{
  for(const bool with_border : {false, true}) {
    const Mesh input = with_border ? make_cap() : make_sphere(1.0, 4);
    Mesh primal, quads;
    RSR::primal_remesh(input, primal, params::grid_spacing(0.09));
    auto carried = quads.add_property_map<Vertex, Point>("v:carried_point").first;
    const auto stats = RSR::dualize(primal, quads,
                                    params::dual_placement(RSR::Dual_placement::AVERAGE).vertex_attribute_maps(primal.points()),
                                    params::vertex_attribute_maps(carried));
    std::size_t border_vertices = 0;
    for(Vertex v : vertices(quads))
      border_vertices += bool(CGAL::is_border(v, quads));
    const double error = worst_position_mismatch(quads, carried);
    std::cout << "dual" << (with_border ? " with border" : "") << ": " << stats.dual_vertices << " vertices ("
              << border_vertices << " on the border), position carried off by " << error << std::endl;
    CHECK(num_vertices(quads) > 100);
    CHECK(with_border == (border_vertices > 0));
    CHECK(error < 1e-12);
  }
}

/// The nearest point of `m` to p, by a look at every face (the library asks an AABB
/// tree: this is the check).
Point nearest_point_on(const Mesh& m, const Point& p)
{
  Point best = p;
  double best_distance = -1;
  for(auto f : faces(m)) {
    const auto h = halfedge(f, m);
    const K::Triangle_3 t(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
    const Point q = K().construct_projected_point_3_object()(t, p);
    const double d = CGAL::to_double(CGAL::squared_distance(p, q));
    if(best_distance < 0 || d < best_distance) {
      best_distance = d;
      best = q;
    }
  }
  return best;
}

/// remesh(): the attributes are sampled where the output vertices end, after the
/// collapse and the relaxation moved them: with the positions as the attribute, each
/// output vertex carries the nearest point of the input; the UVs are the analytic ones
/// at that point, within the primal's interpolation bound, and so within that and the
/// gradient times the distance of the point to the input at the output point.
/// (Carried through the stages as the dual's face means, they wavered by up to a cell.)
void test_remesh()
{
  {
    Mesh sphere = make_sphere(1.0, 4);
    Mesh quads;
    auto carried = quads.add_property_map<Vertex, Point>("v:carried_point").first;
    RSR::remesh(sphere, quads, params::grid_spacing(0.07).vertex_attribute_maps(sphere.points()),
                params::vertex_attribute_maps(carried));
    double error = 0, moved = 0;
    for(Vertex v : vertices(quads)) {
      const Point nearest = nearest_point_on(sphere, quads.point(v));
      error = (std::max)(error, std::sqrt(CGAL::squared_distance(get(carried, v), nearest)));
      moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(quads.point(v), nearest)));
    }
    std::cout << "remesh: position carried off the nearest input point by " << error << " (the output points off "
              << "the input by up to " << moved << ")" << std::endl;
    CHECK(num_vertices(quads) > 200);
    CHECK(error < 1e-12);
    CHECK(moved > 1e-6); // the check compares two things: the vertices are off the input
  }
  Mesh sphere = make_sphere(1.0, 5);
  const auto uvs = add_uvs(sphere);
  const double e = longest_edge(sphere);
  const double h = 0.05;
  Mesh quads;
  auto out_uvs = quads.add_property_map<Vertex, UV>("v:uv").first;
  const auto stats = RSR::remesh(sphere, quads, params::grid_spacing(h).vertex_texture_map(uvs),
                                 params::vertex_texture_map(out_uvs));
  auto bound = [&](const Point& p) {
    const double off = std::sqrt(CGAL::squared_distance(p, nearest_point_on(sphere, p)));
    return off / (CGAL_PI * (distance_to_axis(p) - e - off)) + primal_uv_bound(p, e + off);
  };
  std::size_t compared = 0;
  const double ratio = worst_uv_error_ratio(quads, out_uvs, 2 * e, bound, compared);
  std::cout << "remesh: " << num_vertices(quads) << " vertices, " << stats.collapse.collapsed_quads
            << " collapses, UV error / bound " << ratio << " over " << compared << " vertices" << std::endl;
  CHECK(num_vertices(quads) > 500);
  CHECK(compared > num_vertices(quads) / 2);
  CHECK(ratio <= 1);
}

/// Distance from p to the surface of m (all faces, brute force).
double distance_to(const Mesh& m, const Point& p)
{
  return std::sqrt(CGAL::squared_distance(p, nearest_point_on(m, p)));
}

/// How far the positions carried by remesh() to the output of `input` are from being
/// nearest points of `surface` (the input's surface divided by `scale`; its copies
/// along the creases have none of their own), in units of `surface`: the largest of
/// each carried point's distance to the surface and of how much farther it is from
/// its output vertex than the surface is. Robust to ties (an output vertex inside a
/// cube, as far from two faces).
double carried_error(const Mesh& input, const Mesh& surface, double scale, double cell = 0.3)
{
  Mesh quads;
  auto carried = quads.add_property_map<Vertex, Point>("v:carried_point").first;
  RSR::remesh(input, quads, params::grid_spacing(cell * scale).vertex_attribute_maps(input.points()),
              params::vertex_attribute_maps(carried));
  CHECK(num_vertices(quads) > 50);
  auto unscaled = [scale](const Point& p) { return Point(p.x() / scale, p.y() / scale, p.z() / scale); };
  double error = 0;
  for(Vertex v : vertices(quads)) {
    const Point p = unscaled(quads.point(v)), c = unscaled(get(carried, v));
    const double off = distance_to(surface, c), farther = std::sqrt(CGAL::squared_distance(p, c)) - distance_to(surface, p);
    CHECK(std::isfinite(off) && std::isfinite(farther));
    error = (std::max)({error, off, farther});
  }
  return error;
}

/// Attributes sampled on the zero-area triangles of opened creases (the nearest point
/// of an output vertex near an edge of a cube is often on one: it took the values of
/// the triangle's first corner, a whole edge away) and on inputs of extreme scale
/// (coordinates of 1e160 or 1e-160: the nearest-point search's exact fallback got a
/// non-finite number and GMP stopped the process; one far vertex at 1e200 leaves the
/// rest too small to sample: refused).
void test_flat_triangles_and_extreme_scales()
{
  const Mesh cube = make_lattice_cube(2);
  Mesh creased;
  RSR::insert_crease_triangles(cube, creased, 30.0);
  CHECK(num_faces(creased) > num_faces(cube));
  const double flat = carried_error(creased, cube, 1.0);
  std::cout << "remesh, cube with opened creases: carried positions off the nearest points by " << flat
            << " edge lengths" << std::endl;
  CHECK(flat < 1e-12);
  for(double scale : {1e160, 1e-160}) {
    Mesh big = creased;
    for(Vertex v : vertices(big))
      big.point(v) = Point(big.point(v).x() * scale, big.point(v).y() * scale, big.point(v).z() * scale);
    const double scaled = carried_error(big, cube, scale);
    std::cout << "remesh, cube scaled by " << scale << ": off by " << scaled << " edge lengths" << std::endl;
    CHECK(scaled < 1e-12);
  }
  Mesh far = make_lattice_cube(2); // one corner pulled to 1e200: the rest is a speck beside it
  far.point(*vertices(far).begin()) = Point(0, 0, 1e200);
  Mesh quads;
  auto carried = quads.add_property_map<Vertex, Point>("v:carried_point").first;
  bool refused = false; // the rest is too small beside it to sample its attributes
  std::size_t reports = 0; // of the remesh's progress: the refusal comes before its work
  try {
    RSR::remesh(far, quads,
                params::grid_spacing(1e198)
                    .vertex_attribute_maps(far.points())
                    .progress_visitor([&reports](RSR::Remeshing_stage, double) { ++reports; return true; }),
                params::vertex_attribute_maps(carried));
  } catch(const RSR::Remeshing_error& e) {
    refused = e.kind() == RSR::Remeshing_error::Kind::BAD_INPUT;
    std::cout << "remesh, one vertex at 1e200: refused after " << reports << " progress reports (" << e.what() << ")"
              << std::endl;
  }
  CHECK(refused);
  CHECK(reports == 0);
  Mesh plain; // without attributes, it is remeshed
  RSR::remesh(far, plain, params::grid_spacing(1e198));
  CHECK(num_vertices(plain) > 0);
}

/// One edge 1e-72 long among edges of 1 (a cube's edge split next to a corner, the two
/// faces beside it split at the new vertex): the features around it are not small, and
/// its faces, flat at the scale of the search, are searched as segments. It was refused
/// as a part too small to sample.
void test_one_short_edge()
{
  Mesh cube = make_lattice_cube(2);
  Halfedge from_origin = Halfedge();
  for(Halfedge h : halfedges(cube))
    if(cube.point(source(h, cube)) == CGAL::ORIGIN && !is_border(h, cube) && !is_border(opposite(h, cube), cube))
      from_origin = h;
  CHECK(from_origin != Halfedge());
  const Point end = cube.point(target(from_origin, cube));
  const Halfedge to_new = CGAL::Euler::split_edge(from_origin, cube); // origin -> new -> end
  cube.point(target(to_new, cube)) = Point(end.x() * 1e-72, end.y() * 1e-72, end.z() * 1e-72);
  const Halfedge back = opposite(from_origin, cube); // end -> new, then new -> origin
  CGAL::Euler::split_face(to_new, next(from_origin, cube), cube);
  CGAL::Euler::split_face(back, next(opposite(to_new, cube), cube), cube);
  CHECK(CGAL::is_triangle_mesh(cube) && CGAL::is_valid_polygon_mesh(cube));
  const double off = carried_error(cube, cube, 1.0);
  std::cout << "remesh, cube with one edge of 1e-72: carried positions off by " << off << std::endl;
  CHECK(off < 1e-12);
}

/// Triangles whose three corners are distinct points of one line (a cube whose edges
/// were split at 0.3 and flipped: 38 of them along its creases) with the normal map and
/// opened creases: the areas' weights on such a triangle are rounding noise, and a
/// point beside a needle is not given back by its unsigned areas (output vertices on
/// the surface took values 0.37 edge lengths away). And a small part beside a far one
/// (a cube 1e30 from a triangle): the part must keep its own values.
void test_needles_and_far_parts(const std::string& data)
{
  Mesh cube;
  CHECK(CGAL::IO::read_polygon_mesh(data + "/cube_collinear_crease.off", cube));
  Mesh creased;
  RSR::insert_crease_triangles(cube, creased, 30.0);
  auto normals = creased.add_property_map<Vertex, K::Vector_3>("v:normal").first;
  RSR::compute_vertex_normals(creased, normals);
  const RSR::Position_normal_range_map f(creased.points(), normals, 1.0, 0.1 * std::sqrt(3.));
  Mesh quads;
  auto carried = quads.add_property_map<Vertex, Point>("v:carried_point").first;
  RSR::remesh(creased, quads,
              params::range_map(f).grid_spacing(0.05).vertex_normal_map(normals)
                  .dual_placement(RSR::Dual_placement::SHARP_FEATURES).vertex_attribute_maps(creased.points()),
              params::vertex_attribute_maps(carried));
  double needle = 0;
  for(Vertex v : vertices(quads)) {
    const Point& p = quads.point(v);
    const Point& c = get(carried, v);
    needle = (std::max)({needle, distance_to(cube, c),
                         std::sqrt(CGAL::squared_distance(p, c)) - distance_to(cube, p)});
  }
  std::cout << "remesh, cube with needles along its creases: " << num_vertices(quads)
            << " vertices, carried positions off the nearest points by " << needle << std::endl;
  CHECK(num_vertices(quads) > 100);
  CHECK(needle < 1e-9);

  const Mesh lattice = make_lattice_cube(2);
  Mesh far = lattice;
  const auto a = far.add_vertex(Point(1e30, 0, 0)), b = far.add_vertex(Point(1e30, 1e30, 0)),
             c = far.add_vertex(Point(1e30, 0, 1e30));
  far.add_face(a, b, c);
  Mesh out;
  auto far_carried = out.add_property_map<Vertex, Point>("v:carried_point").first;
  RSR::remesh(far, out, params::vertex_attribute_maps(far.points()), // the cube in one cell of the default grid
              params::vertex_attribute_maps(far_carried));
  double near_cube = 0;
  std::size_t on_cube = 0;
  for(Vertex v : vertices(out))
    {
      const Point& p = out.point(v);
      if(CGAL::squared_distance(p, Point(1, 1, 1)) > 100)
        continue;
      ++on_cube;
      const Point& q = get(far_carried, v);
      near_cube = (std::max)({near_cube, distance_to(lattice, q),
                              std::sqrt(CGAL::squared_distance(p, q)) - distance_to(lattice, p)});
    }
  std::cout << "remesh, cube beside a triangle at 1e30: " << on_cube << " vertices at the cube, carried positions off by "
            << near_cube << std::endl;
  CHECK(on_cube > 0);
  CHECK(near_cube < 1e-9);
}

/// A part flat at the scale of doubles beside another: a needle, a closed tetrahedron
/// 2 long and 1e-80 thick (its faces lose their area on the sampling's scaled points),
/// beside a cube. Its faces
/// were left out of the nearest-point search, so it took the cube's values.
void test_flat_part()
{
  const Mesh lattice = make_lattice_cube(2);
  Mesh input = lattice, needle;
  const Point corners[4] = {Point(3, 0, 0), Point(5, 0, 0), Point(3.5, 1e-80, 0), Point(4.5, 0, 1e-80)};
  std::vector<Vertex> in_input, in_needle;
  for(const Point& p : corners) {
    in_input.push_back(input.add_vertex(p));
    in_needle.push_back(needle.add_vertex(p));
  }
  for(const std::array<int, 3>& f : {std::array<int, 3>{{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{2, 0, 3}}}) {
    input.add_face(in_input[f[0]], in_input[f[1]], in_input[f[2]]);
    needle.add_face(in_needle[f[0]], in_needle[f[1]], in_needle[f[2]]);
  }
  CHECK(CGAL::is_closed(input) && num_faces(input) == num_faces(lattice) + 4);
  Mesh out;
  auto carried = out.add_property_map<Vertex, Point>("v:carried_point").first;
  RSR::remesh(input, out, params::grid_spacing(0.25).vertex_attribute_maps(input.points()),
              params::vertex_attribute_maps(carried));
  double off = 0;
  std::size_t at_needle = 0;
  for(Vertex v : vertices(out)) {
    const Point& p = out.point(v);
    if(p.x() < 2.5)
      continue;
    ++at_needle;
    const Point& q = get(carried, v);
    off = (std::max)({off, distance_to(needle, q), std::sqrt(CGAL::squared_distance(p, q)) - distance_to(needle, p)});
  }
  std::cout << "remesh, a needle 1e-80 thick beside a cube: " << at_needle
            << " vertices at the needle, carried positions off by " << off << std::endl;
  CHECK(at_needle > 10);
  CHECK(off < 1e-9);
}

/// Two surfaces closer than a cell: nested spheres 0.01 apart (the inner one turned
/// inside out: a shell) and two spheres through each other. Each output vertex must
/// carry the nearest point of either. A search that started from the output's own
/// structures (a walk over the input from the face of the nearest primal vertex, tried
/// once) stayed on one sheet and took the other's values where it was nearer.
void test_close_sheets()
{
  Mesh nested = make_sphere(1.0, 3);
  Mesh inner = make_sphere(0.99, 3);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(inner);
  CGAL::copy_face_graph(inner, nested);
  Mesh crossing = make_sphere(1.0, 3);
  CGAL::copy_face_graph(make_sphere(1.0, 3, Point(0.5, 0, 0)), crossing);
  for(const auto& [name, input] : {std::make_pair("nested spheres", &nested), std::make_pair("crossing spheres", &crossing)}) {
    const double error = carried_error(*input, *input, 1.0, 0.05);
    std::cout << "remesh, " << name << ": carried positions off the nearest points by " << error << std::endl;
    CHECK(error < 1e-12);
  }
}

/// The nearest-point search itself against a look at every face, for queries on, near
/// and far from the surface (a sphere, a speck beside it, and a needle: a split edge's
/// middle point an ulp off its line, so that its plane's normal is rounding noise;
/// far queries end in a scan of every cube), with cubes fitted to few and to many
/// queries.
void test_nearest_face_search()
{
  Mesh input = make_sphere(0.5, 3);
  CGAL::copy_face_graph(make_sphere(0.01, 1, Point(0.9, 0.01, 0)), input);
  const Point needle_end(0.9, 0.7, -0.7);
  input.add_face(input.add_vertex(Point(0, 0, -0.6)), input.add_vertex(needle_end),
                 input.add_vertex(Point(0.3, 0.7 / 3, -0.6 - 0.1 / 3)));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1, 1), scale(0, 4), along(0, 1), beside(-1e-3, 1e-3);
  std::vector<Point> queries;
  for(int i = 0; i < 300; ++i) {
    const double t = along(random);
    queries.emplace_back(t * 0.9 + beside(random), t * 0.7 + beside(random), -0.6 - t * 0.1 + beside(random));
  }
  for(int i = 0; i < 900; ++i) {
    const Point p(coordinate(random), coordinate(random), coordinate(random));
    const double s = i % 3 == 0 ? scale(random) : i % 3 == 1 ? 0.5 / std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Point(0, 0, 0)))) : 1;
    queries.emplace_back(s * p.x(), s * p.y(), s * p.z());
  }
  for(std::size_t fitted_to : {std::size_t(10), std::size_t(20000)}) {
    const RSR::internal::Nearest_face_search<Mesh, decltype(input.points())> search(input, input.points(), fitted_to);
    double worst = 0;
    std::size_t hint = 0;
    for(const Point& q : queries) {
      const auto hit = search.nearest(RSR::internal::to_vec3(q), hint);
      hint = hit.number;
      const Point found(hit.point[0], hit.point[1], hit.point[2]);
      const double by_search = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, found)));
      worst = (std::max)(worst, std::abs(by_search - distance_to(input, q)));
    }
    std::cout << "nearest-face search fitted to " << fitted_to << " queries: distances off the brute force's by "
              << worst << std::endl;
    CHECK(worst < 1e-12);
  }
}

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: test_attributes DATA_FOLDER" << std::endl;
    return EXIT_FAILURE;
  }
  test_primal();
  test_dual();
  test_remesh();
  test_flat_triangles_and_extreme_scales();
  test_needles_and_far_parts(argv[1]);
  test_flat_part();
  test_one_short_edge();
  test_close_sheets();
  test_nearest_face_search();
  return report("test_attributes");
}
