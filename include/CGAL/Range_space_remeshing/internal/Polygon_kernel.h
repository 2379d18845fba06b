// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_KERNEL_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_KERNEL_H

// The kernel of a primal face's polygon (the points that see all of it): where its dual
// vertex must lie for the dual quads around the face not to cross the gap of a notch.

#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

using Vec2 = std::array<double, 2>;

inline double cross_2(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// Cuts the convex polygon `convex` down to its part left of the line a -> b.
inline void keep_left_of(std::vector<Vec2>& convex, const Vec2& a, const Vec2& b, std::vector<Vec2>& scratch)
{
  scratch.clear();
  for(std::size_t i = 0; i < convex.size(); ++i) {
    const Vec2& p = convex[i];
    const Vec2& q = convex[(i + 1) % convex.size()];
    const double sp = cross_2(a, b, p), sq = cross_2(a, b, q);
    if(sp >= 0)
      scratch.push_back(p);
    if((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
      const double t = sp / (sp - sq);
      scratch.push_back(Vec2{{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
    }
  }
  convex.swap(scratch);
}

/// The point of the convex polygon `convex` (counter-clockwise) closest to x.
inline Vec2 closest_in_convex(const std::vector<Vec2>& convex, const Vec2& x)
{
  bool inside = true;
  for(std::size_t i = 0; i < convex.size() && inside; ++i)
    inside = cross_2(convex[i], convex[(i + 1) % convex.size()], x) >= 0;
  if(inside)
    return x;
  Vec2 best = convex.front();
  double best_d2 = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < convex.size(); ++i) {
    const Vec2& a = convex[i];
    const Vec2& b = convex[(i + 1) % convex.size()];
    const Vec2 ab = {{b[0] - a[0], b[1] - a[1]}};
    const double length2 = ab[0] * ab[0] + ab[1] * ab[1];
    double t = length2 > 0 ? ((x[0] - a[0]) * ab[0] + (x[1] - a[1]) * ab[1]) / length2 : 0.;
    t = (std::min)((std::max)(t, 0.), 1.);
    const Vec2 c = {{a[0] + t * ab[0], a[1] + t * ab[1]}};
    const double d2 = (x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]);
    if(d2 < best_d2) {
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

/// x moved, parallel to the polygon's mean plane, to the nearest point of the polygon's
/// kernel seen along its Newell normal: the primal face seen from there has no corner
/// hiding another, so its dual vertex joined to its neighbours' stays over the face. An
/// L-shaped face (where a crease turns a corner, say) has its kernel near the inner
/// corner, while its mass point, or the quadric's minimiser, may lie over the notch. x is
/// returned as it is if the polygon has no area or no kernel (a folded polygon).
inline Vec3 into_polygon_kernel(const std::vector<Vec3>& polygon, const Vec3& x)
{
  const Vec3 n = normalized(newell_normal(polygon));
  if(polygon.size() < 3 || n == Vec3{{0, 0, 0}})
    return x;
  const Vec3 e1 = any_orthogonal(n), e2 = cross(n, e1);
  const Vec3& origin = polygon.front(); // coordinates relative to it: no cancellation
  auto flat = [&](const Vec3& p) {
    const Vec3 d = difference(p, origin);
    return Vec2{{dot(d, e1), dot(d, e2)}};
  };
  std::vector<Vec2> corners(polygon.size());
  Vec2 low = {{0, 0}}, high = {{0, 0}};
  for(std::size_t i = 0; i < polygon.size(); ++i) {
    corners[i] = flat(polygon[i]);
    for(int d = 0; d < 2; ++d) {
      low[d] = (std::min)(low[d], corners[i][d]);
      high[d] = (std::max)(high[d], corners[i][d]);
    }
  }
  std::vector<Vec2> kernel = {low, {{high[0], low[1]}}, high, {{low[0], high[1]}}}, scratch;
  for(std::size_t i = 0; i < corners.size() && !kernel.empty(); ++i)
    keep_left_of(kernel, corners[i], corners[(i + 1) % corners.size()], scratch);
  if(kernel.size() < 3)
    return x;
  const Vec2 x_flat = flat(x);
  const Vec2 y = closest_in_convex(kernel, x_flat);
  if(y == x_flat)
    return x;
  Vec3 moved = x;
  for(int d = 0; d < 3; ++d)
    moved[d] += (y[0] - x_flat[0]) * e1[d] + (y[1] - x_flat[1]) * e2[d];
  return moved;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_KERNEL_H
