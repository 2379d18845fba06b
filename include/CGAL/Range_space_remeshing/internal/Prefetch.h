// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PREFETCH_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PREFETCH_H

// A hint that an object will be read soon, for walks whose next address is known a
// step ahead of its use.

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Asks for the cache lines at every 64 bytes from the start of `*object` to be
/// loaded, without waiting for them (all its lines when it starts on one: asking also
/// for the last line of an object that straddles one more made no measurable
/// difference); nothing where the compiler has no prefetch intrinsic. Never changes a
/// result.
template <class T>
inline void prefetch(const T* object)
{
#if defined(__GNUC__) || defined(__clang__)
  constexpr std::size_t line = 64;
  const char* bytes = reinterpret_cast<const char*>(object);
  for(std::size_t offset = 0; offset < sizeof(T); offset += line)
    __builtin_prefetch(bytes + offset);
#else
  (void)object;
#endif
}

/// Asks for the value of `key` in a property map that returns it by reference (as
/// `Surface_mesh`'s maps do); nothing for one that computes it. Such a map's `get()`
/// is called once more: an address computation for an array, a second lookup (with the
/// same effects as the first) for an associative map.
template <class PropertyMap, class Key>
inline void prefetch_value(const PropertyMap& map, const Key& key)
{
  if constexpr(std::is_lvalue_reference<decltype(get(map, key))>::value)
    prefetch(&get(map, key));
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PREFETCH_H
