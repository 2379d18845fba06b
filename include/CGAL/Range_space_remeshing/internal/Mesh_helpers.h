// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H

// Small FaceGraph helpers shared by the dual, the collapse and the relaxation.

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Mesh>
void collect_garbage_if_any(Mesh&) {}
template <class P>
void collect_garbage_if_any(CGAL::Surface_mesh<P>& m)
{
  if(m.has_garbage())
    m.collect_garbage();
}

/// One more than the largest index of the elements of `range`: the size of a vector
/// indexed by them (a `Surface_mesh` with removed elements has gaps in its indices).
template <class Range, class IndexMap>
std::size_t index_bound(const Range& range, IndexMap index)
{
  std::size_t bound = 0;
  for(auto x : range)
    bound = (std::max)(bound, std::size_t(get(index, x)) + 1);
  return bound;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H
