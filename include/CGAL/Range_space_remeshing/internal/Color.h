// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_COLOR_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_COLOR_H

// Colours as three numbers in [0, 1], to and from what property maps store.

#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/IO/Color.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// A colour as three numbers in [0, 1]: `CGAL::IO::Color` (0..255 channels) or any
/// triple of numbers, taken as it is.
inline Vec3 to_rgb(const CGAL::IO::Color& c) { return {{c.r() / 255., c.g() / 255., c.b() / 255.}}; }

template <class Triple>
Vec3 to_rgb(const Triple& c)
{
  return {{double(c[0]), double(c[1]), double(c[2])}};
}


/// A colour from three numbers in [0, 1], as the output colour map stores it.
template <class Color>
Color from_rgb(const Vec3& c)
{
  return {c[0], c[1], c[2]};
}
template <>
inline CGAL::IO::Color from_rgb<CGAL::IO::Color>(const Vec3& c)
{
  auto channel = [](double x) { return static_cast<unsigned char>(std::lround(255 * (std::min)((std::max)(x, 0.), 1.))); };
  return CGAL::IO::Color(channel(c[0]), channel(c[1]), channel(c[2]));
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_COLOR_H
