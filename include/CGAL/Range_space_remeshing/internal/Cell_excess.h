// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_EXCESS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_EXCESS_H

// For the topology check (Topology_check.h): the excess of a cell c, chi_c(M inside
// c) - (traced faces in c), zero where the surface in c is a set of disks each
// bounded by one traced cycle. chi_c of M inside an open cell is #triangles - #edges
// + #vertices meeting it. Counted either for every cell at once, each face once, or
// for a few cells only (those of closed loops, or the suspect ones), by a flood from
// seed faces across the edges that meet the cell.

#include <CGAL/Range_space_remeshing/internal/Cell_incidence.h>
#include <CGAL/Range_space_remeshing/internal/Cell_index.h>
#include <CGAL/Range_space_remeshing/internal/Face_cells.h>
#include <CGAL/Range_space_remeshing/internal/Lost_pieces.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// A closed loop no arc traced, between two cells of the grid.
template <class Levels>
struct Closed_loop_cells
{
  int axis;
  Levels cell; // above the loop in `axis`
  std::vector<std::uint32_t> faces;
  bool harmless = false;

  Levels cell_below() const
  {
    Levels c = cell;
    --c[axis];
    return c;
  }
};

template <class Tracer>
class Cell_excess
{
  using Input = typename Tracer::Input;
  using Levels = typename Tracer::Levels;
  using Loop = Closed_loop_cells<Levels>;
  static constexpr std::uint32_t none = std::uint32_t(-1);
  static constexpr std::size_t unlimited = std::size_t(-1);

public:
  using Cell_map = std::unordered_map<Levels, long, Levels_hash<Levels>>;
  using Seeds = std::unordered_map<Levels, std::vector<std::uint32_t>, Levels_hash<Levels>>;

  Cell_excess(Tracer& tracer, const Primal_complex& complex, const Lost_pieces<Input>& lost,
              Cell_incidence<Tracer>& incidence, Face_cells<Tracer>& face_cells)
    : tracer_(tracer), input_(tracer.input()), complex_(complex), lost_(lost), incidence_(incidence),
      face_cells_(face_cells), number_of_faces_(std::uint32_t(input_.number_of_input_faces()))
  {}

  /// The excess of every cell, as a map of the cells where it is not zero.
  Cell_map count_per_cell(const Progress& progress)
  {
    face_cells_.index_cells();
    std::vector<long> excess(face_cells_.cell_index().size(), 0);
    Work_meter meter(progress, Remeshing_stage::TOPOLOGY_CHECK);
    count_faces_and_edges(excess, meter);
    for(std::uint32_t id : face_cells_.vertex_cells())
      if(id != none)
        ++excess[id];
    auto excess_of = [&](const Levels& c) -> long& {
      const std::uint32_t id = face_cells_.cell_index().id_of(c);
      if(id >= excess.size())
        excess.resize(id + 1, 0);
      return excess[id];
    };
    for(const auto& corner : complex_.traced_face_corners()) {
      meter.add(1, 0.7);
      --excess_of(incidence_.cell_of_traced_face(corner));
    }
    incidence_.add_border_pieces([&](const Levels& c) { ++excess_of(c); });
    Cell_map nonzero;
    for(std::uint32_t id = 0; id < excess.size(); ++id)
      if(excess[id] != 0)
        nonzero.emplace(face_cells_.cell_index().cell(id), excess[id]);
    return nonzero;
  }

  /// The excesses of the two cells of every loop, counted in those cells only.
  Cell_map count_in_cells_of_loops(const std::vector<Loop>& loops)
  {
    Seeds seeds = seeds_of_loops(loops);
    Cell_map excess;
    count_in_cells(seeds, unlimited, excess, nullptr);
    return excess;
  }

  /// The excesses of the suspect cells, in `excess`, and the faces meeting each, kept
  /// for `faces_in_suspect_cell()`; whether they add up to the total over all cells,
  /// chi(M) - chi(traced). Then the other cells, of excess 0 or below, are all 0.
  /// False too, without counting, when the suspect cells hold more than a third of
  /// the traced faces, or after visiting as many faces as the input has: a face
  /// meets many cells of a fine grid, and counting cell by cell would then cost
  /// more than the count of all cells, which takes each face once.
  bool count_in_suspect_cells(const std::vector<Loop>& loops, long total, Cell_map& excess)
  {
    std::size_t traced_in_suspects = 0;
    Seeds seeds = seeds_of_suspect_cells(loops, traced_in_suspects);
    if(3 * traced_in_suspects > complex_.traced_face_corners().size() ||
       !count_in_cells(seeds, number_of_faces_, excess, &faces_in_suspect_cells_))
      return false;
    long sum = 0;
    for(const auto& entry : excess)
      sum += entry.second;
    return sum == total;
  }

  /// The faces meeting suspect cell c, as count_in_suspect_cells() found them.
  std::vector<std::uint32_t>& faces_in_suspect_cell(const Levels& c) { return faces_in_suspect_cells_[c]; }

private:
  /// Adds each face to the cells it meets and takes each edge from the cells it
  /// meets, at the face that owns the edge.
  void count_faces_and_edges(std::vector<long>& excess, Work_meter& meter) const
  {
    std::vector<std::uint32_t> edge_cells;
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      const std::uint32_t begin = face_cells_.face_begin(f), end = face_cells_.face_end(f);
      meter.add(1 + end - begin, [&] { return 0.2 + 0.5 * f / number_of_faces_; });
      for(std::uint32_t x = begin; x < end; ++x)
        ++excess[face_cells_.face_cell(x)];
      if(lost_.is_lost(f))
        continue;
      for(int e = 0; e < 3; ++e)
        if(face_cells_.owns_edge(f, e)) {
          face_cells_.cells_of_owned_edge(f, e, edge_cells);
          for(std::uint32_t id : edge_cells)
            --excess[id];
        }
    }
  }

  /// The loops' faces, as seeds of both their cells.
  static Seeds seeds_of_loops(const std::vector<Loop>& loops)
  {
    Seeds seeds;
    for(const Loop& loop : loops) {
      auto& above = seeds[loop.cell];
      auto& below = seeds[loop.cell_below()];
      above.insert(above.end(), loop.faces.begin(), loop.faces.end());
      below.insert(below.end(), loop.faces.begin(), loop.faces.end());
    }
    return seeds;
  }

  /// The cells where a region may have excess above zero (those of loops) or may be
  /// bounded by several traced cycles (those of two traced faces or more): with no
  /// lost piece, every other cell holds regions bounded by one traced cycle each,
  /// of excess 0 (a disk) or below (a handle inside the cell).
  Seeds seeds_of_suspect_cells(const std::vector<Loop>& loops, std::size_t& traced_in_suspects) const
  {
    Seeds seeds = seeds_of_loops(loops);
    Cell_index<Levels> traced_cells;
    std::vector<std::uint32_t> traced_faces;
    for(const auto& corner : complex_.traced_face_corners()) {
      const Levels c = incidence_.cell_of_traced_face(corner);
      const std::uint32_t id = traced_cells.id_of(c);
      if(id == traced_faces.size())
        traced_faces.push_back(0);
      if(++traced_faces[id] == 2)
        seeds[c];
    }
    traced_in_suspects = 0;
    for(std::uint32_t n : traced_faces)
      traced_in_suspects += n >= 2 ? n : 0;
    return seeds;
  }

  /// Scratch of count_in_cell(): marks by face and by vertex, cleared after each cell.
  struct Flood
  {
    Flood(std::size_t faces, std::size_t vertices, std::size_t limit)
      : in_region(faces, 0), vertex_counted(vertices, 0), budget(limit)
    {}
    std::vector<std::uint8_t> in_region, vertex_counted;
    std::size_t budget; // faces left to visit
    std::vector<std::uint32_t> region, stack, counted_vertices;
  };

  /// The excesses of the seeded cells, from the input faces meeting them only: those
  /// reached from the seeds and the traced faces' vertices in them, across edges
  /// meeting the cell (a region is connected through them). Each region must hold a
  /// seed or bound a traced face of the cell. Lists the faces meeting each cell in
  /// `faces_meeting` if given. False if it stopped after visiting `budget` faces.
  bool count_in_cells(Seeds& seeds, std::size_t budget, Cell_map& excess, Seeds* faces_meeting)
  {
    incidence_.index_vertices_by_face();
    const auto& vertices = tracer_.intersection_vertices();
    for(const auto& corner : complex_.traced_face_corners()) {
      const auto found = seeds.find(incidence_.cell_of_traced_face(corner));
      if(found != seeds.end()) {
        found->second.push_back(vertices[corner.halfedge / 4].face_id);
        --excess[found->first];
      }
    }
    Flood flood(number_of_faces_, input_.number_of_input_vertices(), budget);
    for(auto& entry : seeds) {
      excess[entry.first] += count_in_cell(entry.first, entry.second, flood);
      if(flood.budget == 0)
        return false;
      if(faces_meeting)
        (*faces_meeting)[entry.first] = flood.region;
    }
    const Cell_map seeded = excess;
    incidence_.add_border_pieces([&](const Levels& c) {
      if(seeded.count(c))
        ++excess[c];
    });
    return true;
  }

  /// #faces - #edges + #vertices meeting cell c, over the faces reached from
  /// `seeds` (those meeting c) across edges meeting c; the faces in `flood.region`.
  long count_in_cell(const Levels& c, const std::vector<std::uint32_t>& seeds, Flood& flood) const
  {
    flood.region.clear();
    flood.counted_vertices.clear();
    for(std::uint32_t f : seeds)
      if(!flood.in_region[f] && incidence_.face_meets(f, c)) {
        flood.in_region[f] = 1;
        flood.stack.push_back(f);
      }
    long excess = 0;
    while(!flood.stack.empty()) {
      if(flood.budget == 0) { // give up; unmark the faces met
        flood.region.insert(flood.region.end(), flood.stack.begin(), flood.stack.end());
        flood.stack.clear();
        break;
      }
      --flood.budget;
      const std::uint32_t f = flood.stack.back();
      flood.stack.pop_back();
      flood.region.push_back(f);
      excess += count_face_in_cell(f, c, flood);
    }
    for(std::uint32_t f : flood.region)
      flood.in_region[f] = 0;
    for(std::uint32_t v : flood.counted_vertices)
      flood.vertex_counted[v] = 0;
    return excess;
  }

  /// Face f, reached by the flood in cell c: +1 for it, -1 for each of its edges
  /// meeting c (each edge once, both its faces meeting c), +1 for each of its corners
  /// in c not counted yet; pushes the neighbours across those edges.
  long count_face_in_cell(std::uint32_t f, const Levels& c, Flood& flood) const
  {
    long excess = 1;
    const auto& corners = input_.corners_of(f);
    for(int e = 0; e < 3; ++e) {
      if(!incidence_.edge_meets(corners[e], corners[(e + 1) % 3], c))
        continue;
      const std::uint32_t n = input_.neighbours_of(f)[e];
      if(n == Input::border || n > f)
        --excess;
      if(n != Input::border && !flood.in_region[n]) {
        flood.in_region[n] = 1;
        flood.stack.push_back(n);
      }
    }
    for(std::uint32_t v : corners)
      if(!flood.vertex_counted[v] && incidence_.vertex_in(v, c)) {
        flood.vertex_counted[v] = 1;
        flood.counted_vertices.push_back(v);
        ++excess;
      }
    return excess;
  }

  Tracer& tracer_;
  Input& input_;
  const Primal_complex& complex_;
  const Lost_pieces<Input>& lost_;
  Cell_incidence<Tracer>& incidence_;
  Face_cells<Tracer>& face_cells_;
  std::uint32_t number_of_faces_;
  Seeds faces_in_suspect_cells_; // by cell, when only those were counted
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_EXCESS_H
