// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_RANGE_SPACE_TRAITS_H
#define CGAL_RANGE_SPACE_REMESHING_RANGE_SPACE_TRAITS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/enum.h>

#include <array>

namespace CGAL {
namespace Range_space_remeshing {

/// Smallest and largest supported range-space dimensions.
constexpr int minimum_range_dimension = 3;
constexpr int maximum_range_dimension = 16;

/*!
\ingroup PkgRangeSpaceRemeshingTraits

Default model of the concept `RangeSpaceTraits`.

A point of the range space \f$\mathbb{R}^D\f$ is a `std::array<double, D>`.
The predicates are the 2-D and 3-D orientations of points whose coordinates are
picked from range-space points (coordinate projections), evaluated with the
predicates of the 3-D CGAL kernel `K`. With the default kernel
`Exact_predicates_inexact_constructions_kernel` they are filtered and exact;
`Exact_predicates_exact_constructions_kernel` gives the same signs.

The symbolic perturbation of the grid is not part of the traits: it is built
on top of these unperturbed exact signs, in one internal header.

\tparam D the dimension of the range space, between 3 and 16.
\tparam K a CGAL kernel with exact `Orientation_2` and `Orientation_3` predicates.

\cgalModels `RangeSpaceTraits`
*/
template <int D, class K = CGAL::Exact_predicates_inexact_constructions_kernel>
class Range_space_traits
{
  static_assert(D >= minimum_range_dimension && D <= maximum_range_dimension,
                "Range_space_traits: the dimension must be between 3 and 16");

public:
  static constexpr int dimension = D;
  using Kernel = K;
  using FT = double;
  using Point_d = std::array<double, D>;

  /// Exact sign of the 2-D orientation of (ax,ay), (bx,by), (cx,cy).
  struct Orientation_2
  {
    CGAL::Orientation operator()(double ax, double ay, double bx, double by,
                                 double cx, double cy) const
    {
      using P = typename K::Point_2;
      return K().orientation_2_object()(P(ax, ay), P(bx, by), P(cx, cy));
    }
  };

  /// Exact sign of the 3-D orientation of four points given coordinate-wise.
  struct Orientation_3
  {
    CGAL::Orientation operator()(const std::array<double, 3>& a,
                                 const std::array<double, 3>& b,
                                 const std::array<double, 3>& c,
                                 const std::array<double, 3>& d) const
    {
      using P = typename K::Point_3;
      return K().orientation_3_object()(P(a[0], a[1], a[2]), P(b[0], b[1], b[2]),
                                        P(c[0], c[1], c[2]), P(d[0], d[1], d[2]));
    }
  };

  Orientation_2 orientation_2_object() const { return Orientation_2(); }
  Orientation_3 orientation_3_object() const { return Orientation_3(); }
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_RANGE_SPACE_TRAITS_H
