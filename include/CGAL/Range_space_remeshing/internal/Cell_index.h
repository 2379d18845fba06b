// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INDEX_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INDEX_H

// Dense ids for the grid cells a computation meets: a cell, D integer levels, is
// hashed once, and what is counted per cell then lives in arrays indexed by id.

#include <cstdint>
#include <unordered_map>
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

template <class Levels>
class Cell_index
{
public:
  /// The id of cell c, a new one the first time c is seen.
  std::uint32_t id_of(const Levels& c)
  {
    const auto inserted = ids_.emplace(c, std::uint32_t(cells_.size()));
    if(inserted.second)
      cells_.push_back(c);
    return inserted.first->second;
  }

  const Levels& cell(std::uint32_t id) const { return cells_[id]; }
  std::size_t size() const { return cells_.size(); }

private:
  std::unordered_map<Levels, std::uint32_t, Levels_hash<Levels>> ids_;
  std::vector<Levels> cells_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INDEX_H
