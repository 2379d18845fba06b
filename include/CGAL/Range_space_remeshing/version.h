// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_VERSION_H
#define CGAL_RANGE_SPACE_REMESHING_VERSION_H

// The version of the Range_space_remeshing package, for `#if` and for printing.
// Kept by hand, so that the headers work straight from the source tree; configuring
// the package's CMakeLists.txt fails when it differs from the version of its project().
#define RANGE_SPACE_REMESHING_VERSION_MAJOR 1
#define RANGE_SPACE_REMESHING_VERSION_MINOR 0
#define RANGE_SPACE_REMESHING_VERSION_PATCH 0
// the version as a string literal, "MAJOR.MINOR.PATCH"
#define RANGE_SPACE_REMESHING_VERSION_STR "1.0.0"
// the version as one number, MAJOR * 10000 + MINOR * 100 + PATCH, to compare in `#if`
#define RANGE_SPACE_REMESHING_VERSION_NR                                                          \
  (RANGE_SPACE_REMESHING_VERSION_MAJOR * 10000 + RANGE_SPACE_REMESHING_VERSION_MINOR * 100 +      \
   RANGE_SPACE_REMESHING_VERSION_PATCH)

#endif // CGAL_RANGE_SPACE_REMESHING_VERSION_H
