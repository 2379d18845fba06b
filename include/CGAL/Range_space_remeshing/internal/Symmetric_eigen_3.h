// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_SYMMETRIC_EIGEN_3_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_SYMMETRIC_EIGEN_3_H

// The eigen-decomposition of a symmetric 3x3 matrix, in closed form.

#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

using Matrix3 = std::array<std::array<double, 3>, 3>;

/// The unit eigenvector of the symmetric m for its simple eigenvalue `lambda`: the
/// longest cross product of two rows of m - lambda I, whose rank is 2.
inline Vec3 simple_eigenvector(const Matrix3& m, double lambda)
{
  const Vec3 r0 = {{m[0][0] - lambda, m[0][1], m[0][2]}}, r1 = {{m[1][0], m[1][1] - lambda, m[1][2]}},
             r2 = {{m[2][0], m[2][1], m[2][2] - lambda}};
  const Vec3 candidates[3] = {cross(r0, r1), cross(r0, r2), cross(r1, r2)};
  int best = 0;
  for(int k = 1; k < 3; ++k)
    if(dot(candidates[k], candidates[k]) > dot(candidates[best], candidates[best]))
      best = k;
  return normalized(candidates[best]);
}

/// Eigen-decomposition of a symmetric 3x3 matrix: a = sum_k values[k] vectors[k]
/// vectors[k]^T, vectors orthonormal. The eigenvalues in closed form (the
/// trigonometric solution of the characteristic cubic); the one farthest from the
/// middle one is simple, with a gap of at least 1.5 p (p: the deviation from a multiple
/// of the identity), so its vector from cross products is accurate; the other two by one
/// exact Jacobi rotation in the plane orthogonal to it, which stays accurate when they
/// are (nearly) equal; faster than cyclic Jacobi sweeps from a guessed normal
/// (benchmark/RESULTS.md).
inline void symmetric_eigen_3(const Matrix3& a, Vec3& values, std::array<Vec3, 3>& vectors)
{
  vectors = {{{{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}}};
  values = {{a[0][0], a[1][1], a[2][2]}};
  double scale = 0; // the largest entry: the scaled matrix neither under- nor overflows
  for(const auto& row : a)
    for(double x : row)
      scale = (std::max)(scale, std::abs(x));
  if(!(scale > 0) || !std::isfinite(scale))
    return;
  Matrix3 m;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      m[i][j] = a[i][j] / scale;
  const double q = (m[0][0] + m[1][1] + m[2][2]) / 3;
  const Vec3 deviation = {{m[0][0] - q, m[1][1] - q, m[2][2] - q}};
  const double p2 = dot(deviation, deviation) + 2 * (m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2]);
  if(p2 < 1e-28) // a multiple of the identity, up to rounding: any basis will do
    return;
  const double p = std::sqrt(p2 / 6);
  Matrix3 b; // (m - q I) / p, whose eigenvalues are 2 cos(phi + 2 k pi / 3)
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
      b[i][j] = (m[i][j] - (i == j ? q : 0.)) / p;
  const double half_det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                           b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                           b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0])) / 2;
  const double phi = std::acos((std::max)(-1., (std::min)(1., half_det))) / 3; // in [0, pi/3]
  const double cos_phi = std::cos(phi), sin_phi = std::sqrt((std::max)(0., 1 - cos_phi * cos_phi));
  const double largest = q + 2 * p * cos_phi;
  const double smallest = q - p * (cos_phi + std::sqrt(3.) * sin_phi); // q + 2 p cos(phi + 2 pi / 3)
  const double middle = 3 * q - largest - smallest;
  const Vec3 v = simple_eigenvector(m, largest - middle >= middle - smallest ? largest : smallest);
  const Vec3 t1 = any_orthogonal(v), t2 = cross(v, t1);
  auto form = [&m](const Vec3& x, const Vec3& y) {
    return x[0] * dot(m[0], y) + x[1] * dot(m[1], y) + x[2] * dot(m[2], y);
  };
  const double a11 = form(t1, t1), a12 = form(t1, t2), a22 = form(t2, t2);
  double c = 1, s = 0, t = 0; // the rotation that zeroes a12
  if(a12 != 0) {
    const double theta = (a22 - a11) / (2 * a12);
    t = (theta >= 0 ? 1. : -1.) / (std::abs(theta) + std::sqrt(theta * theta + 1));
    c = 1 / std::sqrt(t * t + 1);
    s = t * c;
  }
  values = {{form(v, v) * scale, (a11 - t * a12) * scale, (a22 + t * a12) * scale}};
  for(int i = 0; i < 3; ++i) {
    vectors[0][i] = v[i];
    vectors[1][i] = c * t1[i] - s * t2[i];
    vectors[2][i] = s * t1[i] + c * t2[i];
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_SYMMETRIC_EIGEN_3_H
