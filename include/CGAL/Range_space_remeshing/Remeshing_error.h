// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_REMESHING_ERROR_H
#define CGAL_RANGE_SPACE_REMESHING_REMESHING_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

Thrown by the functions of the package when their input is unusable: an empty
mesh, a face that is not a triangle, a border where a closed surface is required
(`insert_crease_triangles()`),
a NaN or infinite map value, a non-positive or non-finite cell size, a grid so fine
that the range coordinates overflow or the output cap would be exceeded.
`what()` names the problem in one line.
*/
class Remeshing_error : public std::runtime_error
{
public:
  explicit Remeshing_error(const std::string& message) : std::runtime_error(message) {}
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_REMESHING_ERROR_H
