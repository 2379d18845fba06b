// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_VEC3_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_VEC3_H

// Small 3-vector helpers (std::array<double, 3>) that the placement, the
// relaxation, the collapse and the output writers share.

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

using Vec3 = std::array<double, 3>;

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

template <class Point>
Vec3 to_vec3(const Point& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

/// (lets maps and normals be given as std::array as well as CGAL points and vectors)
inline Vec3 to_vec3(const Vec3& v) { return v; }

/// normalized() of a vector whose squared length under- or overflows: scaled by its
/// largest component first. Out of line, so that normalized() itself inlines.
#if defined(__GNUC__)
__attribute__((noinline))
#endif
inline Vec3 normalized_with_rescaling(const Vec3& v)
{
  if(!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    return Vec3{{0, 0, 0}};
  const double largest = (std::max)({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  if(!(largest > 0))
    return Vec3{{0, 0, 0}};
  const Vec3 w = {{v[0] / largest, v[1] / largest, v[2] / largest}};
  const double length = std::sqrt(dot(w, w));
  return Vec3{{w[0] / length, w[1] / length, w[2] / length}};
}

/// v / |v|, or the zero vector if v is zero or not finite. Neither tiny nor huge
/// vectors (input coordinates of 1e200) under- or overflow in the squared length.
inline Vec3 normalized(const Vec3& v)
{
  // common case: the squared length neither underflows nor overflows, one division
  const double squared = dot(v, v);
  if(squared > 1e-280 && squared < 1e280) {
    const double inverse_length = 1 / std::sqrt(squared);
    return Vec3{{v[0] * inverse_length, v[1] * inverse_length, v[2] * inverse_length}};
  }
  return normalized_with_rescaling(v);
}

/// The sum of the normals of a range of tangent planes (point, normal), not normalised.
template <class PlaneRange>
Vec3 average_normal(const PlaneRange& planes)
{
  Vec3 sum = {{0, 0, 0}};
  for(const auto& plane : planes)
    for(int d = 0; d < 3; ++d)
      sum[d] += plane.second[d];
  return sum;
}

inline Vec3 difference(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }

/// x multiplied by 2^exponent, exactly where the result is a normal number (the
/// factor itself may be beyond doubles: 2^1070 brings subnormal offsets to unit size).
inline Vec3 scaled_by_power_of_two(Vec3 x, int exponent)
{
  if(exponent != 0)
    for(double& c : x)
      c = std::ldexp(c, exponent);
  return x;
}

/// The point of segment [a, b] closest to x (a, if the segment is a point).
inline Vec3 closest_on_segment(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = difference(b, a);
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? (std::min)((std::max)(dot(difference(x, a), ab) / length2, 0.), 1.) : 0.;
  return {{a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]}};
}

inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// A unit vector orthogonal to the unit vector n.
inline Vec3 any_orthogonal(const Vec3& n)
{
  // cross n with the axis it is least aligned with: never nearly parallel
  const int axis = std::abs(n[0]) <= std::abs(n[1]) ? (std::abs(n[0]) <= std::abs(n[2]) ? 0 : 2)
                                                    : (std::abs(n[1]) <= std::abs(n[2]) ? 1 : 2);
  Vec3 e = {{0, 0, 0}};
  e[axis] = 1;
  return normalized(cross(n, e));
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_VEC3_H
