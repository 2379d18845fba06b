// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_UNION_FIND_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_UNION_FIND_H

#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The representative of x in a union-find forest stored as parent indices (a root
/// is its own parent), halving the path on the way.
template <class Index>
Index union_find_root(std::vector<Index>& parent, Index x)
{
  while(parent[x] != x)
    x = parent[x] = parent[parent[x]];
  return x;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_UNION_FIND_H
