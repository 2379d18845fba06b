// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INCIDENCE_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INCIDENCE_H

// For the topology check (Topology_check.h): which open grid cells an input vertex,
// edge or face meets, and in which cell a traced face or a piece of the border lies.
// A triangle or an edge meets a convex cell in one convex piece, so the cells around
// a triangle are those where its corners lie, both sides of its edges' crossings and
// the four quadrants of its intersection vertices.

#include <CGAL/Range_space_remeshing/internal/Cell_index.h>
#include <CGAL/Range_space_remeshing/internal/Closed_loops.h>
#include <CGAL/Range_space_remeshing/internal/Lost_pieces.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Tracer>
class Cell_incidence
{
  using Input = typename Tracer::Input;
  static constexpr int D = Tracer::D;
  using Levels = typename Tracer::Levels;

public:
  Cell_incidence(Tracer& tracer, const Closed_loops<Input>& closed_loops, const Lost_pieces<Input>& lost)
    : tracer_(tracer), input_(tracer.input()), closed_loops_(closed_loops), lost_(lost),
      number_of_faces_(std::uint32_t(input_.number_of_input_faces()))
  {}

  bool same_ceiling(std::uint32_t v, std::uint32_t w) const
  {
    return same_levels(input_.ceiling_of(v), input_.ceiling_of(w));
  }

  Levels cell_of_vertex(std::uint32_t v) const
  {
    Levels c = input_.ceiling_of(v);
    for(std::int32_t& x : c)
      --x; // a coordinate on a level counts as below it
    return c;
  }

  /// The cell of the point where the edge from vertex a to vertex b crosses
  /// x_P = level (cell[P] = level): the cell above the crossing.
  Levels cell_of_edge_crossing(std::uint32_t a, std::uint32_t b, int P, std::int32_t level) const
  {
    return closed_loops_.cell_of_edge_crossing(a, b, P, level);
  }

  /// Whether vertex v lies in cell c.
  bool vertex_in(std::uint32_t v, const Levels& c) const
  {
    const Levels& ceiling = input_.ceiling_of(v);
    for(int P = 0; P < D; ++P)
      if(ceiling[P] != c[P] + 1) // a coordinate on a level counts as below it
        return false;
    return true;
  }

  /// Whether the closed edge from vertex a to vertex b meets cell c: at an end, or
  /// where it crosses one of the two hyperplanes bounding c in some axis (the cells
  /// of its other crossings differ from c in that axis).
  bool edge_meets(std::uint32_t a, std::uint32_t b, const Levels& c) const
  {
    if(vertex_in(a, c) || vertex_in(b, c))
      return true;
    const Levels &ca = input_.ceiling_of(a), &cb = input_.ceiling_of(b);
    for(int P = 0; P < D; ++P)
      for(std::int32_t level = c[P]; level <= c[P] + 1; ++level) {
        if(level < (std::min)(ca[P], cb[P]) || level >= (std::max)(ca[P], cb[P]))
          continue;
        Levels x = closed_loops_.cell_of_edge_crossing(a, b, P, level);
        x[P] = c[P]; // the cell above the crossing, or below it
        if(same_levels(x, c))
          return true;
      }
    return false;
  }

  /// Whether face f meets cell c: along an edge, or around one of its intersection
  /// vertices.
  bool face_meets(std::uint32_t f, const Levels& c) const
  {
    const auto& corners = input_.corners_of(f);
    for(int e = 0; e < 3; ++e)
      if(edge_meets(corners[e], corners[(e + 1) % 3], c))
        return true;
    bool around_vertex = false;
    for_each_cell_around_vertices_of(f, [&](const Levels& x) { around_vertex = around_vertex || same_levels(x, c); });
    return around_vertex;
  }

  /// Whether face f lies in one cell: its corners do and no hyperplane crosses it.
  bool is_in_one_cell(std::uint32_t f) const
  {
    const auto& corners = input_.corners_of(f);
    return vertex_start_[f] == vertex_start_[f + 1] && same_ceiling(corners[0], corners[1]) &&
           same_ceiling(corners[0], corners[2]);
  }

  /// Calls `add(cell)` for the four cells around each intersection vertex of face f.
  template <class Add>
  void for_each_cell_around_vertices_of(std::uint32_t f, const Add& add) const
  {
    const auto& vertices = tracer_.intersection_vertices();
    for(std::uint32_t x = vertex_start_[f]; x < vertex_start_[f + 1]; ++x) {
      const auto& v = vertices[vertices_by_face_[x]];
      for(int quadrant = 0; quadrant < 4; ++quadrant) {
        Levels c = v.cell;
        c[v.i] -= quadrant & 1;
        c[v.j] -= quadrant >> 1;
        add(c);
      }
    }
  }

  /// The counts of M inside a cell take it with its border: a region that reaches
  /// the border has, for each open border piece between two boundary vertices in
  /// it, -1 in chi_c (a half-open disk has chi_c = 0). Calls `add(cell)` for each
  /// piece, so that such a disk has excess 0 too.
  template <class Add>
  void add_border_pieces(const Add& add) const
  {
    for(const auto& v : tracer_.intersection_vertices())
      if(v.is_boundary() && !v.is_corner() && !lost_.is_lost(v.face_id))
        add(cell_ahead(v));
  }

  /// The cell of a traced face, from the sector it fills at one of its vertices.
  Levels cell_of_traced_face(const Primal_complex::Traced_face_corner& corner) const
  {
    const auto& v = tracer_.intersection_vertices()[corner.halfedge / 4];
    const std::uint32_t s = corner.halfedge % 4, t = corner.next_slot;
    Levels c = v.cell;
    if(v.is_corner())
      return c;
    if(v.is_boundary()) {
      // between the forward boundary edge and the arc (slots 0 -> 1): the forward
      // side; between the arc and the backward edge: the other
      c = cell_ahead(v);
      if(s != 0)
        c[v.i] += c[v.i] == v.k() ? -1 : 1;
      return c;
    }
    const std::uint32_t along_i = (s % 2 == 0) ? s : t, along_j = (s % 2 == 0) ? t : s;
    c[v.i] = v.k() - (along_i == 0 ? 0 : 1); // slot 0 is +i, 2 is -i
    c[v.j] = v.m() - (along_j == 1 ? 0 : 1); // slot 1 is +j, 3 is -j
    return c;
  }

  /// Lists the intersection vertices inside each face, once.
  void index_vertices_by_face()
  {
    if(!vertex_start_.empty())
      return; // indexed already (the loops' cells were counted first)
    const auto& vertices = tracer_.intersection_vertices();
    vertex_start_.assign(std::size_t(number_of_faces_) + 1, 0);
    for(const auto& v : vertices)
      if(!v.is_boundary())
        ++vertex_start_[v.face_id + 1];
    for(std::uint32_t f = 0; f < number_of_faces_; ++f)
      vertex_start_[f + 1] += vertex_start_[f];
    vertices_by_face_.resize(vertex_start_.back());
    std::vector<std::uint32_t> next(vertex_start_.begin(), vertex_start_.end() - 1);
    for(std::uint32_t x = 0; x < vertices.size(); ++x)
      if(!vertices[x].is_boundary())
        vertices_by_face_[next[vertices[x].face_id]++] = x;
  }

private:
  /// The cell of the border piece that starts at boundary vertex v going forward:
  /// on the side of its hyperplane where the border edge ends.
  template <class Vertex>
  Levels cell_ahead(const Vertex& v) const
  {
    Levels c = v.cell;
    const std::uint32_t end = input_.corners_of(v.face_id)[(v.border_edge + 1) % 3];
    c[v.i] = v.k() - (input_.ceiling_of(end)[v.i] > v.k() ? 0 : 1);
    return c;
  }

  Tracer& tracer_;
  Input& input_;
  const Closed_loops<Input>& closed_loops_;
  const Lost_pieces<Input>& lost_;
  std::uint32_t number_of_faces_;
  std::vector<std::uint32_t> vertex_start_, vertices_by_face_; // intersection vertices by face
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_INCIDENCE_H
