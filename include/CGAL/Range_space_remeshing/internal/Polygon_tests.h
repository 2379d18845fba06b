// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_TESTS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_TESTS_H

// Tests of small 3-D polygons (corners in order): Newell normal, net area,
// convexity, fan orientation.

#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The corner after corner i of a polygon of n corners, and the one before it. Not
/// (i + 1) % n: the polygon tests run at every corner of every face the collapse and
/// the relaxation try, and an integer division there costs more than the test's
/// arithmetic.
inline std::size_t next_corner(std::size_t i, std::size_t n) { return i + 1 < n ? i + 1 : 0; }
inline std::size_t previous_corner(std::size_t i, std::size_t n) { return i > 0 ? i - 1 : n - 1; }

/// Twice the vector area of a polygon (Newell's normal), summed over the fan from its
/// first corner: Newell's own sums of coordinates lose the area to cancellation when
/// the polygon is small against its distance to the origin.
inline Vec3 newell_normal(const std::vector<Vec3>& polygon)
{
  Vec3 n = {{0, 0, 0}};
  for(std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec3 fan = cross(difference(polygon[i], polygon[0]), difference(polygon[i + 1], polygon[0]));
    for(int d = 0; d < 3; ++d)
      n[d] += fan[d];
  }
  return n;
}

/// A polygon whose net area is below this fraction of its longest side squared has
/// none: up to rounding (or so nearly that its plane means nothing), as the corners of
/// the primal faces inside the zero-area strips of opened creases do. Its Newell normal
/// is then rounding error, whose direction must decide nothing.
constexpr double no_area_ratio = 1e-9;

/// The longest side of the polygon, squared.
inline double longest_side_squared(const std::vector<Vec3>& polygon)
{
  double longest = 0;
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 side = difference(polygon[next_corner(i, polygon.size())], polygon[i]);
    longest = (std::max)(longest, dot(side, side));
  }
  return longest;
}

/// Whether the polygon, whose Newell normal (twice its vector area) is `normal`, has
/// no net area (see `no_area_ratio`): it lies on a line, or is a tree of segments, or
/// folds so that its lobes cancel.
inline bool has_no_net_area(const std::vector<Vec3>& polygon, const Vec3& normal)
{
  return std::sqrt(dot(normal, normal)) <= 2 * no_area_ratio * longest_side_squared(polygon);
}

/// Whether a polygon of n corners, corner i being `corner(i)`, turns left at every
/// corner, seen from the side of `normal`: the one corner test of the collapse, the
/// relaxation and the untangling, which hold their polygons in different containers.
template <class Corner>
bool turns_left_at_every_corner(std::size_t n, const Corner& corner, const Vec3& normal)
{
  for(std::size_t i = 0; i < n; ++i) {
    const Vec3& p = corner(previous_corner(i, n));
    const Vec3& q = corner(i);
    const Vec3& r = corner(next_corner(i, n));
    if(!(dot(cross(difference(q, p), difference(r, q)), normal) > 0))
      return false;
  }
  return true;
}

/// Whether the polygon turns left at every corner, seen from the side of `normal`.
inline bool is_convex(const std::vector<Vec3>& polygon, const Vec3& normal)
{
  return turns_left_at_every_corner(polygon.size(), [&](std::size_t i) -> const Vec3& { return polygon[i]; },
                                    normal);
}

/// Whether every triangle of the fan from the polygon's first corner turns left, seen
/// from the side of `normal`.
inline bool fan_turns_with(const std::vector<Vec3>& polygon, const Vec3& normal)
{
  const Vec3& apex = polygon.front();
  for(std::size_t i = 1; i + 1 < polygon.size(); ++i)
    if(!(dot(cross(difference(polygon[i], apex), difference(polygon[i + 1], apex)), normal) > 0))
      return false;
  return true;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_TESTS_H
