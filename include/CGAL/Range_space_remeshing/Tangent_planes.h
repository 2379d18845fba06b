// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_TANGENT_PLANES_H
#define CGAL_RANGE_SPACE_REMESHING_TANGENT_PLANES_H

#include <array>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/// The tangent planes (point, normal) of the primal vertices of a dual vertex's
/// primal face: what the relaxation projects on.
using Tangent_planes = std::vector<std::pair<std::array<double, 3>, std::array<double, 3>>>;

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_TANGENT_PLANES_H
