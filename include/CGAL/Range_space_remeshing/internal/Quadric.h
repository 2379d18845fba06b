// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUADRIC_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUADRIC_H

// The quadric error of a set of tangent planes (p_i, n_i): Q(x) = sum <n_i, x - p_i>^2,
// its robust minimiser (dual contouring's truncated pseudo-inverse around the mass
// point), and its minimiser on a line (the paper's relaxation projection); plus the
// small 3-vector helpers the output writers share.

#include <CGAL/number_utils.h>

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

/// The corner after corner i of a polygon of n corners, and the one before it. Not
/// (i + 1) % n: the polygon tests run at every corner of every face the collapse and
/// the relaxation try, and an integer division there costs more than the test's
/// arithmetic (about 430,000 of them in the whole pipeline on refined_elephant).
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

/// Whether the polygon turns left at every corner, seen from the side of `normal`.
inline bool is_convex(const std::vector<Vec3>& polygon, const Vec3& normal)
{
  const std::size_t n = polygon.size();
  for(std::size_t i = 0; i < n; ++i) {
    const Vec3& p = polygon[previous_corner(i, n)];
    const Vec3& q = polygon[i];
    const Vec3& r = polygon[next_corner(i, n)];
    if(!(dot(cross(difference(q, p), difference(r, q)), normal) > 0))
      return false;
  }
  return true;
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
/// are (nearly) equal. A third faster than cyclic Jacobi sweeps from a guessed normal
/// (170 against 265 ns, measured on the quadrics of tangent planes).
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
