// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H

// The vertex attributes of remesh()'s output, sampled where its vertices end: the
// collapse, the relaxation and the untangling move the vertices after the dual gave
// them the mean of their primal face's values, by up to about a cell, so a texture's
// lines would waver. Each output vertex takes the values at the nearest point of the
// input (CGAL's AABB tree finds it and its face).

#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_attributes.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/version.h>
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <limits>
#include <utility>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The weights of q, the point nearest to it on a triangle without area (corners on
/// one line, or a crease's copies): those of its foot on the nearest side with two
/// distinct ends, between those ends, so that the values vary along the line as on
/// the input's edges; the first corner's if the corners coincide.
inline std::array<double, 3> weights_on_flat_triangle(const Vec3& q, const std::array<Vec3, 3>& corners)
{
  std::array<double, 3> weights = {{1, 0, 0}};
  double nearest = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < 3; ++i) {
    const std::size_t from = (i + 1) % 3, to = (i + 2) % 3; // the side opposite corner i
    const Vec3 side = difference(corners[to], corners[from]);
    const double length2 = dot(side, side);
    if(!(length2 > 0))
      continue;
    const double t = (std::min)((std::max)(dot(difference(q, corners[from]), side) / length2, 0.), 1.);
    const Vec3 off = difference(q, closest_on_segment(q, corners[from], corners[to]));
    if(dot(off, off) < nearest) {
      nearest = dot(off, off);
      weights = {{0, 0, 0}};
      weights[from] = 1 - t;
      weights[to] = t;
    }
  }
  return weights;
}

/// The barycentric coordinates of q, a point of the triangle of `corners`, as the
/// areas of the triangles q makes with each side over their sum. Hand-written where
/// CGAL has `Polygon_mesh_processing::locate_in_face()`: that asserts on a triangle
/// without area, and the zero-area triangles of insert_crease_triangles() are inputs
/// of remesh() by design (see weights_on_flat_triangle()).
inline std::array<double, 3> barycentric_weights(const Vec3& q, const std::array<Vec3, 3>& corners)
{
  const Vec3 normal = cross(difference(corners[1], corners[0]), difference(corners[2], corners[0]));
  auto area = [&q](const Vec3& x, const Vec3& y) {
    const Vec3 n = cross(difference(x, q), difference(y, q));
    return std::sqrt(dot(n, n));
  };
  const std::array<double, 3> areas = {area(corners[1], corners[2]), area(corners[2], corners[0]),
                                       area(corners[0], corners[1])};
  const double sum = areas[0] + areas[1] + areas[2];
  if(dot(normal, normal) == 0 || !(sum > 0) || !std::isfinite(sum))
    return weights_on_flat_triangle(q, corners);
  return {{areas[0] / sum, areas[1] / sum, areas[2] / sum}};
}

/// A point map that moves and scales the points of `vpm` into the cube [-1, 1]^3
/// (centre of the bounding box at the origin, the largest side scaled by a power of
/// two) and rounds them to multiples of 2^-60. The nearest-point search then never
/// squares a coordinate of 1e160 into infinity, nor multiplies differences of 1e-160
/// (or of points 1e-200 apart beside one at 1e200) into zero and divides by it: both
/// sent a non-finite number to its exact fallback predicates, which stop the process
/// (GMP raises SIGFPE). Rounding moves a point by at most 2^-61 of the box's side,
/// far below what an attribute's sampling can see.
template <class VertexPointMap, class Point>
struct Unit_cube_point_map
{
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;

  VertexPointMap vpm;
  Vec3 centre = {{0, 0, 0}};
  double scale = 1;

  Point operator()(const Vec3& p) const
  {
    auto on_grid = [this, &p](std::size_t d) {
      return std::ldexp(std::nearbyint(std::ldexp((p[d] - centre[d]) * scale, 60)), -60);
    };
    return Point(on_grid(0), on_grid(1), on_grid(2));
  }
  friend Point get(const Unit_cube_point_map& map, const key_type& key) { return map(to_vec3(get(map.vpm, key))); }
};

template <class Point, class TriangleMesh, class VertexPointMap>
Unit_cube_point_map<VertexPointMap, Point> unit_cube_point_map(const TriangleMesh& tm, VertexPointMap vpm)
{
  Vec3 lower = {{0, 0, 0}}, upper = {{0, 0, 0}};
  bool first = true;
  for(auto v : vertices(tm)) {
    const Vec3 p = to_vec3(get(vpm, v));
    for(std::size_t d = 0; d < 3; ++d) {
      lower[d] = first ? p[d] : (std::min)(lower[d], p[d]);
      upper[d] = first ? p[d] : (std::max)(upper[d], p[d]);
    }
    first = false;
  }
  Unit_cube_point_map<VertexPointMap, Point> map{vpm, {{0, 0, 0}}, 1};
  double side = 0;
  for(std::size_t d = 0; d < 3; ++d) {
    map.centre[d] = lower[d] / 2 + upper[d] / 2; // halves first: no overflow
    side = (std::max)(side, upper[d] / 2 - lower[d] / 2);
  }
  if(side > 0 && std::isfinite(side))
    map.scale = std::ldexp(1., -std::ilogb(side) - 1); // side * scale in [0.5, 1)
  return map;
}

/// Puts at every vertex of `out` the mix of the attributes' input values at the
/// nearest point of `tm` (its vertex points `vpm`) to the vertex's point (`out_vpm`).
template <class TriangleMesh, class VertexPointMap, class PolygonMesh, class OutVertexPointMap, class Attributes>
void sample_attributes_at_nearest_points(const TriangleMesh& tm, VertexPointMap vpm, const PolygonMesh& out,
                                         OutVertexPointMap out_vpm, const Attributes& attributes,
                                         const Progress& progress)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, Unit_cube_point_map<VertexPointMap, Point>>;
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Kernel, Primitive>>;
#else
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
#endif
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  if(num_faces(tm) == 0)
    return;
  const auto unit_vpm = unit_cube_point_map<Point>(tm, vpm);
  Tree tree(faces(tm).first, faces(tm).second, tm, unit_vpm);
  tree.accelerate_distance_queries();
  std::array<std::pair<vertex_descriptor, double>, 3> sources;
  std::size_t done = 0;
  for(auto v : vertices(out)) {
    progress.report_every(Remeshing_stage::RELAXATION, done++, num_vertices(out));
    const auto nearest = tree.closest_point_and_primitive(unit_vpm(to_vec3(get(out_vpm, v))));
    const auto h = halfedge(nearest.second, tm);
    const std::array<vertex_descriptor, 3> corners = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
    const std::array<double, 3> weights =
        barycentric_weights(to_vec3(nearest.first), {{to_vec3(get(unit_vpm, corners[0])),
                                                      to_vec3(get(unit_vpm, corners[1])),
                                                      to_vec3(get(unit_vpm, corners[2]))}});
    for(int i = 0; i < 3; ++i)
      sources[i] = {corners[i], weights[i]};
    attributes.put_mixed(v, sources);
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H
