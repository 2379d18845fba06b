// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUADRIC_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUADRIC_H
// The quadric error of a set of tangent planes (p_i, n_i): Q(x) = sum <n_i, x - p_i>^2,
// its robust minimiser (dual contouring's truncated pseudo-inverse around the mass
// point), and its minimiser on a line (the paper's relaxation projection).

#include <CGAL/Range_space_remeshing/internal/Polygon_tests.h>
#include <CGAL/Range_space_remeshing/internal/Symmetric_eigen_3.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Eigenvalues below this fraction of the largest count as free directions: the
/// normals of a smoothly curved piece spread a little, those of a crease a lot.
constexpr double quadric_truncation = 0.1;

/// Accumulates tangent planes; normals need not be unit (zero ones are ignored).
class Quadric
{
public:
  void add_plane(const Vec3& p, const Vec3& n)
  {
    const double length2 = dot(n, n);
    if(!(length2 > 0))
      return;
    const double d = dot(n, p) / length2; // unit normal u = n/|n|: u u^T, u u^T p
    for(int r = 0; r < 3; ++r) {
      for(int c = 0; c < 3; ++c)
        a_[r][c] += n[r] * n[c] / length2;
      b_[r] += n[r] * d;
    }
    ++planes_;
  }

  int number_of_planes() const { return planes_; }
  /// sum of u u^T over the unit normals u: what the decomposition depends on
  const Matrix3& matrix() const { return a_; }

  /// Minimiser of the quadric, regularised towards `mass_point`: directions whose
  /// eigenvalue is below `truncation` times the largest are left at the mass point
  /// (a flat region has one constrained direction, a crease two, a corner three).
  Vec3 minimiser(const Vec3& mass_point, double truncation = quadric_truncation) const;

  template <class PlaneRange>
  void add_planes(const PlaneRange& planes)
  {
    for(const auto& plane : planes)
      add_plane(plane.first, plane.second);
  }

private:
  Matrix3 a_ = {};
  Vec3 b_ = {};
  int planes_ = 0;

  friend struct Quadric_eigen;
};

/// A quadric's eigen-decomposition, done once for projections at several truncations.
struct Quadric_eigen
{
  explicit Quadric_eigen(const Quadric& q) : b(q.b_), planes(q.planes_)
  {
    if(planes > 0)
      symmetric_eigen_3(q.a_, values, vectors);
  }

  /// q's, with the eigenvalues and eigenvectors of q's matrix found earlier.
  Quadric_eigen(const Quadric& q, const Vec3& known_values, const std::array<Vec3, 3>& known_vectors)
      : b(q.b_), planes(q.planes_), values(known_values), vectors(known_vectors)
  {}

  Vec3 b;
  int planes;
  Vec3 values = {};
  std::array<Vec3, 3> vectors = {};
};

/// The bounding box (low, high) of the points of a non-empty range of planes.
template <class PlaneRange>
std::pair<Vec3, Vec3> points_box(const PlaneRange& planes)
{
  Vec3 low = planes.begin()->first, high = low;
  for(const auto& plane : planes)
    for(int d = 0; d < 3; ++d) {
      low[d] = (std::min)(low[d], plane.first[d]);
      high[d] = (std::max)(high[d], plane.first[d]);
    }
  return {low, high};
}

/// x clamped to the box (low, high).
inline Vec3 clamped_to_box(Vec3 x, const std::pair<Vec3, Vec3>& box)
{
  for(int d = 0; d < 3; ++d)
    x[d] = (std::min)((std::max)(x[d], box.first[d]), box.second[d]);
  return x;
}

/// Moves points to the nearest minimisers of a quadric, along the directions it
/// constrains and no other: onto the plane in a flat region, onto the line of a
/// crease, to the point of a corner. The eigen-decomposition is done once, so
/// projecting many points (one per relaxation iteration) costs a few dot products.
/// Directions whose eigenvalue is below `truncation` times the largest are free.
class Quadric_projection
{
public:
  Quadric_projection() = default; // projects nothing: every direction free

  Quadric_projection(const Quadric& q, double truncation) : Quadric_projection(Quadric_eigen(q), truncation) {}

  Quadric_projection(const Quadric_eigen& e, double truncation)
  {
    if(e.planes == 0)
      return;
    const double largest = std::max({std::abs(e.values[0]), std::abs(e.values[1]), std::abs(e.values[2])});
    for(int k = 0; k < 3; ++k) {
      if(!(largest > 0) || !(e.values[k] > truncation * largest))
        continue;
      // along v_k the quadric is values[k] (<v_k, x> - <v_k, b> / values[k])^2
      directions_[constrained_] = e.vectors[k];
      levels_[constrained_] = dot(e.vectors[k], e.b) / e.values[k];
      ++constrained_;
    }
  }

  int constrained_directions() const { return constrained_; }

  /// Moves x along the same constrained directions, to the least-squares fit of the
  /// planes weighted by closeness to x, where the quadric weighs them all alike. A
  /// tangent plane strays from a curved surface by about the curvature times the
  /// square of the distance to its point, so a plane whose point is at distance d
  /// gets weight 1 / (d^2 + s^2 / 20)^2 (inverse-variance weighting of that error;
  /// s^2 the planes' mean squared distance, so that no plane takes all the weight).
  /// Weights are relative to the largest, and at least a tenth: the system then
  /// stays as well-conditioned as the truncation made the quadric's. A corner (three
  /// directions) is the quadric's point, whatever the weights. The planes' normals
  /// must be unit vectors.
  template <class PlaneRange>
  Vec3 fit_nearest_planes(const Vec3& x, const PlaneRange& planes) const
  {
    if(constrained_ == 0 || constrained_ == 3)
      return (*this)(x);
    double sum_d2 = 0, least_d2 = std::numeric_limits<double>::infinity();
    std::size_t count = 0;
    for(const auto& plane : planes) {
      const Vec3 d = difference(plane.first, x);
      sum_d2 += dot(d, d);
      least_d2 = (std::min)(least_d2, dot(d, d));
      ++count;
    }
    const double softening = sum_d2 / double(count) / 20;
    // the weight over the largest, as a ratio that can neither overflow nor underflow
    auto relative_weight = [&](double d2) {
      const double r = (least_d2 + softening) / (d2 + softening);
      return r * r;
    };
    // normal equations in the coordinates t of x + t_0 e_0 + t_1 e_1
    double m[2][2] = {{0, 0}, {0, 0}}, rhs[2] = {0, 0};
    for(const auto& plane : planes) {
      const Vec3& n = plane.second;
      const Vec3 d = difference(plane.first, x);
      const double w = (std::max)(relative_weight(dot(d, d)), 0.1);
      const double a[2] = {dot(n, directions_[0]), constrained_ > 1 ? dot(n, directions_[1]) : 0.};
      const double offset = dot(n, d);
      for(int r = 0; r < constrained_; ++r) {
        rhs[r] += w * a[r] * offset;
        for(int c = 0; c < constrained_; ++c)
          m[r][c] += w * a[r] * a[c];
      }
    }
    double t[2] = {0, 0};
    if(constrained_ == 1) {
      if(!(m[0][0] > 0))
        return (*this)(x);
      t[0] = rhs[0] / m[0][0];
    } else {
      const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
      if(!(det > 1e-12 * m[0][0] * m[1][1]) || !std::isfinite(det))
        return (*this)(x); // no planes with a normal in one of the directions
      t[0] = (rhs[0] * m[1][1] - m[0][1] * rhs[1]) / det;
      t[1] = (m[0][0] * rhs[1] - m[1][0] * rhs[0]) / det;
    }
    Vec3 y = x;
    for(int k = 0; k < constrained_; ++k)
      for(int i = 0; i < 3; ++i)
        y[i] += t[k] * directions_[k][i];
    return y;
  }

  Vec3 operator()(const Vec3& x) const
  {
    Vec3 y = x;
    for(int k = 0; k < constrained_; ++k) {
      const double step = levels_[k] - dot(directions_[k], x);
      for(int i = 0; i < 3; ++i)
        y[i] += step * directions_[k][i];
    }
    return y;
  }

private:
  std::array<Vec3, 3> directions_ = {};
  std::array<double, 3> levels_ = {};
  int constrained_ = 0;
};

inline Vec3 Quadric::minimiser(const Vec3& mass_point, double truncation) const
{
  return Quadric_projection(*this, truncation)(mass_point);
}

/// Eigenvalues above this fraction of the largest may still be constrained directions:
/// where two creases meet at a corner, the planes of the points along them pin the
/// corner, but with an eigenvalue of a few hundredths only (where the normals of a
/// crease's points blend the normals of its two sides: no `vertex_crease_normal_map`).
constexpr double sharp_truncation = 0.001;

/// The bounding box of the planes' points, grown on each side by a hundredth of its
/// largest extent (rounding puts a corner that is one of the points just outside, and
/// the box of a flat face has no thickness). In position coordinates, that box
/// approximates the face's grid cell, dual contouring's bound for its vertex.
template <class PlaneRange>
std::pair<Vec3, Vec3> grown_points_box(const PlaneRange& planes)
{
  auto [low, high] = points_box(planes);
  const double margin = (std::max)({high[0] - low[0], high[1] - low[1], high[2] - low[2]}) / 100;
  for(int d = 0; d < 3; ++d) {
    low[d] -= margin;
    high[d] += margin;
  }
  return {low, high};
}

/// Whether x lies in the grown box of the planes' points (`grown_points_box()`).
template <class PlaneRange>
bool is_in_points_box(const Vec3& x, const PlaneRange& planes)
{
  if(planes.empty())
    return false;
  const auto [low, high] = grown_points_box(planes);
  for(int d = 0; d < 3; ++d)
    if(!(x[d] >= low[d] && x[d] <= high[d]))
      return false;
  return true;
}

/// The minimiser of the planes' quadric nearest to x that keeps sharp features: truncated
/// at `sharp_truncation` where that lands in the points' box (a corner or a crease line
/// that the planes pin), at `quadric_truncation` otherwise (the weak directions then
/// come from curvature or noise, and their minimiser lies outside), and then clamped
/// into the box: the planes around a convex corner of three opened creases can pin a
/// point beyond the corner, outside the solid.
template <class PlaneRange>
Vec3 sharp_feature_minimiser(const PlaneRange& planes, const Vec3& x)
{
  Quadric quadric;
  quadric.add_planes(planes);
  const Quadric_eigen eigen(quadric); // one decomposition for both truncations
  const Vec3 sharp = Quadric_projection(eigen, sharp_truncation)(x);
  if(is_in_points_box(sharp, planes))
    return sharp;
  const Vec3 fallback = Quadric_projection(eigen, quadric_truncation)(x);
  return planes.empty() ? fallback : clamped_to_box(fallback, grown_points_box(planes));
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUADRIC_H
