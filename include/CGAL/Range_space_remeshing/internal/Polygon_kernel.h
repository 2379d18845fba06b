// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_KERNEL_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_KERNEL_H

// The kernel of a primal face's polygon (the points that see all of it): where its dual
// vertex must lie for the dual quads around the face not to cross the gap of a notch.

#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

// The polygon is flattened to coordinates (u, v, 0) in its mean plane, so that the
// 3-vector helpers serve: the turn of a -> b -> c is the third coordinate of a cross
// product.
inline double turn(const Vec3& a, const Vec3& b, const Vec3& c) { return cross(difference(b, a), difference(c, a))[2]; }

/// Cuts the flat convex polygon `convex` down to its part left of the line a -> b.
inline void keep_left_of(std::vector<Vec3>& convex, const Vec3& a, const Vec3& b, std::vector<Vec3>& scratch)
{
  scratch.clear();
  for(std::size_t i = 0; i < convex.size(); ++i) {
    const Vec3& p = convex[i];
    const Vec3& q = convex[next_corner(i, convex.size())];
    const double sp = turn(a, b, p), sq = turn(a, b, q);
    if(sp >= 0)
      scratch.push_back(p);
    if((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
      const double t = sp / (sp - sq);
      scratch.push_back(Vec3{{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), 0}});
    }
  }
  convex.swap(scratch);
}

/// The point of the polygon's sides closest to x.
inline Vec3 closest_on_sides(const std::vector<Vec3>& polygon, const Vec3& x)
{
  Vec3 best = polygon.front();
  double best_d2 = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 c = closest_on_segment(x, polygon[i], polygon[next_corner(i, polygon.size())]);
    const double d2 = dot(difference(x, c), difference(x, c));
    if(d2 < best_d2) {
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

/// The point of the flat convex polygon `convex` (counter-clockwise) closest to x.
inline Vec3 closest_in_convex(const std::vector<Vec3>& convex, const Vec3& x)
{
  bool inside = true;
  for(std::size_t i = 0; i < convex.size() && inside; ++i)
    inside = turn(convex[i], convex[next_corner(i, convex.size())], x) >= 0;
  return inside ? x : closest_on_sides(convex, x);
}

/// Whether the polygon, whose Newell normal is `normal`, encloses nothing: it lies on a
/// line, or is a tree of segments (as where opened creases meet), each of its sides
/// gone over again by another. It has no net area (`has_no_net_area()`), and the
/// midpoint of every side lies on another side (up to `no_area_ratio` of the longest);
/// a folded polygon whose two lobes cancel, a bow tie, has the first property only.
inline bool encloses_nothing(const std::vector<Vec3>& polygon, const Vec3& normal)
{
  if(!has_no_net_area(polygon, normal))
    return false;
  const double tolerance2 = no_area_ratio * no_area_ratio * longest_side_squared(polygon);
  const std::size_t n = polygon.size();
  for(std::size_t i = 0; i < n; ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[next_corner(i, n)];
    const Vec3 mid = {{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}};
    bool retraced = false;
    for(std::size_t j = 0; j < n && !retraced; ++j) {
      if(j == i)
        continue;
      const Vec3 c = closest_on_segment(mid, polygon[j], polygon[next_corner(j, n)]);
      retraced = dot(difference(mid, c), difference(mid, c)) <= tolerance2;
    }
    if(!retraced)
      return false;
  }
  return true;
}

/// x moved, parallel to the polygon's mean plane, to the nearest point of the polygon's
/// kernel seen along its Newell normal: the primal face seen from there has no corner
/// hiding another, so its dual vertex joined to its neighbours' stays over the face. An
/// L-shaped face (where a crease turns a corner, say) has its kernel near the inner
/// corner, while its mass point, or the quadric's minimiser, may lie over the notch. A
/// polygon that encloses nothing (`encloses_nothing()`: a segment, or a tree of segments
/// where opened creases meet) is made of its sides: x goes to the nearest point of a
/// side. x is returned as it is if the polygon has no kernel (a folded polygon) or no
/// plane (no net area, rounding for a normal). `area` is the polygon's Newell normal.
inline Vec3 into_polygon_kernel(const std::vector<Vec3>& polygon, const Vec3& area, const Vec3& x)
{
  if(polygon.empty())
    return x;
  if(polygon.size() < 3 || encloses_nothing(polygon, area))
    return closest_on_sides(polygon, x);
  if(has_no_net_area(polygon, area))
    return x;
  const Vec3 n = normalized(area);
  if(n == Vec3{{0, 0, 0}})
    return x; // not finite
  const Vec3 e1 = any_orthogonal(n), e2 = cross(n, e1);
  const Vec3& origin = polygon.front(); // coordinates relative to it: no cancellation
  auto flat = [&](const Vec3& p) {
    const Vec3 d = difference(p, origin);
    return Vec3{{dot(d, e1), dot(d, e2), 0}};
  };
  std::vector<Vec3> corners(polygon.size());
  Vec3 low = {{0, 0, 0}}, high = {{0, 0, 0}};
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    corners[i] = flat(polygon[i]);
    for(int d = 0; d < 2; ++d) {
      low[d] = (std::min)(low[d], corners[i][d]);
      high[d] = (std::max)(high[d], corners[i][d]);
    }
  }
  std::vector<Vec3> kernel = {low, {{high[0], low[1], 0}}, high, {{low[0], high[1], 0}}}, scratch;
  for(std::size_t i = 0; i < corners.size() && !kernel.empty(); ++i)
    keep_left_of(kernel, corners[i], corners[next_corner(i, corners.size())], scratch);
  if(kernel.size() < 3)
    return x;
  const Vec3 x_flat = flat(x);
  const Vec3 y = closest_in_convex(kernel, x_flat);
  if(y == x_flat)
    return x;
  Vec3 moved = x;
  for(int d = 0; d < 3; ++d)
    moved[d] += (y[0] - x_flat[0]) * e1[d] + (y[1] - x_flat[1]) * e2[d];
  return moved;
}

inline Vec3 into_polygon_kernel(const std::vector<Vec3>& polygon, const Vec3& x)
{
  return into_polygon_kernel(polygon, newell_normal(polygon), x);
}

/// The dual vertex of a primal face whose corners are `polygon`, on a surface whose
/// normal there is `surface_normal` (the sum of the corners'), from the minimiser x of
/// its planes: x moved into the polygon's kernel (`into_polygon_kernel()`), but where
/// the polygon turns against the surface, the corner nearest to x. Such a polygon is
/// that of a face around a concave corner where opened creases meet: the face spans
/// three quarters of a turn of a side around the corner, its corners lie on the two
/// creases and at the corner, and their polygon, the remaining quarter, is the notch.
inline Vec3 into_face(const std::vector<Vec3>& polygon, const Vec3& surface_normal, const Vec3& x)
{
  const Vec3 area = newell_normal(polygon); // computed once, for both tests
  if(polygon.size() >= 3 && dot(area, surface_normal) < 0) {
    Vec3 nearest = polygon.front();
    for(const Vec3& corner : polygon)
      if(dot(difference(corner, x), difference(corner, x)) < dot(difference(nearest, x), difference(nearest, x)))
        nearest = corner;
    return nearest;
  }
  return into_polygon_kernel(polygon, area, x);
}

/// Whether the points of the tangent planes (three or more), in order, are the corners
/// of a polygon that encloses nothing (`encloses_nothing()`): those of the dual vertex
/// of a primal face inside the zero-area strips of opened creases, or where such strips
/// meet. `scratch` keeps its memory from call to call.
template <class PlaneRange>
bool planes_of_face_without_area(const PlaneRange& planes, std::vector<Vec3>& scratch)
{
  scratch.clear();
  for(const auto& plane : planes)
    scratch.push_back(plane.first);
  return scratch.size() >= 3 && encloses_nothing(scratch, newell_normal(scratch));
}

/// Where a collapse puts vertices a and c (at `pa` and `pc`, with tangent planes
/// `planes_a` and `planes_c`) if either lies on a primal face that encloses nothing (on
/// an opened crease): such a vertex keeps its place, as in the relaxation, because the
/// midpoint of it and a vertex on another crease, or on a side, may lie in the notch
/// between them, off the surface; two such vertices go to the point of their faces'
/// sides nearest to `merged`, their midpoint on input. Returns false, `merged`
/// untouched, if neither does. `scratch_a` and `scratch_c` keep their memory.
template <class PlaneRange>
bool merged_on_creases(const PlaneRange& planes_a, const Vec3& pa, const PlaneRange& planes_c, const Vec3& pc,
                       Vec3& merged, std::vector<Vec3>& scratch_a, std::vector<Vec3>& scratch_c)
{
  const bool a_on_crease = planes_of_face_without_area(planes_a, scratch_a);
  const bool c_on_crease = planes_of_face_without_area(planes_c, scratch_c);
  if(a_on_crease != c_on_crease) {
    merged = a_on_crease ? pa : pc;
    return true;
  }
  if(!a_on_crease)
    return false;
  const Vec3 on_a = closest_on_sides(scratch_a, merged), on_c = closest_on_sides(scratch_c, merged);
  const Vec3 to_a = difference(on_a, merged), to_c = difference(on_c, merged);
  merged = dot(to_a, to_a) <= dot(to_c, to_c) ? on_a : on_c;
  return true;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_KERNEL_H
