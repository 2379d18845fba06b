// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_FACE_CELLS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_FACE_CELLS_H

// For the topology check (Topology_check.h): dense ids for the cells that faces of
// kept components meet, and by id the cells of every such vertex, edge and face, for
// the count of the surface cell by cell. The cells where an edge crosses the grid
// are found once (an exact search each), at the face that owns the edge.

#include <CGAL/Range_space_remeshing/internal/Cell_incidence.h>
#include <CGAL/Range_space_remeshing/internal/Cell_index.h>
#include <CGAL/Range_space_remeshing/internal/Lost_pieces.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Lists of cells (their levels or their ids) that keep each cell once.
template <class Levels>
struct Cell_lists
{
  /// A list keeps each cell once by a search per insertion up to this size; past it,
  /// repeats are let in and removed once, by `remove_repeats()`. A face of a fine
  /// grid (the Gauss map at a crease) meets very many cells: a search per insertion
  /// would make that quadratic, and a sort of every list would slow down the common
  /// case, a face in a cell or two.
  static constexpr std::size_t searched_cells = 16;

  /// Appends x to the part of `list` from `from` on, where not there yet; a long part
  /// may hold repeats until `remove_repeats()`.
  template <class T>
  static void add_once(std::vector<T>& list, const T& x, std::size_t from = 0)
  {
    if(list.size() - from > searched_cells ||
       std::find_if(list.begin() + from, list.end(), [&](const T& y) { return same(y, x); }) == list.end())
      list.push_back(x);
  }

  template <class T>
  static void add_each_once(const T* begin, const T* end, std::vector<T>& list, std::size_t from)
  {
    for(; begin != end; ++begin)
      add_once(list, *begin, from);
  }

  template <class T>
  static void remove_repeats(std::vector<T>& list, std::size_t from = 0)
  {
    if(list.size() - from <= searched_cells)
      return;
    std::sort(list.begin() + from, list.end());
    list.erase(std::unique(list.begin() + from, list.end()), list.end());
  }

private:
  static bool same(std::uint32_t a, std::uint32_t b) { return a == b; }
  static bool same(const Levels& a, const Levels& b) { return same_levels(a, b); }
};

template <class Tracer>
class Face_cells
{
  using Input = typename Tracer::Input;
  static constexpr int D = Tracer::D;
  using Levels = typename Tracer::Levels;
  using Lists = Cell_lists<Levels>;
  static constexpr std::uint32_t none = std::uint32_t(-1);

public:
  Face_cells(Input& input, Cell_incidence<Tracer>& incidence, const Lost_pieces<Input>& lost)
    : input_(input), incidence_(incidence), lost_(lost),
      number_of_faces_(std::uint32_t(input.number_of_input_faces()))
  {}

  /// Gives the cells ids and lists them by vertex, by edge and by face.
  void index_cells()
  {
    incidence_.index_vertices_by_face();
    index_vertex_cells();
    index_edge_crossings();
    index_face_cells();
  }

  const Cell_index<Levels>& cell_index() const { return cell_index_; }
  Cell_index<Levels>& cell_index() { return cell_index_; }

  /// The cell id of each input vertex (`none` in lost components).
  const std::vector<std::uint32_t>& vertex_cells() const { return vertex_cell_; }

  /// The ids of the cells face f meets, from `face_begin(f)` to `face_end(f)`.
  std::uint32_t face_begin(std::uint32_t f) const { return face_start_[f]; }
  std::uint32_t face_end(std::uint32_t f) const { return face_start_[f + 1]; }
  std::uint32_t face_cell(std::uint32_t x) const { return face_cells_[x]; }

  /// Whether edge e of face f is counted at f (each edge is, at one face).
  bool owns_edge(std::uint32_t f, int e) const
  {
    const std::uint32_t n = input_.neighbours_of(f)[e];
    return n == Input::border || n > f;
  }

  /// Sets `cells` to the ids of the cells the closed edge e of face f meets, which f owns.
  void cells_of_owned_edge(std::uint32_t f, int e, std::vector<std::uint32_t>& cells) const
  {
    const auto& corners = input_.corners_of(f);
    cells.clear();
    Lists::add_once(cells, vertex_cell_[corners[e]]);
    Lists::add_once(cells, vertex_cell_[corners[(e + 1) % 3]]);
    Lists::add_each_once(crossings_begin(3 * std::size_t(f) + e), crossings_end(3 * std::size_t(f) + e), cells, 0);
    Lists::remove_repeats(cells);
  }

private:
  /// A vertex takes the id of a corner of the same face in the same cell where one
  /// has an id already (most do): a comparison instead of a hash.
  void index_vertex_cells()
  {
    vertex_cell_.assign(input_.number_of_input_vertices(), none);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      if(lost_.is_lost(f))
        continue;
      const auto& corners = input_.corners_of(f);
      for(int k = 0; k < 3; ++k) {
        const std::uint32_t v = corners[k];
        if(vertex_cell_[v] != none)
          continue;
        for(int other = 1; other < 3 && vertex_cell_[v] == none; ++other) {
          const std::uint32_t w = corners[(k + other) % 3];
          if(vertex_cell_[w] != none && incidence_.same_ceiling(w, v))
            vertex_cell_[v] = vertex_cell_[w];
        }
        if(vertex_cell_[v] == none)
          vertex_cell_[v] = cell_index_.id_of(incidence_.cell_of_vertex(v));
      }
    }
  }

  void index_edge_crossings()
  {
    crossing_start_.assign(3 * std::size_t(number_of_faces_) + 1, 0);
    crossing_cells_.clear();
    std::vector<Levels> cells;
    for(std::uint32_t f = 0; f < number_of_faces_; ++f)
      for(int e = 0; e < 3; ++e) {
        crossing_start_[3 * f + e] = std::uint32_t(crossing_cells_.size());
        if(lost_.is_lost(f) || !owns_edge(f, e))
          continue;
        const std::uint32_t a = input_.corners_of(f)[e], b = input_.corners_of(f)[(e + 1) % 3];
        if(incidence_.same_ceiling(a, b))
          continue; // no crossing
        cells.clear();
        add_crossing_cells(a, b, cells);
        Lists::remove_repeats(cells);
        const Levels cell_a = incidence_.cell_of_vertex(a), cell_b = incidence_.cell_of_vertex(b);
        for(const Levels& c : cells) // the ends' cells are listed with the ends
          if(!same_levels(c, cell_a) && !same_levels(c, cell_b))
            crossing_cells_.push_back(cell_index_.id_of(c));
      }
    crossing_start_.back() = std::uint32_t(crossing_cells_.size());
  }

  /// Adds the cells the open edge from vertex a to vertex b meets, but for its ends';
  /// long lists may hold repeats until the caller runs `remove_repeats()`.
  void add_crossing_cells(std::uint32_t a, std::uint32_t b, std::vector<Levels>& cells) const
  {
    const Levels &ca = input_.ceiling_of(a), &cb = input_.ceiling_of(b);
    for(int P = 0; P < D; ++P)
      for(std::int32_t level = (std::min)(ca[P], cb[P]); level < (std::max)(ca[P], cb[P]); ++level) {
        Levels c = incidence_.cell_of_edge_crossing(a, b, P, level);
        Lists::add_once(cells, c);
        --c[P];
        Lists::add_once(cells, c);
      }
  }

  /// Where the crossings of edge e of face f are listed: at the face owning the edge.
  std::size_t crossing_slot(std::uint32_t f, int e) const
  {
    if(owns_edge(f, e))
      return 3 * std::size_t(f) + e;
    const std::uint32_t n = input_.neighbours_of(f)[e];
    const std::uint32_t a = input_.corners_of(f)[e], b = input_.corners_of(f)[(e + 1) % 3];
    const auto& corners = input_.corners_of(n);
    for(int k = 0; k < 3; ++k) {
      const std::uint32_t p = corners[k], q = corners[(k + 1) % 3];
      if(input_.neighbours_of(n)[k] == f && ((p == a && q == b) || (p == b && q == a)))
        return 3 * std::size_t(n) + k;
    }
    CGAL_error_msg("Range_space_remeshing: an edge without its twin");
    return 0;
  }

  const std::uint32_t* crossings_begin(std::size_t slot) const { return crossing_cells_.data() + crossing_start_[slot]; }
  const std::uint32_t* crossings_end(std::size_t slot) const { return crossing_cells_.data() + crossing_start_[slot + 1]; }

  /// The cells a face meets: its corners', its edges' crossings', and the four
  /// around each of its intersection vertices.
  void index_face_cells()
  {
    face_start_.assign(std::size_t(number_of_faces_) + 1, 0);
    face_cells_.clear();
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      const std::size_t from = face_cells_.size();
      face_start_[f] = std::uint32_t(from);
      if(lost_.is_lost(f))
        continue;
      if(incidence_.is_in_one_cell(f))
        face_cells_.push_back(vertex_cell_[input_.corners_of(f)[0]]);
      else
        add_cells_of_face(f, from);
    }
    face_start_.back() = std::uint32_t(face_cells_.size());
  }

  /// Appends the cells face f meets, not in one cell, to `face_cells_` from `from` on.
  void add_cells_of_face(std::uint32_t f, std::size_t from)
  {
    const auto& corners = input_.corners_of(f);
    for(std::uint32_t v : corners)
      Lists::add_once(face_cells_, vertex_cell_[v], from);
    for(int e = 0; e < 3; ++e) {
      if(incidence_.same_ceiling(corners[e], corners[(e + 1) % 3]))
        continue; // no crossing: no need to find the twin that lists them
      const std::size_t slot = crossing_slot(f, e);
      Lists::add_each_once(crossings_begin(slot), crossings_end(slot), face_cells_, from);
    }
    incidence_.for_each_cell_around_vertices_of(f, [&](const Levels& c) {
      const std::uint32_t id = cell_index_.id_of(c);
      Lists::add_once(face_cells_, id, from);
    });
    Lists::remove_repeats(face_cells_, from);
  }

  Input& input_;
  Cell_incidence<Tracer>& incidence_;
  const Lost_pieces<Input>& lost_;
  std::uint32_t number_of_faces_;
  Cell_index<Levels> cell_index_;
  std::vector<std::uint32_t> vertex_cell_;                     // cell id by input vertex
  std::vector<std::uint32_t> crossing_start_, crossing_cells_; // by slot 3 face + edge, at the owning face
  std::vector<std::uint32_t> face_start_, face_cells_;         // cell ids by face
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_FACE_CELLS_H
