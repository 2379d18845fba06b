// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_TOPOLOGY_CHECK_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_TOPOLOGY_CHECK_H

// Whether the primal remesh has the topology of its input, decided after a complete
// scan from the tracer's records and the traced complex.
//
// The grid cuts the surface M into vertices, open arcs, closed loops and open
// regions (the components of M inside the open cells). Counting Euler
// characteristics with compact support, chi(M) = V - E + sum over regions of
// chi_c(R) (a loop counts 0), while the traced complex has V - E + F with F the
// number of traced faces, one per boundary cycle. So
//     chi(M) - chi(traced) = sum over regions of (chi_c(R) - cycles(R)),
// and for a region with at least one boundary cycle chi_c(R) - cycles(R) =
// 2 - 2 genus - ends - cycles <= 0, zero exactly for a disk bounded by one cycle.
// Regions without a traced cycle are bounded by closed loops or are whole
// components, and are found directly. Hence the cheap test: no loop, no lost
// component, no hole inside a cell and chi(M) = chi(traced) mean every region is a
// disk, and then the output is a cell decomposition of M: the same topology.
//
// Only when it fails are the defects located, cell by cell (Cell_excess.h). The
// parts: the input's components and the pieces the output lacks (Lost_pieces.h),
// the cells a vertex, edge or face meets (Cell_incidence.h), the cells by id of every
// face (Face_cells.h), the excesses of the cells (Cell_excess.h); here, the decision
// and the report of the defects.

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Topology_defect.h>
#include <CGAL/Range_space_remeshing/internal/Cell_excess.h>
#include <CGAL/Range_space_remeshing/internal/Cell_incidence.h>
#include <CGAL/Range_space_remeshing/internal/Cell_index.h>
#include <CGAL/Range_space_remeshing/internal/Closed_loops.h>
#include <CGAL/Range_space_remeshing/internal/Face_cells.h>
#include <CGAL/Range_space_remeshing/internal/Lost_pieces.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Tracer, class FaceDescriptor>
class Topology_check
{
  using Input = typename Tracer::Input;
  using Levels = typename Tracer::Levels;
  using Defect = Topology_defect<FaceDescriptor>;
  using Excess = Cell_excess<Tracer>;
  using Cell_map = typename Excess::Cell_map;
  using Loop = Closed_loop_cells<Levels>;

public:
  Topology_check(Tracer& tracer, const Primal_complex& complex)
    : tracer_(tracer), input_(tracer.input()),
      closed_loops_(tracer.input(), tracer.untraced_pieces(), tracer.predicates()), complex_(complex),
      lost_(input_), incidence_(tracer, closed_loops_, lost_), face_cells_(input_, incidence_, lost_),
      excess_(tracer, complex, lost_, incidence_, face_cells_),
      number_of_faces_(std::uint32_t(input_.number_of_input_faces()))
  {}

  /// Fills the topology fields of `stats` and returns the defects found.
  std::vector<Defect> run(Statistics& stats, const Progress& progress)
  {
    progress_ = &progress;
    progress.report(Remeshing_stage::TOPOLOGY_CHECK, 0);
    stats.topology_checked = true;
    find_loops();
    progress.report(Remeshing_stage::TOPOLOGY_CHECK, 0.1);
    const long chi_of_kept_components = find_components(stats);
    progress.report(Remeshing_stage::TOPOLOGY_CHECK, 0.2);
    if(stats.uncrossed_border_cycles > 0) // the scan counted them: walk them for their faces
      find_lost_border_cycles();
    stats.input_euler_characteristic = lost_.input_euler_characteristic();
    stats.output_euler_characteristic = complex_.euler_characteristic();
    stats.output_components = complex_.number_of_components();
    const bool chi_matches = chi_of_kept_components == complex_.traced_euler_characteristic();
    if(defects_.empty() && chi_matches && !loops_.empty() && only_caps_cut_off(stats))
      return std::move(defects_);
    if(!defects_.empty() || !loops_.empty() || !chi_matches)
      locate_defects(chi_of_kept_components - complex_.traced_euler_characteristic(), stats);
    return std::move(defects_);
  }

private:
  template <class Faces>
  Defect& add_defect(Topology_defect_kind kind, const Levels& cell, const Faces& face_ids)
  {
    defects_.emplace_back();
    Defect& d = defects_.back();
    d.kind = kind;
    d.cell.assign(cell.begin(), cell.end());
    for(std::uint32_t f : face_ids)
      d.input_faces.push_back(input_.face_of_id(f));
    return d;
  }

  void find_loops()
  {
    closed_loops_.find(
        [&](int axis, std::int32_t level, const Levels& cell, const std::vector<std::uint32_t>& faces) {
          loops_.push_back(Loop{axis, cell, faces});
          loops_.back().cell[axis] = level;
        });
  }

  /// Loops only: if they all just cut caps off, counting their cells is enough (the
  /// other cells then have excess 0, the total being 0): no full count. Whether so;
  /// if not, the loops are left as they were.
  bool only_caps_cut_off(Statistics& stats)
  {
    Cell_map excess = excess_.count_in_cells_of_loops(loops_);
    stats.harmless_loops = absorb_caps(excess);
    if(stats.harmless_loops == loops_.size())
      return true;
    stats.harmless_loops = 0;
    for(Loop& loop : loops_)
      loop.harmless = false;
    return false;
  }

  /// Counts the excesses, reports the loops that are not harmless and the cells of
  /// nonzero excess. Without lost pieces, counting the suspect cells is enough if
  /// they make up the whole difference `total`; else every cell is counted.
  void locate_defects(long total, Statistics& stats)
  {
    Cell_map excess;
    const bool suspects_only = defects_.empty() && excess_.count_in_suspect_cells(loops_, total, excess);
    if(!suspects_only)
      excess = excess_.count_per_cell(*progress_);
    stats.harmless_loops = absorb_caps(excess);
    for(const Loop& loop : loops_)
      if(!loop.harmless) {
        add_defect(Topology_defect_kind::CLOSED_LOOP, loop.cell, loop.faces).axis = loop.axis;
        ++stats.closed_loops;
      }
    stats.non_disk_cells = suspects_only ? locate_non_disk_suspect_cells(excess) : locate_non_disk_cells(excess);
  }

  /// Labels the input components, reports those without output, and returns the
  /// Euler characteristic of the others.
  long find_components(Statistics& stats)
  {
    const long chi_kept = lost_.label_components(tracer_.intersection_vertices());
    stats.input_components = lost_.number_of_components();
    report_lost_components(stats);
    return chi_kept;
  }

  void report_lost_components(Statistics& stats)
  {
    std::vector<std::size_t> defect_of(lost_.number_of_components(), std::size_t(-1));
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      const std::uint32_t c = lost_.component_of(f);
      if(!lost_.is_lost_component(c))
        continue;
      if(defect_of[c] == std::size_t(-1)) {
        defect_of[c] = defects_.size();
        add_defect(Topology_defect_kind::LOST_COMPONENT, incidence_.cell_of_vertex(input_.corners_of(f)[0]),
                   std::vector<std::uint32_t>());
        ++stats.lost_components;
      }
      defects_[defect_of[c]].input_faces.push_back(input_.face_of_id(f));
    }
  }

  /// Border cycles whose vertices all lie in one cell (no hyperplane crosses them),
  /// in components that have an output.
  void find_lost_border_cycles()
  {
    lost_.for_each_border_cycle_in_one_cell([&](std::uint32_t f, int e, const std::vector<std::uint32_t>& faces) {
      add_defect(Topology_defect_kind::LOST_BORDER_CYCLE, incidence_.cell_of_vertex(input_.corners_of(f)[e]), faces);
    });
  }

  /// A closed loop whose two cells hold no other loop and have excesses +1 and -1
  /// only cuts a cap off: the +1 is a disk bounded by the loop alone (any other
  /// region bounded by it, or one with a traced cycle too, has an excess below 1,
  /// and the other regions of the cell at most 0), and gluing it across the loop
  /// makes the other cell's regions disks (their excesses, at most 0 each, then sum
  /// to 0). The output, which covers the loop by the face of the other cell, then
  /// has the input's topology. Marks those loops harmless, and their cells zero.
  std::size_t absorb_caps(Cell_map& excess)
  {
    std::unordered_map<Levels, int, Levels_hash<Levels>> loops_per_cell;
    for(const Loop& loop : loops_) {
      ++loops_per_cell[loop.cell];
      ++loops_per_cell[loop.cell_below()];
    }
    std::size_t harmless = 0;
    for(Loop& loop : loops_) {
      long& above = excess[loop.cell];
      long& below = excess[loop.cell_below()];
      if(loops_per_cell[loop.cell] == 1 && loops_per_cell[loop.cell_below()] == 1 && above + below == 0 &&
         (above == 1 || below == 1)) {
        above = below = 0;
        loop.harmless = true;
        ++harmless;
      }
    }
    return harmless;
  }

  /// Reports the cells of nonzero excess (in the order of their levels), with the
  /// faces meeting them; their number. Those cells have ids: count_per_cell() met them.
  std::size_t locate_non_disk_cells(const Cell_map& excess)
  {
    const std::vector<Levels> cells = add_non_disk_cells(excess);
    if(cells.empty())
      return 0;
    std::vector<std::size_t> defect_of_id(face_cells_.cell_index().size(), std::size_t(-1));
    for(std::size_t k = 0; k < cells.size(); ++k)
      defect_of_id[face_cells_.cell_index().id_of(cells[k])] = defects_.size() - cells.size() + k;
    Work_meter meter(*progress_, Remeshing_stage::TOPOLOGY_CHECK);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      const std::uint32_t begin = face_cells_.face_begin(f), end = face_cells_.face_end(f);
      meter.add(1 + end - begin, [&] { return 0.7 + 0.3 * f / number_of_faces_; });
      for(std::uint32_t x = begin; x < end; ++x) {
        const std::size_t d = defect_of_id[face_cells_.face_cell(x)];
        if(d != std::size_t(-1))
          defects_[d].input_faces.push_back(input_.face_of_id(f));
      }
    }
    return cells.size();
  }

  /// The same from the faces count_in_suspect_cells() found in each suspect cell:
  /// the cells of nonzero excess are among them.
  std::size_t locate_non_disk_suspect_cells(const Cell_map& excess)
  {
    const std::vector<Levels> cells = add_non_disk_cells(excess);
    for(std::size_t k = 0; k < cells.size(); ++k) {
      std::vector<std::uint32_t>& faces = excess_.faces_in_suspect_cell(cells[k]);
      std::sort(faces.begin(), faces.end()); // in face order, as a scan would list them
      Defect& d = defects_[defects_.size() - cells.size() + k];
      for(std::uint32_t f : faces)
        d.input_faces.push_back(input_.face_of_id(f));
    }
    return cells.size();
  }

  /// Adds a defect without faces for each cell of nonzero excess, in the order of
  /// their levels, and returns those cells in that order.
  std::vector<Levels> add_non_disk_cells(const Cell_map& excess)
  {
    std::vector<Levels> cells;
    for(const auto& entry : excess)
      if(entry.second != 0)
        cells.push_back(entry.first);
    std::sort(cells.begin(), cells.end());
    for(const Levels& c : cells)
      add_defect(Topology_defect_kind::NON_DISK_CELL, c, std::vector<std::uint32_t>());
    return cells;
  }

  const Progress* progress_ = &Progress::none();
  Tracer& tracer_;
  Input& input_;
  Closed_loops<Input> closed_loops_;
  const Primal_complex& complex_;
  Lost_pieces<Input> lost_;
  Cell_incidence<Tracer> incidence_;
  Face_cells<Tracer> face_cells_;
  Excess excess_;
  std::uint32_t number_of_faces_;
  std::vector<Loop> loops_;
  std::vector<Defect> defects_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_TOPOLOGY_CHECK_H
