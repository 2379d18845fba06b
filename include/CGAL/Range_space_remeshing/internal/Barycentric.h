// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_BARYCENTRIC_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_BARYCENTRIC_H

// Where in its triangle the point over a lattice point (k, m) of the projection on
// (i, j) lies, in barycentric coordinates: the output's position of an intersection
// vertex, and the tracer's first guess of its cell. Only constructions: the exact
// predicates have decided that the point exists, and in which cell it lies.

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The 2x2 solve; false where the projection is degenerate. Where it is nearly
/// so (the projected triangle's angles below 1e-8), rounding would throw the point
/// far off, possibly out of the cell the exact predicates gave it: solve in exact
/// rationals there (rare, and the inputs are doubles and integers, so exact).
template <class Triangle>
bool solve_barycentric(const Triangle& t, int i, int j, double k, double m, std::array<double, 3>& w)
{
  const auto &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
  const double bi = b[i] - a[i], bj = b[j] - a[j], ci = c[i] - a[i], cj = c[j] - a[j];
  const double det = bi * cj - bj * ci;
  double s, r;
  if(std::abs(det) > 1e-8 * std::sqrt((bi * bi + bj * bj) * (ci * ci + cj * cj))) {
    s = ((k - a[i]) * cj - (m - a[j]) * ci) / det;
    r = (bi * (m - a[j]) - bj * (k - a[i])) / det;
  } else {
    using Q = CGAL::Exact_rational;
    const Q qbi = Q(b[i]) - Q(a[i]), qbj = Q(b[j]) - Q(a[j]), qci = Q(c[i]) - Q(a[i]), qcj = Q(c[j]) - Q(a[j]),
            qk = Q(k) - Q(a[i]), qm = Q(m) - Q(a[j]);
    const Q qdet = qbi * qcj - qbj * qci;
    if(CGAL::is_zero(qdet))
      return false;
    s = CGAL::to_double((qk * qcj - qm * qci) / qdet);
    r = CGAL::to_double((qbi * qm - qbj * qk) / qdet);
  }
  const double s0 = (std::min)((std::max)(s, 0.), 1.);
  const double r0 = (std::min)((std::max)(r, 0.), 1. - s0);
  w = {{1. - s0 - r0, s0, r0}};
  return true;
}

using Barycentric_segment = std::array<std::array<double, 3>, 2>;

/// Of the points where the triangle's edges reach the parameter `wanted` along the
/// projected segment (`param`: its corners' parameters), on one line of the
/// barycentric triangle, the two farthest apart.
inline Barycentric_segment farthest_points_at(const std::array<double, 3>& param, double wanted)
{
  const std::array<double, 3> centroid = {{1. / 3, 1. / 3, 1. / 3}};
  std::array<std::array<double, 3>, 4> found;
  int count = 0;
  for(int v = 0; v < 3; ++v) {
    const int w = (v + 1) % 3;
    std::array<double, 3> x = {{0, 0, 0}};
    if(param[v] == param[w]) {
      if(param[v] != wanted)
        continue;
      x[v] = 1; // the whole edge is over the point: both ends
      found[count++] = x;
      x[v] = 0;
      x[w] = 1;
      found[count++] = x;
    } else if((std::min)(param[v], param[w]) <= wanted && wanted <= (std::max)(param[v], param[w])) {
      const double lambda = (wanted - param[v]) / (param[w] - param[v]);
      x[v] = 1 - lambda;
      x[w] = lambda;
      if(count < 4)
        found[count++] = x;
    }
  }
  if(count == 0)
    return {{centroid, centroid}};
  Barycentric_segment ends = {{found[0], found[0]}};
  double farthest = -1;
  for(int x = 0; x < count; ++x)
    for(int y = x; y < count; ++y) {
      double distance = 0;
      for(int c = 0; c < 3; ++c)
        distance += (found[x][c] - found[y][c]) * (found[x][c] - found[y][c]);
      if(distance > farthest) {
        farthest = distance;
        ends = {{found[x], found[y]}};
      }
    }
  return ends;
}

/// Where the triangle projects on (i, j) to a segment (two coordinates of the map
/// that vary together, a symmetric input) the points of the triangle over (k, m)
/// form a segment: its two ends, in barycentric coordinates. Where it projects to
/// a point, the whole triangle is over it: the centroid, twice.
template <class Triangle>
Barycentric_segment points_over(const Triangle& t, int i, int j, double k, double m)
{
  const std::array<double, 3> centroid = {{1. / 3, 1. / 3, 1. / 3}};
  std::array<std::array<double, 2>, 3> q;
  for(int v = 0; v < 3; ++v)
    q[v] = {{(*t.p[v])[i], (*t.p[v])[j]}};
  std::array<double, 2> d = {{0, 0}}; // direction of the segment: the longest edge
  for(int v = 0; v < 3; ++v) {
    const std::array<double, 2> e = {{q[(v + 1) % 3][0] - q[v][0], q[(v + 1) % 3][1] - q[v][1]}};
    if(e[0] * e[0] + e[1] * e[1] > d[0] * d[0] + d[1] * d[1])
      d = e;
  }
  if(d[0] == 0 && d[1] == 0)
    return {{centroid, centroid}};
  std::array<double, 3> param;
  for(int v = 0; v < 3; ++v)
    param[v] = (q[v][0] - q[0][0]) * d[0] + (q[v][1] - q[0][1]) * d[1];
  const double lowest = (std::min)({param[0], param[1], param[2]});
  const double highest = (std::max)({param[0], param[1], param[2]});
  const double wanted = (std::min)((std::max)((k - q[0][0]) * d[0] + (m - q[0][1]) * d[1], lowest), highest);
  return farthest_points_at(param, wanted);
}

/// Barycentric coordinates of the point of the triangle whose (i, j) coordinates
/// are (k, m). Where the triangle's projection on (i, j) is degenerate, the
/// centre of the points over (k, m); `barycentric_in_cell` does better there.
template <class Triangle>
std::array<double, 3> barycentric(const Triangle& t, int i, int j, double k, double m)
{
  std::array<double, 3> w;
  if(solve_barycentric(t, i, j, k, m, w))
    return w;
  const auto ends = points_over(t, i, j, k, m);
  return {{(ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2, (ends[0][2] + ends[1][2]) / 2}};
}

/// On the segment of the triangle over the vertex's (k, m) (see `points_over`), the
/// middle of the part whose coordinates lie in the vertex's cell: so that the sampled
/// point agrees with the cell the exact predicates gave the vertex (or the nearest
/// point of the segment to it).
template <class Triangle, class Vertex>
std::array<double, 3> barycentric_in_cell(const Triangle& t, const Vertex& v)
{
  const auto ends = points_over(t, v.i, v.j, double(v.k()), double(v.m()));
  auto coordinate = [&](const std::array<double, 3>& w, int q) {
    return w[0] * (*t.p[0])[q] + w[1] * (*t.p[1])[q] + w[2] * (*t.p[2])[q];
  };
  double from = 0, to = 1; // part of the segment inside the cell, as a parameter
  for(int q = 0; q < int(v.cell.size()); ++q) {
    if(q == v.i || q == v.j)
      continue;
    const double x0 = coordinate(ends[0], q), x1 = coordinate(ends[1], q);
    const double low = double(v.cell[q]), high = low + 1;
    if(x0 == x1)
      continue; // constant along the segment: nothing to choose
    const double t_low = (low - x0) / (x1 - x0), t_high = (high - x0) / (x1 - x0);
    from = (std::max)(from, (std::min)(t_low, t_high));
    to = (std::min)(to, (std::max)(t_low, t_high));
  }
  const double middle = (std::min)((std::max)((from + to) / 2, 0.), 1.);
  std::array<double, 3> w;
  for(int c = 0; c < 3; ++c)
    w[c] = (1 - middle) * ends[0][c] + middle * ends[1][c];
  return w;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_BARYCENTRIC_H
