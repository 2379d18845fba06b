// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_SCANNER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_SCANNER_H

// Section 4 of the paper: finding the intersection vertices, the points where the
// mapped surface meets the grid edges {x_i = k, x_j = m}, by the exact test of every
// lattice point near the projection of a triangle on (i, j). A scan queues each
// vertex it finds for the tracing, and the boundary vertices of the border edges of
// each face it scans.
//
// Three scans: the complete one over all faces, on this thread or on all threads
// (the same vertices in the same order), and the seeded one, which scans the faces
// around a seed, nearest first, until one holds a vertex; the tracing then finds the
// rest of that component.

#include <CGAL/Range_space_remeshing/internal/Border_crossings.h>
#include <CGAL/Range_space_remeshing/internal/Intersection_vertices.h>
#include <CGAL/Range_space_remeshing/internal/Lattice.h>
#include <CGAL/Range_space_remeshing/internal/Lazily_zeroed_array.h>
#include <CGAL/Range_space_remeshing/internal/Level_differences.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>
#include <CGAL/Range_space_remeshing/internal/Output_size_cap.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Untraced_pieces.h>

#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Input>
class Grid_scanner
{
  static constexpr int D = Input::D;
  using Levels = typename Input::Levels;
  using Triangle = typename Input::Triangle;
  using Predicates = Perturbed_predicates<typename Input::Traits>;
  using face_descriptor = typename Input::face_descriptor;

  /// The lattice levels a triangle strictly crosses, per axis.
  struct Crossed_levels
  {
    // level k + eps lies strictly between lo and hi iff ceil(lo) <= k <= ceil(hi) - 1;
    // set in the listed axes only
    Levels first, last;
    std::array<int, D> axes;      // the axes with a crossed level, increasing
    int number_of_axes = 0;
    // crossed levels over all axes: the hyperplane segments in the triangle (up to
    // D * 2^30 for an absurd cell size, hence 64 bits)
    std::int64_t hyperplanes = 0;
  };

public:
  Grid_scanner(Input& input, Intersection_vertices<D>& vertices, Border_crossings<Input>& border,
               Untraced_pieces& pieces, const Output_size_cap& cap, const Predicates& predicates)
    : input_(input), vertices_(vertices), border_(border), pieces_(pieces), cap_(cap), predicates_(predicates)
  {}

  /// Finds every intersection vertex of the triangle `f` and queues it.
  void scan_face(face_descriptor f)
  {
    scan_triangle(input_.load_face(f), [](const Crossed_levels&) {});
  }

  /// The complete scan on this thread, after `Mapped_input::map_all_vertices()`.
  /// Refuses an output whose expected size exceeds the cap before it is built, without
  /// the pass over all faces that this estimate takes on most runs: a bound of the
  /// vertices built, summed before each face is scanned, has to reach
  /// `vertices_built_before_estimate` (or the cap, if lower) first. Only then is the
  /// estimate made, once; if it is above the cap, at most about that many vertices
  /// were built for nothing, however large one face is.
  void scan_all_faces(const Progress& progress)
  {
    const double cap = cap_.maximum();
    const double check_at = (std::min)(cap, vertices_built_before_estimate);
    double bound = 0;
    bool checked = false;
    auto bound_before_scan = [&](const Crossed_levels& levels) {
      if(checked)
        return;
      bound += Output_size_cap::vertices_bound(levels.hyperplanes);
      if(Output_size_cap::bound_may_reach(bound, check_at)) {
        checked = true;
        Output_size_cap::refuse_if_expected_above(input_, cap);
      }
    };
    input_.record_all_faces();
    const std::vector<std::uint32_t>& face_ids = input_.faces_in_scan_order();
    const std::size_t n = face_ids.size();
    Work_meter meter(progress, Remeshing_stage::SCAN);
    std::size_t vertices_before = vertices_.size();
    for(std::size_t position = 0; position < n; ++position) {
      // the work: a face, and the vertices it holds; the second half of the scan
      meter.add(1 + vertices_.size() - vertices_before, [&] { return 0.5 + 0.5 * double(position) / double(n); });
      vertices_before = vertices_.size();
      if(position + scan_lookahead < n)
        input_.prefetch_corners(face_ids[position + scan_lookahead]);
      scan_triangle(input_.load(face_ids[position]), bound_before_scan);
    }
  }

  /// Faces ahead in the scan whose corners are asked for: the work of a face covers
  /// about a memory access's wait at this distance.
  static constexpr std::size_t scan_lookahead = 8;

#if defined(CGAL_LINKED_WITH_TBB)
  /// The second half of the complete scan on all threads, after
  /// `Mapped_input::map_and_record_in_parallel()`: the exact tests of every face on
  /// all threads, then, on this thread, the vertices created and queued in the order
  /// in which `scan_face()` over `faces(tm)` creates them, so that the result is the
  /// sequential one, vertex numbering included.
  void scan_in_parallel(const Progress& progress)
  {
    const std::vector<std::uint32_t>& face_ids = input_.faces_in_scan_order();
    const std::size_t n = face_ids.size(), chunks = (n + parallel_chunk - 1) / parallel_chunk;
    std::vector<std::vector<Found>> found(chunks);
    in_reported_blocks(progress, chunks, 0.5, [&](std::size_t first, std::size_t last) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last), [&](const tbb::blocked_range<std::size_t>& range) {
        for(std::size_t c = range.begin(); c != range.end(); ++c)
          test_chunk(c, found[c]);
      });
    });
    for(std::size_t c = 0; c < chunks; ++c) {
      auto next = found[c].begin();
      for(std::size_t position = c * parallel_chunk; position < (std::min)(n, (c + 1) * parallel_chunk); ++position) {
        const std::uint32_t face_id = face_ids[position];
        for(; next != found[c].end() && next->position == position; ++next)
          vertices_.find_or_create(face_id, next->i, next->j, next->k, next->m, next->orientation, /*queue*/ true);
        border_.create_crossings_of(face_id);
      }
    }
  }
#endif

  /// Scans the faces reachable from `seed` across edges, nearest first, until one
  /// holding an intersection vertex is found. Returns false if there is none.
  bool seed_from(face_descriptor seed)
  {
    if(seed_marks_.empty())
      seed_marks_ = Zeroed_array<std::uint8_t>(num_faces(input_.mesh()));
    const std::uint32_t seed_id = input_.id_of(seed);
    std::deque<std::uint32_t> faces_to_scan(1, seed_id);
    std::vector<std::uint32_t> marked(1, seed_id);
    seed_marks_[seed_id] = 1;
    bool found = false;
    while(!faces_to_scan.empty() && !found) {
      const std::uint32_t f = faces_to_scan.front();
      faces_to_scan.pop_front();
      const std::size_t before = vertices_.number_queued();
      scan_face(input_.face_of_id(f));
      found = vertices_.number_queued() > before;
      for(std::uint32_t n : input_.record_of(f).neighbour)
        if(n != Input::border && !seed_marks_[n]) {
          seed_marks_[n] = 1;
          marked.push_back(n);
          faces_to_scan.push_back(n);
        }
    }
    if(!found) // the whole component was scanned: its border cycles are all uncrossed
      border_.count_border_cycles_of(marked);
    for(std::uint32_t f : marked)
      seed_marks_[f] = 0;
    return found;
  }

private:
  /// A vertex found by a task of the parallel scan, created later on this thread.
  struct Found
  {
    std::uint32_t position; // in faces(tm)
    std::int8_t i, j, orientation;
    std::int32_t k, m;
  };
  static constexpr std::size_t parallel_chunk = 1024; // faces per task: the merge needs the order

  /// The exact tests of the faces of chunk c of the parallel scan, which only reads the
  /// input: all mapped and recorded.
  void test_chunk(std::size_t c, std::vector<Found>& found) const
  {
    const std::vector<std::uint32_t>& face_ids = input_.faces_in_scan_order();
    const std::size_t n = face_ids.size();
    for(std::size_t position = c * parallel_chunk; position < (std::min)(n, (c + 1) * parallel_chunk); ++position) {
      const Triangle t = input_.load(face_ids[position]);
      const Crossed_levels levels = crossed_levels(t);
      if(levels.number_of_axes == 0)
        continue;
      account_for_crossings(levels, t.face_id);
      scan_crossed_levels(t, levels, [&](int i, int j, std::int32_t k, std::int32_t m, int o) {
        found.push_back({std::uint32_t(position), std::int8_t(i), std::int8_t(j), std::int8_t(o), k, m});
      });
    }
  }

  /// Finds every intersection vertex of the triangle and queues it. If it crosses a
  /// level, `before_scan(levels)` is told which before anything is built.
  template <class BeforeScan>
  void scan_triangle(const Triangle& t, const BeforeScan& before_scan)
  {
    const Crossed_levels levels = crossed_levels(t);
    if(levels.number_of_axes > 0) {
      before_scan(levels);
      account_for_crossings(levels, t.face_id);
      scan_crossed_levels(t, levels, [&](int i, int j, std::int32_t k, std::int32_t m, int o) {
        vertices_.find_or_create(t.face_id, i, j, k, m, o, /*queue*/ true);
      });
    }
    border_.create_crossings_of(t.face_id);
  }

  /// What every scan does with the levels a face crosses before its exact tests:
  /// refuses too many, and counts the pieces of arc the topology check expects.
  /// Writes only the face's own entry, so tasks of the parallel scan may call it.
  void account_for_crossings(const Crossed_levels& levels, std::uint32_t face_id) const
  {
    cap_.refuse_if_too_many_crossings(levels.hyperplanes, face_id);
    pieces_.add_crossed_hyperplanes(face_id, levels.hyperplanes);
  }

  /// Asked of every face. Only the axes in which the corners' ceilings differ have a
  /// crossed level; a face with none lies in one cell and holds no intersection vertex
  /// (many faces, and the more so the higher D). One comparison of the three arrays
  /// finds those axes (see Level_differences.h).
  static Crossed_levels crossed_levels(const Triangle& t)
  {
    Crossed_levels levels;
    for(std::uint32_t axes = level_differences(*t.c[0], *t.c[2], *t.c[1]); axes != 0; axes &= axes - 1) {
      const int q = lowest_set_bit(axes);
      levels.first[q] = lowest_ceiling(t, q);
      levels.last[q] = highest_ceiling(t, q) - 1;
      levels.hyperplanes += std::int64_t(levels.last[q]) + 1 - levels.first[q];
      levels.axes[levels.number_of_axes++] = q;
    }
    return levels;
  }

  /// The intersection vertices of the triangle: the grid edges {x_i = k, x_j = m}
  /// of the levels it strictly crosses, tested exactly. Calls
  /// `found(i, j, k, m, orientation)` for each, in a fixed order.
  template <class Found_vertex>
  void scan_crossed_levels(const Triangle& t, const Crossed_levels& levels, const Found_vertex& found) const
  {
    const Levels &first = levels.first, &last = levels.last;
    for(int a = 0; a < levels.number_of_axes; ++a)
      for(int b = a + 1; b < levels.number_of_axes; ++b) {
        const int i = levels.axes[a], j = levels.axes[b];
        for(std::int32_t k = first[i]; k <= last[i]; ++k) {
          // Only the lattice points near the column x_i = k of the projected triangle
          // are candidates: the work is proportional to its area, not its bounding box.
          std::int32_t m_first = first[j], m_last = last[j];
          column_range(t, i, j, k, m_first, m_last);
          for(std::int32_t m = m_first; m <= m_last; ++m) {
            const int o = predicates_.grid_edge_orientation(*t.p[0], *t.p[1], *t.p[2], i, j, double(k), double(m));
            if(o != 0)
              found(i, j, k, m, o);
          }
        }
      }
  }

  /// Narrows [m_first, m_last] to the levels of axis j near the segment where the
  /// line x_i = k meets the triangle projected on (i, j). Estimated in doubles and
  /// widened by one level: the exact test of each candidate decides.
  static void column_range(const Triangle& t, int i, int j, std::int32_t k, std::int32_t& m_first,
                           std::int32_t& m_last)
  {
    double low = infinity, high = -infinity;
    for(int e = 0; e < 3; ++e) {
      const auto& p = *t.p[e];
      const auto& q = *t.p[(e + 1) % 3];
      if((std::min)(p[i], q[i]) > k || (std::max)(p[i], q[i]) < k)
        continue;
      if(p[i] == q[i]) {
        low = (std::min)({low, p[j], q[j]});
        high = (std::max)({high, p[j], q[j]});
        continue;
      }
      const double y = p[j] + (double(k) - p[i]) / (q[i] - p[i]) * (q[j] - p[j]);
      low = (std::min)(low, y);
      high = (std::max)(high, y);
    }
    if(!(low <= high))
      return; // keep the bounding-box range
    const double margin = 1. + 1e-9 * (std::abs(low) + std::abs(high));
    m_first = (std::max)(m_first, std::int32_t(std::floor(low - margin)));
    m_last = (std::min)(m_last, std::int32_t(std::ceil(high + margin)));
  }

  Input& input_;
  Intersection_vertices<D>& vertices_;
  Border_crossings<Input>& border_;
  Untraced_pieces& pieces_;
  const Output_size_cap& cap_;
  const Predicates& predicates_;
  Zeroed_array<std::uint8_t> seed_marks_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_SCANNER_H
