// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_LATTICE_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_LATTICE_H

// The integer lattice of the range space, in cell units. A coordinate x lies strictly
// between the perturbed levels ceil(x) - 1 and ceil(x) (a coordinate on a level counts
// as below it), so a triangle strictly crosses the levels from the lowest ceiling of
// its corners to the highest minus one. The lattice cell of a point of the mapped
// surface on grid hyperplanes is the floor of its other coordinates, decided by the
// exact perturbed predicates (a guess in doubles, then moved level by level until
// the predicates agree), so that every face that asks gets the same cell.

#include <CGAL/Range_space_remeshing/internal/Barycentric.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Lattice levels are kept in 32-bit integers; range coordinates beyond this bound
// mean an absurd cell size and are rejected before they could overflow.
constexpr double maximum_lattice_coordinate = 1 << 29;

/// Index of the lowest set bit of x != 0.
inline int lowest_set_bit(std::uint32_t x)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(x);
#else
  int i = 0;
  for(; !(x & 1); x >>= 1)
    ++i;
  return i;
#endif
}

/// std::ceil for |x| < 2^31, without a library call.
inline std::int32_t ceil_to_int(double x)
{
  const std::int32_t i = std::int32_t(x);
  return i + (double(i) < x);
}

/// The lowest and highest ceilings of a triangle's corners in axis P: the levels
/// of P it strictly crosses are [lowest, highest - 1].
template <class Triangle>
std::int32_t lowest_ceiling(const Triangle& t, int P)
{
  return (std::min)({(*t.c[0])[P], (*t.c[1])[P], (*t.c[2])[P]});
}

template <class Triangle>
std::int32_t highest_ceiling(const Triangle& t, int P)
{
  return (std::max)({(*t.c[0])[P], (*t.c[1])[P], (*t.c[2])[P]});
}

/// The lattice cell of the point where segment ab crosses x_P = level, exactly:
/// the floor of its coordinates in the other axes, and level in axis P. In an axis
/// where a and b have the same ceiling c, the crossing, strictly between them,
/// lies in (c - 1, c] as they do: cell c - 1, with no predicate (most axes, as
/// an edge crosses few hyperplanes).
template <int D, class Predicates, class Point_d>
std::array<std::int32_t, D> cell_of_crossing(const Predicates& predicates, const Point_d& a, const Point_d& b, int P,
                                             std::int32_t level)
{
  std::array<std::int32_t, D> cell;
  cell[P] = level;
  const double t = Predicates::crossing_parameter(a, b, P, double(level));
  for(int q = 0; q < D; ++q) {
    if(q == P)
      continue;
    const double ceiling = std::ceil(a[q]);
    if(ceiling == std::ceil(b[q])) {
      cell[q] = std::int32_t(ceiling) - 1;
      continue;
    }
    const double guess = a[q] + t * (b[q] - a[q]);
    std::int32_t n =
        std::int32_t(std::floor((std::min)((std::max)(guess, (std::min)(a[q], b[q])), (std::max)(a[q], b[q]))));
    while(predicates.crossing_side(a, b, P, double(level), q, double(n)) < 0) --n;
    while(predicates.crossing_side(a, b, P, double(level), q, double(n + 1)) > 0) ++n;
    cell[q] = n;
  }
  return cell;
}

/// The lattice cell of the intersection vertex v of triangle t in the axes other
/// than its grid edge's.
template <class Predicates, class Triangle, class Vertex>
void locate_vertex_in_cell(const Predicates& predicates, const Triangle& t, Vertex& v)
{
  const auto &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
  const auto &ca = *t.c[0], &cb = *t.c[1], &cc = *t.c[2];
  // barycentric estimate, only to guess the level; the exact test decides
  std::array<double, 3> w{};
  bool estimated = false;
  for(int q = 0; q < int(v.cell.size()); ++q) {
    if(q == v.i || q == v.j)
      continue;
    // Corners with one ceiling C lie strictly between the perturbed levels C - 1
    // and C, and so does every point of the triangle: the cell is C - 1 without a
    // test. True of most axes when D is large, as the cells are then wide.
    if(ca[q] == cb[q] && cb[q] == cc[q]) {
      v.cell[q] = ca[q] - 1;
      continue;
    }
    if(!estimated) {
      w = barycentric(t, v.i, v.j, v.k(), v.m());
      estimated = true;
    }
    const double lo = (std::min)({a[q], b[q], c[q]});
    const double hi = (std::max)({a[q], b[q], c[q]});
    double guess = w[0] * a[q] + w[1] * b[q] + w[2] * c[q];
    guess = (std::min)((std::max)(guess, lo), hi);
    std::int32_t n = std::int32_t(std::floor(guess));
    auto above = [&](std::int32_t level) {
      return predicates.vertex_coordinate_side(a, b, c, v.orientation, v.i, v.j, double(v.k()), double(v.m()), q,
                                               double(level)) > 0;
    };
    while(!above(n)) --n;
    while(above(n + 1)) ++n;
    v.cell[q] = n;
  }
  v.has_cell = true;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_LATTICE_H
