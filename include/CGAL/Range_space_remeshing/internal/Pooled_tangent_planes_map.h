// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_POOLED_TANGENT_PLANES_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_POOLED_TANGENT_PLANES_MAP_H

// remesh() keeps each quad vertex's tangent planes from the dual to the relaxation.
// As a vertex property of a `Surface_mesh` holding the lists themselves, they are
// copied, list by list, each time the mesh collects its garbage (`Property_array`
// swaps by copy and shrinks by copying the whole array). Here the mesh's property
// holds only a slot number, which garbage collection moves like any integer, and the
// lists stay in a pool.
//
// The pool also keeps, per slot, the eigen-decomposition of the quadric of the list
// that the dual made for its placement: the relaxation needs the same one for every
// vertex the collapse did not merge, and need not compute it again. (What each saves:
// benchmark/RESULTS.md.)

#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The lists of `Pooled_tangent_planes_map`, by slot, and the decompositions
/// remembered for them (with the matrix each was made from).
struct Tangent_planes_pool
{
  struct Decomposition // of `matrix`; the rest of a `Quadric_eigen` comes with the quadric
  {
    Matrix3 matrix;
    Vec3 values;
    std::array<Vec3, 3> vectors;
  };
  std::deque<Tangent_planes> planes;
  // a vector: nothing holds references to these, and a deque would allocate a block
  // for every two of them
  std::vector<std::optional<Decomposition>> decompositions;
};

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

  Pooled_tangent_planes_map(SlotMap slots, Tangent_planes_pool& pool) : slots_(slots), pool_(&pool) {}

  friend reference get(const Pooled_tangent_planes_map& map, key_type v) { return map.pool_->planes[map.slot(v)]; }

  friend void put(const Pooled_tangent_planes_map& map, key_type v, const Tangent_planes& planes)
  {
    get(map, v) = planes;
  }

  /// Keeps `eigen`, the decomposition of `quadric`, for v.
  void remember(key_type v, const Quadric& quadric, const Quadric_eigen& eigen) const
  {
    pool_->decompositions[slot(v)] = Tangent_planes_pool::Decomposition{quadric.matrix(), eigen.values, eigen.vectors};
  }

  /// The decomposition of `quadric`: v's remembered one if it was made from the same
  /// matrix, bit for bit (the collapse merges lists: a merged vertex's is not).
  Quadric_eigen decomposition(key_type v, const Quadric& quadric) const
  {
    const auto& remembered = pool_->decompositions[slot(v)];
    if(remembered && remembered->matrix == quadric.matrix())
      return Quadric_eigen(quadric, remembered->values, remembered->vectors);
    return Quadric_eigen(quadric);
  }

private:
  std::size_t slot(key_type v) const
  {
    std::size_t slot = get(slots_, v);
    if(slot == 0) {
      pool_->planes.emplace_back();
      pool_->decompositions.emplace_back();
      slot = pool_->planes.size();
      put(slots_, v, slot);
    }
    return slot - 1;
  }

  SlotMap slots_;
  Tangent_planes_pool* pool_;
};

template <class Map>
struct Is_pooled_tangent_planes_map : std::false_type
{};

template <class SlotMap>
struct Is_pooled_tangent_planes_map<Pooled_tangent_planes_map<SlotMap>> : std::true_type
{};

/// Where `planes` is a pooled map, keeps the decomposition of the quadric of v's list
/// for `decomposition_of()`; else nothing.
template <class TangentPlanesMap, class Key>
void remember_decomposition(const TangentPlanesMap& planes, Key v, const Quadric& quadric, const Quadric_eigen& eigen)
{
  if constexpr(Is_pooled_tangent_planes_map<TangentPlanesMap>::value)
    planes.remember(v, quadric, eigen);
  else {
    (void)planes, (void)v, (void)quadric, (void)eigen;
  }
}

/// The eigen-decomposition of `quadric`, the quadric of v's planes: the one
/// `remember_decomposition()` kept if it still holds, else made now.
template <class TangentPlanesMap, class Key>
Quadric_eigen decomposition_of(const TangentPlanesMap& planes, Key v, const Quadric& quadric)
{
  if constexpr(Is_pooled_tangent_planes_map<TangentPlanesMap>::value)
    return planes.decomposition(v, quadric);
  else {
    (void)planes, (void)v;
    return Quadric_eigen(quadric);
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_POOLED_TANGENT_PLANES_MAP_H
