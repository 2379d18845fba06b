// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_BORDER_CROSSINGS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_BORDER_CROSSINGS_H

// The input border (section 7 of the paper): the boundary vertices where it crosses
// grid hyperplanes (see Intersection_vertices.h), made per border edge on first
// request and sorted along it; the boundary edges between consecutive ones along a
// border cycle; the corners that keep a cycle of two crossings from becoming a hole
// of two edges; and the border cycles no hyperplane crosses, which the output does
// not have (a hole inside one cell is covered by the face of that cell).

#include <CGAL/Range_space_remeshing/internal/Intersection_vertices.h>
#include <CGAL/Range_space_remeshing/internal/Lattice.h>
#include <CGAL/Range_space_remeshing/internal/Lazily_zeroed_array.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Input>
class Border_crossings
{
  static constexpr int D = Input::D;
  using Point_d = typename Input::Point_d;
  using Levels = typename Input::Levels;
  using Vertex = Intersection_vertex<D>;
  using Predicates = Perturbed_predicates<typename Input::Traits>;
  using halfedge_descriptor = typename Input::halfedge_descriptor;

  struct Border_edge
  {
    std::uint32_t face_id;
    int e; // edge vertex e -> vertex e+1 of the face record, its opposite a border
  };

public:
  Border_crossings(Input& input, Intersection_vertices<D>& vertices, const Predicates& predicates)
    : input_(input), vertices_(vertices), predicates_(predicates)
  {}

  /// The boundary vertices of border edge e of a face, in order along the edge
  /// (the face's counter-clockwise direction); created, and queued, on first request.
  const std::vector<std::uint32_t>& crossings(std::uint32_t face_id, int e)
  {
    const std::uint64_t key = border_key({face_id, e});
    const auto found = crossings_.find(key);
    if(found != crossings_.end())
      return found->second;
    const auto t = input_.load(face_id);
    const Point_d &a = *t.p[e], &b = *t.p[(e + 1) % 3];
    const Levels &ca = *t.c[e], &cb = *t.c[(e + 1) % 3];
    std::vector<std::uint32_t> ids;
    for(int P = 0; P < D; ++P) // levels strictly crossed, as in the scan
      for(std::int32_t level = (std::min)(ca[P], cb[P]); level < (std::max)(ca[P], cb[P]); ++level)
        ids.push_back(vertices_.create_boundary(face_id, e, P, level, cell_of_crossing<D>(predicates_, a, b, P, level)));
    std::sort(ids.begin(), ids.end(), [&](std::uint32_t x, std::uint32_t y) {
      return comes_first_along_edge(a, b, vertices_[x], vertices_[y]);
    });
    return crossings_.emplace(key, std::move(ids)).first->second;
  }

  /// Creates the boundary vertices on the border edges of a face, if it has any.
  void create_crossings_of(std::uint32_t face_id)
  {
    for(int e = 0; e < 3; ++e)
      if(input_.record_of(face_id).neighbour[e] == Input::border)
        crossings(face_id, e);
  }

  /// Links the boundary vertex v to its neighbours along the border, where not yet.
  void link_along_border(std::uint32_t v)
  {
    if(vertices_[v].link[forward_slot] == no_link)
      vertices_.link(v, forward_slot, neighbour_along_border(v, +1), backward_slot);
    if(vertices_[v].link[backward_slot] == no_link)
      vertices_.link(v, backward_slot, neighbour_along_border(v, -1), forward_slot);
  }

  /// Where a border cycle has two boundary vertices a, b only, inserts after a the
  /// input vertex that ends a's border edge, taking a whose forward neighbour b is
  /// not further along the same edge: that vertex is then between a and b.
  void add_corners_to_two_vertex_holes()
  {
    const std::size_t n = vertices_.size();
    for(std::uint32_t a = 0; a < n; ++a) {
      if(!vertices_[a].is_boundary())
        continue;
      const std::uint32_t b = vertices_.linked(a, forward_slot);
      if(b < a || vertices_.linked(b, forward_slot) != a)
        continue; // not a cycle of two, or seen from b already
      const auto& here = crossings(vertices_[a].face_id, vertices_[a].border_edge);
      const bool b_after_a_on_its_edge =
          std::find(std::find(here.begin(), here.end(), a), here.end(), b) != here.end();
      insert_corner_after(b_after_a_on_its_edge ? b : a);
    }
  }

  /// Number of border cycles of the input that no grid hyperplane crosses: they have
  /// no boundary vertex, so the output does not have them. Meaningful after a
  /// complete scan only.
  std::size_t number_of_uncrossed_border_cycles()
  {
    const auto& tm = input_.mesh();
    std::vector<std::uint8_t> walked(3 * num_faces(tm), 0); // by border_key()
    std::size_t uncrossed = 0;
    for(halfedge_descriptor b : halfedges(tm)) {
      if(!is_border(b, tm) || walked[border_key(border_edge_of(opposite(b, tm)))])
        continue;
      bool crossed = false;
      walk_border_cycle(b, walked, [&](std::uint64_t key) {
        const auto found = crossings_.find(key);
        crossed = crossed || (found != crossings_.end() && !found->second.empty());
      });
      uncrossed += crossed ? 0 : 1;
    }
    return uncrossed;
  }

  /// Counts the border cycles of a component in which the seeded scan found nothing:
  /// all uncrossed (the seeded mode cannot tell for the others).
  void count_border_cycles_of(const std::vector<std::uint32_t>& faces_of_component)
  {
    const auto& tm = input_.mesh();
    if(walked_border_.empty())
      walked_border_ = Zeroed_array<std::uint8_t>(3 * num_faces(tm)); // once: by border_key()
    for(std::uint32_t f : faces_of_component)
      for(int e = 0; e < 3; ++e) {
        if(input_.record_of(f).neighbour[e] != Input::border || walked_border_[border_key({f, e})])
          continue;
        ++border_cycles_of_empty_components_;
        walk_border_cycle(opposite(input_.halfedge_of(f, e), tm), walked_border_, [](std::uint64_t) {});
      }
  }

  std::size_t number_of_border_cycles_of_empty_components() const { return border_cycles_of_empty_components_; }
  /// Number of corners added (see `Intersection_vertex::is_corner()`).
  std::size_t number_of_corners() const { return number_of_corners_; }

private:
  static std::uint64_t border_key(const Border_edge& b) { return 3 * std::uint64_t(b.face_id) + b.e; }

  /// Walks the border cycle of the border halfedge `b`: marks each of its edges in
  /// `walked` (by border_key()), so that the cycle is walked once, and shows its key
  /// to `visit`. The one walk of a whole border cycle of the input.
  template <class Walked, class Visit>
  void walk_border_cycle(halfedge_descriptor b, Walked& walked, const Visit& visit)
  {
    const auto& tm = input_.mesh();
    for(halfedge_descriptor c : CGAL::halfedges_around_face(b, tm)) {
      const std::uint64_t key = border_key(border_edge_of(opposite(c, tm)));
      walked[key] = 1;
      visit(key);
    }
  }

  Border_edge border_edge_of(halfedge_descriptor h)
  {
    const auto& tm = input_.mesh();
    const auto f = face(h, tm);
    const std::uint32_t face_id = input_.id_of(f);
    int e = 0;
    for(halfedge_descriptor g = halfedge(f, tm); g != h; g = next(g, tm))
      ++e;
    return {face_id, e};
  }

  /// The next border edge along the border, forward (direction > 0: the direction
  /// of the face's edge) or backward, turning around the shared input vertex.
  Border_edge next_border_edge(const Border_edge& b, int direction)
  {
    const auto& tm = input_.mesh();
    halfedge_descriptor g = input_.halfedge_of(b.face_id, b.e);
    if(direction > 0) {
      g = next(g, tm);
      while(!is_border(opposite(g, tm), tm))
        g = next(opposite(g, tm), tm);
    } else {
      g = prev(g, tm);
      while(!is_border(opposite(g, tm), tm))
        g = prev(opposite(g, tm), tm);
    }
    return border_edge_of(g);
  }

  /// Of two crossings of edge ab with hyperplanes, is x met first going from a to b?
  bool comes_first_along_edge(const Point_d& a, const Point_d& b, const Vertex& x, const Vertex& y) const
  {
    if(x.i == y.i)
      return (x.k() < y.k()) == (a[x.i] < b[x.i]);
    // side of x's crossing point relative to y's hyperplane, against the direction
    // in which the edge crosses that hyperplane
    const int side_of_x = predicates_.crossing_side(a, b, x.i, double(x.k()), y.i, double(y.k()));
    return side_of_x != (a[y.i] < b[y.i] ? 1 : -1);
  }

  /// The boundary vertex next to v along the input border (direction +1: forward).
  std::uint32_t neighbour_along_border(std::uint32_t v, int direction)
  {
    Border_edge b{vertices_[v].face_id, vertices_[v].border_edge};
    const std::vector<std::uint32_t>& here = crossings(b.face_id, b.e);
    const std::size_t at = std::size_t(std::find(here.begin(), here.end(), v) - here.begin());
    CGAL_assertion(at < here.size());
    if(direction > 0 && at + 1 < here.size())
      return here[at + 1];
    if(direction < 0 && at > 0)
      return here[at - 1];
    // the border cycle holds v, so the walk ends at the latest back on v's edge
    for(std::size_t step = 0; step <= 3 * num_faces(input_.mesh()); ++step) {
      b = next_border_edge(b, direction);
      const std::vector<std::uint32_t>& next_crossings = crossings(b.face_id, b.e);
      if(!next_crossings.empty())
        return direction > 0 ? next_crossings.front() : next_crossings.back();
    }
    CGAL_error_msg("Range_space_remeshing: endless border");
  }

  void insert_corner_after(std::uint32_t a)
  {
    const std::uint32_t b = vertices_.linked(a, forward_slot);
    Vertex c;
    c.face_id = vertices_[a].face_id;
    c.border_edge = vertices_[a].border_edge;
    c.i = c.j = -1;
    c.orientation = 1;
    const auto t = input_.load(c.face_id);
    const Levels& ceiling = *t.c[(c.border_edge + 1) % 3];
    for(int q = 0; q < D; ++q)
      c.cell[q] = ceiling[q] - 1; // a coordinate on a level counts as below it
    c.has_cell = true;
    const std::uint32_t id = vertices_.add_corner(c);
    vertices_[a].link[forward_slot] = vertices_[b].link[backward_slot] = no_link;
    vertices_.link(a, forward_slot, id, backward_slot);
    vertices_.link(id, forward_slot, b, backward_slot);
    ++number_of_corners_;
  }

  Input& input_;
  Intersection_vertices<D>& vertices_;
  const Predicates& predicates_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> crossings_; // by border_key()
  std::size_t number_of_corners_ = 0;
  Zeroed_array<std::uint8_t> walked_border_; // by border_key(), for empty components
  std::size_t border_cycles_of_empty_components_ = 0;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_BORDER_CROSSINGS_H
