// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CLOSED_LOOPS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CLOSED_LOOPS_H

// For the topology check (Topology_check.h): the closed loops of the surface in a
// grid hyperplane that meet no grid edge, so that no arc traced them. They are found
// where pieces of hyperplane segments were left untraced (Untraced_pieces.h), and
// followed from face to face as the tracer would follow an arc.

#include <CGAL/Range_space_remeshing/internal/Arc_tracer.h>
#include <CGAL/Range_space_remeshing/internal/Lattice.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>
#include <CGAL/Range_space_remeshing/internal/Untraced_pieces.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Input>
class Closed_loops
{
  static constexpr int D = Input::D;
  using Levels = typename Input::Levels;
  using Triangle = typename Input::Triangle;
  using Predicates = Perturbed_predicates<typename Input::Traits>;

public:
  /// Needs a complete scan and the tracing, with the untraced pieces counted.
  Closed_loops(Input& input, Untraced_pieces& pieces, const Predicates& predicates)
    : input_(input), counts_(pieces.counts()), predicates_(predicates)
  {}

  /// Calls `report(P, level, cell, faces)` for each closed loop in a hyperplane
  /// x_P = level: `cell` is the lattice cell above the grid face holding it
  /// (cell[P] = level), `faces` the ids of the input faces it crosses. Walks only from
  /// the faces with untraced pieces.
  template <class Report>
  std::size_t find(const Report& report)
  {
    std::size_t loops = 0;
    std::vector<std::uint32_t> loop;
    auto key = [](int P, std::int32_t level) { return (std::uint64_t(std::uint32_t(level)) << 8) | std::uint64_t(P); };
    // the segments of the loops found: a face several loops cross is met again. The
    // keys keep all their 64 bits, so that a negative level stays apart from others.
    std::unordered_map<std::uint32_t, std::vector<decltype(key(0, 0))>> found; // face -> keys
    auto is_found = [&](std::uint32_t f, int P, std::int32_t level) {
      const auto it = found.find(f);
      return it != found.end() && std::find(it->second.begin(), it->second.end(), key(P, level)) != it->second.end();
    };
    for(std::uint32_t f = 0; f < counts_.size(); ++f) {
      if(counts_[f] < 0)
        CGAL_error_msg("Range_space_remeshing: an arc crossed a face more often than "
                       "hyperplanes do");
      if(counts_[f] == 0)
        continue;
      const Triangle t = input_.load(f);
      for(int P = 0; P < D && counts_[f] > 0; ++P)
        for(std::int32_t level = lowest_ceiling(t, P); level < highest_ceiling(t, P) && counts_[f] > 0; ++level) {
          if(is_found(f, P, level) || segment_has_vertex(t, P, level) || !walk_loop(f, P, level, loop))
            continue;
          for(std::uint32_t g : loop) {
            --counts_[g];
            found[g].push_back(key(P, level));
          }
          const int e = exit_edge(t, P, level, 1);
          report(P, level, cell_of_crossing<D>(predicates_, *t.p[e], *t.p[(e + 1) % 3], P, level), loop);
          ++loops;
        }
    }
    return loops;
  }

  /// The cell of the point where the input edge between the two mapped vertices
  /// crosses x_P = level (cell[P] = level): the same whichever face asks, since the
  /// edge is taken from its lower vertex id.
  Levels cell_of_edge_crossing(std::uint32_t a, std::uint32_t b, int P, std::int32_t level) const
  {
    if(b < a)
      std::swap(a, b);
    return cell_of_crossing<D>(predicates_, input_.point_of(a), input_.point_of(b), P, level);
  }

private:
  /// Whether the segment of x_P = level across the triangle holds an intersection
  /// vertex, by the exact tests of the scan.
  bool segment_has_vertex(const Triangle& t, int P, std::int32_t level) const
  {
    for(int l = 0; l < D; ++l) {
      if(l == P)
        continue;
      const int i = (std::min)(P, l), j = (std::max)(P, l);
      for(std::int32_t n = lowest_ceiling(t, l); n < highest_ceiling(t, l); ++n) {
        const double k = double(i == P ? level : n), m = double(i == P ? n : level);
        if(predicates_.grid_edge_orientation(*t.p[0], *t.p[1], *t.p[2], i, j, k, m) != 0)
          return true;
      }
    }
    return false;
  }

  /// Follows the curve of x_P = level from face f0 as the tracer would; true, with
  /// the faces in `loop`, when it comes back to f0 without meeting a face where it
  /// holds a vertex, or the border (then it is a piece of some traced arc).
  bool walk_loop(std::uint32_t f0, int P, std::int32_t level, std::vector<std::uint32_t>& loop)
  {
    loop.assign(1, f0);
    for(std::uint32_t f = f0; loop.size() <= num_faces(input_.mesh());) {
      const std::uint32_t n = input_.record_of(f).neighbour[exit_edge(input_.load(f), P, level, 1)];
      if(n == f0)
        return true;
      if(n == Input::border || segment_has_vertex(input_.load(n), P, level))
        return false;
      loop.push_back(f = n);
    }
    CGAL_error_msg("Range_space_remeshing: endless level curve");
  }

  Input& input_;
  std::vector<std::int32_t>& counts_;
  const Predicates& predicates_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CLOSED_LOOPS_H
