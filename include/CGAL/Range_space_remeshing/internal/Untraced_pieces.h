// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_UNTRACED_PIECES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_UNTRACED_PIECES_H

// What the closed-loop check (Closed_loops.h) needs from the scan and the tracing: per
// input face, the number of pieces of hyperplane segments that no arc has passed
// through. The scan adds the hyperplanes crossing the face and 2 per intersection
// vertex in it (it splits a segment of each of its two hyperplanes); each step of an
// arc through the face takes one. After a complete scan and the tracing, what remains
// are the pieces of closed loops, which meet no grid edge and so no arc.

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

class Untraced_pieces
{
public:
  /// Starts counting, before the scan; until then, and in a seeded run, nothing is
  /// counted (one test of a null pointer per step).
  void start_counting(std::size_t number_of_faces)
  {
    counts_.assign(number_of_faces, 0);
    count_ = counts_.data();
  }

  /// The scan found `hyperplanes` levels crossing the face; writes only the face's own
  /// entry, so tasks of the parallel scan may call it.
  void add_crossed_hyperplanes(std::uint32_t face_id, std::int64_t hyperplanes)
  {
    if(count_)
      count_[face_id] += std::int32_t(hyperplanes);
  }

  void add_vertex(std::uint32_t face_id)
  {
    if(count_)
      count_[face_id] += 2;
  }

  void remove_arc_visit(std::uint32_t face_id)
  {
    if(count_)
      --count_[face_id];
  }

  /// The counts by face, read and decremented by the closed-loop check.
  std::vector<std::int32_t>& counts() { return counts_; }

private:
  std::vector<std::int32_t> counts_;
  std::int32_t* count_ = nullptr; // counts_'s data, or null: not counting
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_UNTRACED_PIECES_H
