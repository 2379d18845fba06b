// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INDEX_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INDEX_H

// Dense ids for the grid cells a computation meets: a cell, D integer levels, is
// hashed once, and what is counted per cell then lives in arrays indexed by id.

#include <cstdint>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Levels>
struct Levels_hash
{
  std::size_t operator()(const Levels& c) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for(std::int32_t x : c)
      h = (h ^ std::uint32_t(x)) * 1099511628211ull;
    return std::size_t(h ^ (h >> 29));
  }
};

/// Whether two cells are the same. An inlined loop, because std::array's == may
/// compile to a call to memcmp, and the topology check compares cells on every edge.
template <class Levels>
inline bool same_levels(const Levels& a, const Levels& b)
{
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i] != b[i])
      return false;
  return true;
}

template <class Levels>
class Cell_index
{
public:
  /// The id of cell c, a new one the first time c is seen. Ids follow the order of
  /// first sight, whatever the table's layout: the callers' results do not depend on it.
  std::uint32_t id_of(const Levels& c)
  {
    if(2 * (cells_.size() + 1) > slots_.size())
      grow();
    const std::size_t h = Levels_hash<Levels>()(c);
    for(std::size_t s = slot_of(h);; s = (s + 1) & mask_) {
      Slot& slot = slots_[s];
      if(slot.id == empty) {
        slot = Slot{std::uint32_t(cells_.size()), std::uint32_t(h)};
        cells_.push_back(c);
        return slot.id;
      }
      if(slot.tag == std::uint32_t(h) && same_levels(cells_[slot.id], c))
        return slot.id;
    }
  }

  const Levels& cell(std::uint32_t id) const { return cells_[id]; }
  std::size_t size() const { return cells_.size(); }

private:
  // Open addressing over ids into cells_: no node per cell, and the low bits of the
  // hash kept as a tag, so that a probe rarely compares levels.
  struct Slot
  {
    std::uint32_t id, tag;
  };
  static constexpr std::uint32_t empty = std::uint32_t(-1);

  std::size_t slot_of(std::size_t h) const { return std::size_t((std::uint64_t(h) * 0x9E3779B97F4A7C15ull) >> shift_); }

  void grow()
  {
    const std::size_t size = slots_.empty() ? 64 : 2 * slots_.size();
    mask_ = size - 1;
    shift_ = 64;
    for(std::size_t s = size; s > 1; s /= 2)
      --shift_;
    slots_.assign(size, Slot{empty, 0});
    for(std::uint32_t id = 0; id < cells_.size(); ++id) {
      const std::size_t h = Levels_hash<Levels>()(cells_[id]);
      std::size_t s = slot_of(h);
      while(slots_[s].id != empty)
        s = (s + 1) & mask_;
      slots_[s] = Slot{id, std::uint32_t(h)};
    }
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::vector<Levels> cells_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INDEX_H
