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
// input (Nearest_face_search.h finds it and its face).

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Nearest_face_search.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_attributes.h>

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The weights of q, the point nearest to it on a triangle of `corners`, on the side
/// nearest to it (those of its foot there, between the side's ends), and the squared
/// distance from q to that foot; the first corner's if the corners coincide.
inline std::array<double, 3> weights_on_nearest_side(const Vec3& q, const std::array<Vec3, 3>& corners,
                                                     double& squared_distance)
{
  std::array<double, 3> weights = {{1, 0, 0}};
  const Vec3 off_first = difference(q, corners[0]);
  squared_distance = dot(off_first, off_first);
  for(std::size_t i = 0; i < 3; ++i) {
    const std::size_t from = (i + 1) % 3, to = (i + 2) % 3; // the side opposite corner i
    const Vec3 side = difference(corners[to], corners[from]);
    const double length2 = dot(side, side);
    if(!(length2 > 0))
      continue;
    const double t = (std::min)((std::max)(dot(difference(q, corners[from]), side) / length2, 0.), 1.);
    Vec3 foot;
    for(std::size_t d = 0; d < 3; ++d)
      foot[d] = corners[from][d] + t * side[d];
    const Vec3 off = difference(q, foot);
    if(dot(off, off) < squared_distance) {
      squared_distance = dot(off, off);
      weights = {{0, 0, 0}};
      weights[from] = 1 - t;
      weights[to] = t;
    }
  }
  return weights;
}

/// The weights of q, a point of the triangle of `corners`: its barycentric coordinates
/// as the areas of the triangles q makes with each side over their sum, unless the
/// weights of the nearest side give back q more closely. On a flat triangle (corners
/// on one line: a crease's copies, a split edge) the areas are rounding noise, and
/// the unsigned areas of a point beside a needle do not give it back: the side does.
/// Hand-written where CGAL has `Polygon_mesh_processing::locate_in_face()`: that
/// asserts on a triangle without area, and the zero-area triangles of
/// insert_crease_triangles() are inputs of remesh() by design.
inline std::array<double, 3> barycentric_weights(const Vec3& q, const std::array<Vec3, 3>& corners)
{
  double side_error = 0;
  const std::array<double, 3> on_side = weights_on_nearest_side(q, corners, side_error);
  auto area = [&q](const Vec3& x, const Vec3& y) {
    const Vec3 n = cross(difference(x, q), difference(y, q));
    return std::sqrt(dot(n, n));
  };
  const std::array<double, 3> areas = {area(corners[1], corners[2]), area(corners[2], corners[0]),
                                       area(corners[0], corners[1])};
  const double sum = areas[0] + areas[1] + areas[2];
  if(!(sum > 0) || !std::isfinite(sum))
    return on_side;
  const std::array<double, 3> by_area = {{areas[0] / sum, areas[1] / sum, areas[2] / sum}};
  Vec3 back = {{0, 0, 0}};
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t d = 0; d < 3; ++d)
      back[d] += by_area[i] * corners[i][d];
  const Vec3 off = difference(back, q);
  return dot(off, off) <= side_error ? by_area : on_side;
}

/// The weights of q, a point of the line of the corners of a face without area: those
/// of the two corners next to each other along the line between which it lies, so that
/// a corner in the middle (a split edge's, a crease's copy) keeps its own values.
inline std::array<double, 3> weights_along_line(const Vec3& q, const std::array<Vec3, 3>& corners)
{
  const std::size_t from = longest_side_start(corners); // the line's direction
  const Vec3 axis = difference(corners[(from + 1) % 3], corners[from]);
  std::array<double, 3> weights = {{1, 0, 0}};
  if(!(dot(axis, axis) > 0))
    return weights;
  std::array<double, 3> at; // the corners' positions along the line
  for(std::size_t i = 0; i < 3; ++i)
    at[i] = dot(difference(corners[i], corners[from]), axis);
  std::array<std::size_t, 3> order = {{0, 1, 2}};
  std::sort(order.begin(), order.end(), [&at](std::size_t i, std::size_t j) { return at[i] < at[j]; });
  const double s = dot(difference(q, corners[from]), axis);
  const std::size_t low = s <= at[order[1]] ? order[0] : order[1], high = s <= at[order[1]] ? order[1] : order[2];
  const double span = at[high] - at[low];
  const double t = span > 0 ? (std::min)((std::max)((s - at[low]) / span, 0.), 1.) : 0.;
  weights = {{0, 0, 0}};
  weights[low] = 1 - t;
  weights[high] += t;
  return weights;
}

/// The points of `vpm` in double precision, scaled by a power of two so that the
/// largest coordinate is at most 1, for the nearest-point search. In a kernel of plain
/// doubles (`Simple_cartesian<double>`): the search need not be exact (it picks where
/// an attribute is sampled), and the exact fallback of a filtered kernel's predicates
/// stops the process (GMP raises SIGFPE) on the non-finite numbers that squares of
/// coordinates of 1e160 give. A power of two scales every point exactly, keeping the
/// precision of a small part beside a far one (a translation to the box's centre
/// would not, nor would a coarse grid: a part 1e-30 of the box across collapsed).
template <class VertexPointMap>
struct Scaled_point_map
{
  using Point = typename CGAL::Simple_cartesian<double>::Point_3;
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;

  VertexPointMap vpm;
  int exponent = 0; // points are multiplied by 2^exponent

  Point operator()(const Vec3& p) const
  {
    // below 2^-197 of the largest, onto multiples of 2^-250: a product of four
    // differences of coordinates never underflows (a speck 1e-200 beside the rest
    // gave 0 / 0), and nothing larger moves
    auto scaled = [this](double x) { return std::ldexp(std::nearbyint(std::ldexp(x, exponent + 250)), -250); };
    return Point(scaled(p[0]), scaled(p[1]), scaled(p[2]));
  }
  friend Point get(const Scaled_point_map& map, const key_type& key) { return map(to_vec3(get(map.vpm, key))); }
};

template <class TriangleMesh, class VertexPointMap>
Scaled_point_map<VertexPointMap> scaled_point_map(const TriangleMesh& tm, VertexPointMap vpm)
{
  double largest = 0;
  for(auto v : vertices(tm)) {
    const Vec3 p = to_vec3(get(vpm, v));
    largest = (std::max)({largest, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  }
  Scaled_point_map<VertexPointMap> map{vpm, 0};
  if(largest > 0 && std::isfinite(largest))
    map.exponent = -std::ilogb(largest) - 1; // largest * 2^exponent in [0.5, 1)
  return map;
}

/// Throws Remeshing_error (bad input) if a vertex of `tm` has all its edges shorter
/// than 2^-220 of the input's largest coordinate (after scaled_point_map()), without
/// being of length 0: the rounding onto multiples of 2^-250 would move the points of
/// such a feature (a part 1e-66 of the box across, the rest beside a vertex at 1e200)
/// by more than 2^-30 of its size, and below that collapse it, so that its values were
/// another part's. One short edge among longer ones is sampled: its faces, flat at that
/// scale, are searched as segments, and its ends keep the values of their neighbours.
template <class TriangleMesh, class PointMap>
void check_scale_range(const TriangleMesh& tm, const PointMap& scaled)
{
  const double smallest = std::ldexp(1., -220);
  for(auto v : vertices(tm)) {
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      continue;
    const Vec3 p = to_vec3(get(scaled.vpm, v));
    double star = 0; // the longest edge at v, in units of the largest coordinate
    for(auto h : halfedges_around_target(v, tm)) {
      const Vec3 d = difference(p, to_vec3(get(scaled.vpm, source(h, tm))));
      star = (std::max)({star, std::ldexp((std::max)({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])}),
                                          scaled.exponent)});
    }
    if(star > 0 && star < smallest)
      throw Remeshing_error("the input has a feature smaller than 2^-220 (about 6e-67) of its largest coordinate "
                            "(all edges at a vertex): its vertex attributes cannot be sampled there",
                            Remeshing_error::Kind::BAD_INPUT);
  }
}

/// check_scale_range() on `tm` at the points of `vpm`: whether the vertex attributes
/// can be sampled, asked before the remesh so that a refusal comes before its work.
template <class TriangleMesh, class VertexPointMap>
void check_attributes_can_be_sampled(const TriangleMesh& tm, VertexPointMap vpm)
{
  check_scale_range(tm, scaled_point_map(tm, vpm));
}

/// Puts at every vertex of `out` the mix of the attributes' input values at the
/// nearest point of `tm` (its vertex points `vpm`) to the vertex's point (`out_vpm`).
/// `tm` passed check_attributes_can_be_sampled().
template <class TriangleMesh, class VertexPointMap, class PolygonMesh, class OutVertexPointMap, class Attributes>
void sample_attributes_at_nearest_points(const TriangleMesh& tm, VertexPointMap vpm, const PolygonMesh& out,
                                         OutVertexPointMap out_vpm, const Attributes& attributes,
                                         const Progress& progress)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Scaled = Scaled_point_map<VertexPointMap>;
  if(faces(tm).empty())
    return;
  const Scaled scaled_vpm = scaled_point_map(tm, vpm);
  const Nearest_face_search<TriangleMesh, Scaled> search(tm, scaled_vpm, num_vertices(out));
  std::array<std::pair<vertex_descriptor, double>, 3> sources;
  std::size_t done = 0, hint = 0;
  for(auto v : vertices(out)) {
    progress.report_every(Remeshing_stage::RELAXATION, done++, num_vertices(out));
    const auto hit = search.nearest(to_vec3(scaled_vpm(to_vec3(get(out_vpm, v)))), hint);
    hint = hit.number;
    const auto h = halfedge(hit.face, tm);
    const std::array<vertex_descriptor, 3> corners = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
    const std::array<Vec3, 3> at = Searched_faces<TriangleMesh, Scaled>::corners(hit.face, tm, scaled_vpm);
    const std::array<double, 3> weights = hit.flat ? weights_along_line(hit.point, at) : barycentric_weights(hit.point, at);
    for(int i = 0; i < 3; ++i)
      sources[i] = {corners[i], weights[i]};
    attributes.put_mixed(v, sources);
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H
