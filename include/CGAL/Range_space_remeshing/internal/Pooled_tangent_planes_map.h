// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_POOLED_TANGENT_PLANES_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_POOLED_TANGENT_PLANES_MAP_H

// remesh() keeps each quad vertex's tangent planes from the dual to the relaxation.
// As a vertex property of a `Surface_mesh` holding the lists themselves, they are
// copied, list by list, each time the mesh collects its garbage (`Property_array`
// swaps by copy and shrinks by copying the whole array): 3 % of the pipeline's
// instructions. Here the mesh's property holds only a slot number, which garbage
// collection moves like any integer, and the lists stay in a pool.

#include <CGAL/Range_space_remeshing/Tangent_planes.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <deque>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// An lvalue property map vertex -> `Tangent_planes`. `SlotMap` (vertex ->
/// `std::size_t`, read-write) must read 0 for a vertex that has no list yet, as a
/// dynamic vertex property does for new vertices; a vertex's list is made on its
/// first `get()` or `put()`. The pool is a deque: making a list for one vertex leaves
/// the references to the others' valid (`Quad_collapser` holds two at once).
template <class SlotMap>
class Pooled_tangent_planes_map
{
public:
  using key_type = typename boost::property_traits<SlotMap>::key_type;
  using value_type = Tangent_planes;
  using reference = Tangent_planes&;
  using category = boost::lvalue_property_map_tag;

  Pooled_tangent_planes_map(SlotMap slots, std::deque<Tangent_planes>& pool) : slots_(slots), pool_(&pool) {}

  friend reference get(const Pooled_tangent_planes_map& map, key_type v)
  {
    std::size_t slot = get(map.slots_, v);
    if(slot == 0) {
      map.pool_->emplace_back();
      slot = map.pool_->size();
      put(map.slots_, v, slot);
    }
    return (*map.pool_)[slot - 1];
  }

  friend void put(const Pooled_tangent_planes_map& map, key_type v, const Tangent_planes& planes)
  {
    get(map, v) = planes;
  }

private:
  SlotMap slots_;
  std::deque<Tangent_planes>* pool_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_POOLED_TANGENT_PLANES_MAP_H
