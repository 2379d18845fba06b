// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PERTURBED_PREDICATES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PERTURBED_PREDICATES_H

// The only place of the package that knows about ties.
//
// Every combinatorial decision of the tracer is the sign of a polynomial in the
// mapped (and scaled) vertex coordinates u and in integer lattice levels. Ties are
// broken by translating the lattice by an infinitesimal vector
// delta = (eps_0, ..., eps_{D-1}), eps_0 >> eps_1 >> ... > 0. Only the lattice moves,
// so each predicate is linear in the eps's: its perturbed sign is the exact sign of
// the unperturbed value, then, at a tie, the signs of the eps-coefficients taken in
// increasing axis index. Because the perturbed configuration is generic and every
// predicate reads it exactly, neighbouring triangles always agree.

#include <CGAL/enum.h>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

inline int sign_of_difference(double a, double b) { return (a > b) - (a < b); }

template <class Traits>
class Perturbed_predicates
{
public:
  using Point_d = typename Traits::Point_d;

  explicit Perturbed_predicates(const Traits& traits = Traits())
    : orient2_(traits.orientation_2_object()), orient3_(traits.orientation_3_object())
  {}

  /// Side of an input coordinate relative to lattice level `k` shifted by eps:
  /// a coordinate equal to `k` counts as below. Never 0.
  static int side(double x, double k) { return x > k ? 1 : -1; }

  /// Exact sign of the orientation of (a, b, c) in the plane. A floating-point
  /// filter decides when it can (Shewchuk's error bound for this evaluation order);
  /// the traits' exact predicate decides the rest.
  int orientation_2(double ax, double ay, double bx, double by, double cx, double cy) const
  {
    const double left = (bx - ax) * (cy - ay);
    const double right = (by - ay) * (cx - ax);
    const double det = left - right;
    const double magnitude = std::abs(left) + std::abs(right);
    // 3.3307e-16 = (3 + 16u) u, u = 2^-53; below 1e-280 underflow could void the bound
    if(magnitude > 1e-280 && std::abs(det) > 3.3307e-16 * magnitude)
      return det > 0 ? 1 : -1;
    return int(orient2_(ax, ay, bx, by, cx, cy));
  }

  /// Exact (unperturbed) orientation of triangle abc projected on axes (a1, a2).
  int projected_orientation(const Point_d& a, const Point_d& b, const Point_d& c,
                            int a1, int a2) const
  {
    return orientation_2(a[a1], a[a2], b[a1], b[a2], c[a1], c[a2]);
  }

  /// Perturbed orientation of (a, b, X) on axes (a1, a2), X the lattice point
  /// (x1, x2) + (eps_a1, eps_a2). Zero only if a and b project to the same point.
  int perturbed_orientation_2(const Point_d& a, const Point_d& b, int a1, int a2,
                              double x1, double x2) const
  {
    int s = orientation_2(a[a1], a[a2], b[a1], b[a2], x1, x2);
    if(s != 0)
      return s;
    // d/dx1 = a_2 - b_2, d/dx2 = b_1 - a_1; the smaller axis index dominates.
    const int coefficient_1 = sign_of_difference(a[a2], b[a2]);
    const int coefficient_2 = sign_of_difference(b[a1], a[a1]);
    if(a1 < a2)
      return coefficient_1 != 0 ? coefficient_1 : coefficient_2;
    return coefficient_2 != 0 ? coefficient_2 : coefficient_1;
  }

  /// Perturbed orientation of (a', b', c', X) where primes denote the projection on
  /// axes (a1, a2, a3) and X = (x1, x2, x3) + eps. Never 0 when the projection of the
  /// triangle on (a1, a2) is not degenerate.
  int perturbed_orientation_3(const Point_d& a, const Point_d& b, const Point_d& c,
                              int a1, int a2, int a3,
                              double x1, double x2, double x3) const
  {
    int s = int(orient3_({a[a1], a[a2], a[a3]}, {b[a1], b[a2], b[a3]},
                         {c[a1], c[a2], c[a3]}, {x1, x2, x3}));
    if(s != 0)
      return s;
    // The eps-coefficients are the components of the normal (b'-a') x (c'-a').
    std::array<int, 3> axis = {a1, a2, a3};
    std::array<int, 3> normal = {projected_orientation(a, b, c, a2, a3),
                                 projected_orientation(a, b, c, a3, a1),
                                 projected_orientation(a, b, c, a1, a2)};
    // three elements: order them by axis index
    std::array<int, 3> order = {0, 1, 2};
    if(axis[order[0]] > axis[order[1]]) std::swap(order[0], order[1]);
    if(axis[order[1]] > axis[order[2]]) std::swap(order[1], order[2]);
    if(axis[order[0]] > axis[order[1]]) std::swap(order[0], order[1]);
    for(int n : order)
      if(normal[n] != 0)
        return normal[n];
    return 0;
  }

  /// Does the grid edge {x_i = k, x_j = m} (i < j) meet triangle abc? Returns the
  /// projected orientation of the triangle on (i, j) (+1 or -1) if it does, 0 if not.
  int grid_edge_orientation(const Point_d& a, const Point_d& b, const Point_d& c,
                            int i, int j, double k, double m) const
  {
    const int o = projected_orientation(a, b, c, i, j);
    if(o == 0)
      return 0; // a flat projection cannot contain the perturbed lattice point
    if(perturbed_orientation_2(a, b, i, j, k, m) != o) return 0;
    if(perturbed_orientation_2(b, c, i, j, k, m) != o) return 0;
    if(perturbed_orientation_2(c, a, i, j, k, m) != o) return 0;
    return o;
  }

  /// Edge ab crosses the plane x_P = level (side(a_P) != side(b_P)). Returns the sign
  /// of p_l - c at the crossing point p, relative to the wall x_l = c.
  int crossing_side(const Point_d& a, const Point_d& b, int P, double level,
                    int l, double c) const
  {
    const int side_b = side(b[P], level); // = sign(b_P - a_P)
    return -perturbed_orientation_2(a, b, P, l, level, c) * side_b;
  }

  /// Parameter of the point where edge ab crosses the plane x_P = level, as a
  /// double estimate for `crossing_slab_side()`.
  static double crossing_parameter(const Point_d& a, const Point_d& b, int P, double level)
  {
    return (level - a[P]) / (b[P] - a[P]);
  }

  /// Where edge ab crosses the plane x_P = level, relative to the slab
  /// lo <= x_l <= hi of two walls: -1 below lo, +1 above hi, 0 between. The double
  /// estimate from `t = crossing_parameter()` decides when it is far from both walls,
  /// the exact predicate otherwise. lo = -infinity or hi = +infinity ignores a wall.
  int crossing_slab_side(const Point_d& a, const Point_d& b, int P, double level, double t,
                         int l, double lo, double hi) const
  {
    // t has a relative error below 3u (u = 2^-53), so |error of p| <= 16 u (|a_l| + |b_l|);
    // the margin is 300 times that.
    const double p = a[l] + t * (b[l] - a[l]);
    if(!(p == p))
      return exact_slab_side(a, b, P, level, l, lo, hi);
    const double margin = 1e-12 * (std::abs(a[l]) + std::abs(b[l]) + 1.);
    if(p - lo < -margin)
      return -1;
    if(p - lo <= margin && crossing_side(a, b, P, level, l, lo) < 0)
      return -1;
    if(p - hi > margin)
      return 1;
    if(p - hi >= -margin && crossing_side(a, b, P, level, l, hi) > 0)
      return 1;
    return 0;
  }

  /// Sign of x_q - n at the point of triangle abc on the grid edge {x_i = k, x_j = m},
  /// `o` being the triangle's orientation projected on (i, j).
  int vertex_coordinate_side(const Point_d& a, const Point_d& b, const Point_d& c,
                             int o, int i, int j, double k, double m,
                             int q, double n) const
  {
    return -perturbed_orientation_3(a, b, c, i, j, q, k, m, n) * o;
  }

  /// An arc in the plane x_P = level crosses, inside triangle abc, both the wall
  /// x_l = c and the wall x_p = d. Is x_l = c met first? `up_p` is +1 if d is the
  /// upper wall of the arc's box in axis p, -1 if the lower. The direction of travel
  /// does not enter.
  bool is_met_first(const Point_d& a, const Point_d& b, const Point_d& c_,
                    int P, double level, int l, double c, int p, double d,
                    int up_p) const
  {
    const int o3 = perturbed_orientation_3(a, b, c_, P, l, p, level, c, d);
    const int o2 = projected_orientation(a, b, c_, P, l);
    return o3 * o2 == up_p;
  }

private:
  int exact_slab_side(const Point_d& a, const Point_d& b, int P, double level, int l,
                      double lo, double hi) const
  {
    if(lo > -std::numeric_limits<double>::infinity() && crossing_side(a, b, P, level, l, lo) < 0)
      return -1;
    if(hi < std::numeric_limits<double>::infinity() && crossing_side(a, b, P, level, l, hi) > 0)
      return 1;
    return 0;
  }

  typename Traits::Orientation_2 orient2_;
  typename Traits::Orientation_3 orient3_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PERTURBED_PREDICATES_H
