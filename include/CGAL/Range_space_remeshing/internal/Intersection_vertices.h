// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_INTERSECTION_VERTICES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_INTERSECTION_VERTICES_H

// The vertices of the primal complex (sections 3-4 of the paper), what the scan and
// the tracing build and the output reads.
//
// An intersection vertex is a (triangle, grid edge {x_i = k, x_j = m}, i < j) pair;
// it has four arcs, stored in slots 0: +i, 1: +j, 2: -i, 3: -j, which is their
// counter-clockwise order on the surface when the triangle's orientation projected
// on (i, j) is positive, clockwise otherwise.
//
// On a surface with boundary (section 7 of the paper), an arc can also end where
// the input border crosses its hyperplane: a boundary vertex, keyed by (triangle,
// border edge of that triangle, hyperplane x_P = k). Its slots, in counter-clockwise
// order: 0 the boundary edge forward along the border (the interior on its left),
// 1 its one arc, 2 the boundary edge backward; slot 3 is unused. Where a border cycle
// has only two crossings, an input vertex between them becomes a boundary vertex too
// (a corner: no arc), since a polygon mesh cannot have a hole of two edges.
//
// Links are 4 * vertex + slot. Each vertex is created once, found by its key in a
// hash table, and queued for the tracing.

#include <CGAL/Range_space_remeshing/internal/Output_size_cap.h>
#include <CGAL/Range_space_remeshing/internal/Untraced_pieces.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_table.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

constexpr std::uint32_t no_link = std::uint32_t(-1);

template <int D>
struct Intersection_vertex
{
  std::uint32_t face_id;
  std::int8_t i, j;        // axes of the grid edge, i < j
  std::int8_t orientation; // sign of the triangle's orientation projected on (i, j)
  bool has_cell = false;
  std::int8_t border_edge = -1; // boundary vertex: its edge in the triangle (i = j = P)
  std::array<std::int32_t, D> cell; // lattice cell; cell[i] = k, cell[j] = m always
  std::array<std::uint32_t, 4> link = {{no_link, no_link, no_link, no_link}}; // 4*vertex+slot

  std::int32_t k() const { return cell[i]; }
  std::int32_t m() const { return cell[j]; }
  bool is_boundary() const { return border_edge >= 0; }
  /// a boundary vertex at an input vertex, added where a border cycle has only two
  /// crossings (a polygon mesh has no hole of two edges); i = j = -1, no arc
  bool is_corner() const { return border_edge >= 0 && i < 0; }
};

// slots of a boundary vertex
constexpr int forward_slot = 0, boundary_arc_slot = 1, backward_slot = 2;

template <int D>
class Intersection_vertices
{
public:
  using Vertex = Intersection_vertex<D>;

  /// `expected`: the table's first size (it grows); `pieces`: counts a piece more for
  /// each vertex created.
  Intersection_vertices(std::size_t expected, const Output_size_cap& cap, Untraced_pieces& pieces)
    : table_(expected), cap_(cap), pieces_(pieces)
  {}

  const std::vector<Vertex>& all() const { return vertices_; }
  std::size_t size() const { return vertices_.size(); }
  Vertex& operator[](std::uint32_t id) { return vertices_[id]; }
  const Vertex& operator[](std::uint32_t id) const { return vertices_[id]; }

  // ---------------------------------------------------------------- the queue
  bool has_queued() const { return !queue_.empty(); }
  std::size_t number_queued() const { return queue_.size(); }
  std::uint32_t pop_queued()
  {
    const std::uint32_t v = queue_.front();
    queue_.pop_front();
    return v;
  }

  // ---------------------------------------------------------------- creation
  /// The vertex of the grid edge {x_i = k, x_j = m} in the face, created (and queued
  /// if `queue`) if it is not there yet.
  std::uint32_t find_or_create(std::uint32_t face_id, int i, int j, std::int32_t k, std::int32_t m, int o, bool queue)
  {
    const Vertex_key key{face_id, i, j, k, m};
    bool inserted = false;
    const std::uint32_t id = table_.find_or_insert(key, std::uint32_t(vertices_.size()), key_of_id(), inserted);
    if(!inserted)
      return id;
    cap_.refuse_if_reached(vertices_.size());
    pieces_.add_vertex(face_id); // the vertex splits the segments of both its hyperplanes
    Vertex v;
    v.face_id = face_id;
    v.i = std::int8_t(i);
    v.j = std::int8_t(j);
    v.orientation = std::int8_t(o);
    v.cell[i] = k;
    v.cell[j] = m;
    vertices_.push_back(v);
    if(queue)
      queue_.push_back(id);
    return id;
  }

  /// Creates and queues the boundary vertex where border edge e of the face crosses
  /// x_P = level, in `cell`.
  std::uint32_t create_boundary(std::uint32_t face_id, int e, int P, std::int32_t level,
                                const std::array<std::int32_t, D>& cell)
  {
    bool inserted = false;
    const std::uint32_t id =
        table_.find_or_insert(boundary_key(face_id, e, P, level), std::uint32_t(vertices_.size()), key_of_id(), inserted);
    CGAL_assertion(inserted);
    cap_.refuse_if_reached(vertices_.size());
    Vertex v;
    v.face_id = face_id;
    v.i = v.j = std::int8_t(P);
    v.border_edge = std::int8_t(e);
    v.orientation = 1; // slots 0, 1, 2 counter-clockwise
    v.cell = cell;
    v.has_cell = true;
    vertices_.push_back(v);
    queue_.push_back(id);
    return id;
  }

  /// Adds a corner (see `Intersection_vertex::is_corner()`): not keyed, not queued.
  std::uint32_t add_corner(const Vertex& c)
  {
    const std::uint32_t id = std::uint32_t(vertices_.size());
    vertices_.push_back(c);
    return id;
  }

  // ---------------------------------------------------------------- lookup
  /// The vertex of the grid edge in the face, or `no_link`.
  std::uint32_t find(std::uint32_t face_id, int i, int j, std::int32_t k, std::int32_t m) const
  {
    return table_.find(Vertex_key{face_id, std::int8_t(i), std::int8_t(j), k, m}, key_of_id());
  }

  /// The boundary vertex of the face's border edge e on x_P = level, or `no_link`.
  std::uint32_t find_boundary(std::uint32_t face_id, int e, int P, std::int32_t level) const
  {
    return table_.find(boundary_key(face_id, e, P, level), key_of_id());
  }

  // ---------------------------------------------------------------- links
  void link(std::uint32_t v, int slot, std::uint32_t w, int w_slot)
  {
    if(vertices_[w].link[w_slot] != no_link)
      CGAL_error_msg("Range_space_remeshing: inconsistent boundary");
    vertices_[v].link[slot] = 4 * w + std::uint32_t(w_slot);
    vertices_[w].link[w_slot] = 4 * v + std::uint32_t(slot);
  }

  /// The vertex at the other end of the link in `slot` of v.
  std::uint32_t linked(std::uint32_t v, int slot) const { return vertices_[v].link[slot] / 4; }

private:
  auto key_of_id() const
  {
    return [this](std::uint32_t stored) { return key_of(vertices_[stored]); };
  }

  static Vertex_key key_of(const Vertex& v)
  {
    if(v.is_boundary())
      return boundary_key(v.face_id, v.border_edge, v.i, v.k());
    return {v.face_id, v.i, v.j, v.k(), v.m()};
  }

  static Vertex_key boundary_key(std::uint32_t face_id, int e, int P, std::int32_t level)
  {
    return {face_id, P, -1 - e, level, 0}; // j < 0: no grid-edge vertex has it
  }

  std::vector<Vertex> vertices_;
  Vertex_table table_;
  std::deque<std::uint32_t> queue_;
  Output_size_cap cap_;
  Untraced_pieces& pieces_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_INTERSECTION_VERTICES_H
