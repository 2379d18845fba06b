// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_COMPLEX_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_COMPLEX_H

// Faces of the primal remesh from the rotation system alone, no geometry.
//
// Halfedge 4*v+s leaves intersection vertex v by its slot s; its twin is the link
// the tracer stored. The counter-clockwise order of the slots around v is 0,1,2,3
// when the vertex's projected orientation is positive, 3,2,1,0 otherwise. A face is
// an orbit of next(h) = the outgoing halfedge at target(h) just before twin(h) in
// counter-clockwise order; faces then have the input's orientation.
//
// A boundary vertex (where an arc meets the input border) has three slots, counter-
// clockwise: 0 the boundary edge forward, 1 its arc, 2 the boundary edge backward.
// The orbits of the backward boundary halfedges are the holes: their halfedges are
// the border halfedges of the output (no face).
//
// Faces a polygon mesh cannot hold are repaired, and counted:
// * a digon (two vertices joined by two arcs around one face) has its two arcs
//   merged into one edge; the two vertices get valence 3, V - E + F is unchanged;
// * a face whose boundary visits a vertex twice is split by a chord across the pinch;
// * a piece that still has a face of degree below 3 is dropped.
// Parallel edges (two edges joining the same two vertices, around a part of the
// surface thinner than a cell) are kept, as a halfedge mesh can hold them; they are
// counted and listed, for a face-list file cannot (it would read them back as one
// edge): the output splits them (Primal_output.h).

#include <CGAL/Range_space_remeshing/internal/Union_find.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

class Primal_complex
{
public:
  struct Halfedge
  {
    std::uint32_t target;
    std::uint32_t twin;
    std::uint32_t next;
    std::uint32_t face;
  };

  /// `links[4*v+s]` is the twin of halfedge 4*v+s, `positive[v]` the sign of the
  /// projected orientation of vertex v, `boundary[v]` whether it is a boundary vertex
  /// (then slot 3 is unused, and slot 1 too at a corner: links of unused slots are `none`).
  Primal_complex(std::vector<std::uint32_t> links, const std::vector<bool>& positive,
                 const std::vector<bool>& boundary)
    : number_of_vertices_(std::uint32_t(positive.size())), boundary_(boundary)
  {
    build_rotation(std::move(links), positive);
    trace_faces();
    merge_digons();
    to_halfedges();
    split_non_simple_faces();
    drop_broken_pieces();
  }

  std::uint32_t number_of_vertices() const { return number_of_vertices_; }
  const std::vector<Halfedge>& halfedges() const { return halfedges_; }
  /// one halfedge per face, or no_face for removed faces
  const std::vector<std::uint32_t>& face_halfedges() const { return face_halfedge_; }
  /// whether vertex v is part of the output
  bool is_kept(std::uint32_t v) const { return kept_vertex_[v]; }

  /// digons merged away from the boundary (their vertices have valence 3)
  std::size_t number_of_digons() const { return digons_; }
  /// digons of an arc and a boundary edge (a corner of the surface that crosses a
  /// hyperplane and comes back), merged: their two boundary vertices have valence 2
  std::size_t number_of_boundary_digons() const { return boundary_digons_; }
  bool is_boundary(std::uint32_t v) const { return boundary_[v]; }
  std::size_t number_of_non_simple_faces() const { return non_simple_faces_; }
  std::size_t number_of_dropped_pieces() const { return dropped_pieces_; }
  /// edges of the output that join the same two vertices as another one (k edges
  /// between two vertices count k - 1)
  std::size_t number_of_parallel_edges() const { return parallel_edges_; }
  /// One halfedge of each edge that joins the same two vertices as an edge before it
  /// (in the order of their vertices, then of their halfedges): `k - 1` of each `k`.
  std::vector<std::uint32_t> parallel_halfedges() const
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> ends = edge_ends();
    std::sort(ends.begin(), ends.end());
    std::vector<std::uint32_t> parallel;
    for(std::size_t i = 1; i < ends.size(); ++i)
      if(ends[i].first == ends[i - 1].first)
        parallel.push_back(ends[i].second);
    return parallel;
  }
  /// The halfedge of the rotation system (4 * vertex + slot: the arc that leaves the
  /// vertex by the slot) that halfedge h was, or `none` for a chord of a split face.
  std::uint32_t traced_halfedge(std::uint32_t h) const { return traced_halfedge_[h]; }

  static constexpr std::uint32_t none = std::uint32_t(-1);

  /// A face as traced, before any repair: its region of the surface lies, at the
  /// vertex `halfedge / 4`, between the slots `halfedge % 4` and `next_slot`
  /// (counter-clockwise). The topology check finds the face's cell from it.
  struct Traced_face_corner
  {
    std::uint32_t halfedge;
    std::uint32_t next_slot;
  };
  /// the traced faces (one per boundary cycle of a region of the surface in a cell),
  /// before digons are merged and pinched faces split
  const std::vector<Traced_face_corner>& traced_face_corners() const { return traced_face_corners_; }
  /// V - E + F of the traced complex, before the repairs (which keep it, but for
  /// dropped pieces)
  long traced_euler_characteristic() const { return traced_euler_characteristic_; }
  /// V - E + F of the output
  long euler_characteristic() const { return euler_characteristic_; }
  std::size_t number_of_components() const { return components_; }

private:
  // ---------------------------------------------------------- rotation system
  void build_rotation(std::vector<std::uint32_t> links, const std::vector<bool>& positive)
  {
    const std::size_t n = links.size();
    twin_ = std::move(links); // the twins, until digons are merged
    ccw_next_.resize(n);
    ccw_prev_.resize(n);
    alive_.assign(n, 1);
    for(std::uint32_t v = 0; v < number_of_vertices_; ++v)
      for(std::uint32_t s = 0; s < 4; ++s) {
        const std::uint32_t forward = 4 * v + (s + 1) % 4, backward = 4 * v + (s + 3) % 4;
        ccw_next_[4 * v + s] = positive[v] ? forward : backward;
        ccw_prev_[4 * v + s] = positive[v] ? backward : forward;
      }
    for(std::uint32_t v = 0; v < number_of_vertices_; ++v)
      if(boundary_[v])
        for(std::uint32_t s : {1, 3})
          if(twin_[4 * v + s] == none) // slot 3, and the arc slot of a corner
            remove_from_rotation(4 * v + s);
  }

  bool is_hole_halfedge(std::uint32_t h) const { return boundary_[h / 4] && h % 4 == 2; }

  std::uint32_t face_next(std::uint32_t h) const { return ccw_prev_[twin_[h]]; }

  void trace_faces()
  {
    std::size_t alive_halfedges = 0;
    face_of_.assign(twin_.size(), none);
    for(std::uint32_t h = 0; h < twin_.size(); ++h) {
      if(face_of_[h] != none || !alive_[h])
        continue;
      const std::uint32_t f = std::uint32_t(orbit_start_.size());
      orbit_start_.push_back(h);
      is_hole_.push_back(is_hole_halfedge(h));
      std::uint32_t degree = 0;
      for(std::uint32_t g = h; face_of_[g] == none; g = face_next(g)) {
        face_of_[g] = f;
        ++degree;
      }
      orbit_degree_.push_back(degree);
      if(!is_hole_halfedge(h))
        traced_face_corners_.push_back({h, ccw_next_[h] % 4});
      alive_halfedges += degree;
    }
    alive_halfedges_ = alive_halfedges;
    traced_euler_characteristic_ = long(number_of_vertices_) - long(alive_halfedges / 2) +
                                   long(traced_face_corners_.size());
  }

  void remove_from_rotation(std::uint32_t h)
  {
    ccw_next_[ccw_prev_[h]] = ccw_next_[h];
    ccw_prev_[ccw_next_[h]] = ccw_prev_[h];
    alive_[h] = 0;
  }

  void merge_digons()
  {
    for(std::uint32_t f = 0; f < orbit_start_.size(); ++f) {
      if(orbit_degree_[f] != 2 || is_hole_[f])
        continue;
      const std::uint32_t h1 = orbit_start_[f], h2 = face_next(h1);
      const std::uint32_t t1 = twin_[h1], t2 = twin_[h2];
      // The two arcs must bound different faces on their other sides, or the
      // merged edge would have one face on both sides.
      if(t1 == h2 || face_of_[t1] == face_of_[t2])
        continue;
      twin_[t1] = t2;
      twin_[t2] = t1;
      remove_from_rotation(h1);
      remove_from_rotation(h2);
      orbit_degree_[f] = 0;
      (boundary_[h1 / 4] ? boundary_digon_vertices_ : digon_vertices_).push_back(h1 / 4);
    }
  }

  // ---------------------------------------------------------- explicit halfedges
  void to_halfedges()
  {
    std::vector<std::uint32_t> new_id(twin_.size(), none);
    // merging digons removes halfedges, a split of a pinched face (rare) adds two
    halfedges_.reserve(alive_halfedges_);
    traced_halfedge_.reserve(alive_halfedges_);
    face_halfedge_.reserve(orbit_start_.size());
    for(std::uint32_t h = 0; h < twin_.size(); ++h)
      if(alive_[h]) {
        new_id[h] = std::uint32_t(halfedges_.size());
        halfedges_.push_back(Halfedge{twin_[h] / 4, none, none, none});
        traced_halfedge_.push_back(h);
      }
    std::vector<std::uint32_t> face_id(orbit_start_.size(), none);
    for(std::uint32_t h = 0; h < twin_.size(); ++h) {
      if(!alive_[h])
        continue;
      Halfedge& he = halfedges_[new_id[h]];
      he.twin = new_id[twin_[h]];
      he.next = new_id[face_next(h)];
      if(is_hole_[face_of_[h]])
        continue; // a border halfedge: no face
      std::uint32_t& f = face_id[face_of_[h]];
      if(f == none) {
        f = std::uint32_t(face_halfedge_.size());
        face_halfedge_.push_back(new_id[h]);
      }
      he.face = f;
    }
    // the rotation system is no longer needed
    twin_ = {}; ccw_next_ = {}; ccw_prev_ = {}; alive_ = {}; face_of_ = {}; is_hole_ = {};
  }

  std::uint32_t source(std::uint32_t h) const { return halfedges_[halfedges_[h].twin].target; }

  enum Pinch { SIMPLE, SPLIT, UNSPLITTABLE };

  /// Splits face f at one pinch vertex by a chord.
  Pinch split_at_pinch(std::uint32_t f)
  {
    // first pinch: a vertex x entered twice, by halfedges `in_1` then `in_2`
    last_visit_.resize(number_of_vertices_, none);
    std::vector<std::uint32_t>& cycle = cycle_;
    cycle.clear();
    std::uint32_t h = face_halfedge_[f];
    do {
      cycle.push_back(h);
      h = halfedges_[h].next;
    } while(h != face_halfedge_[f]);
    std::uint32_t in_1 = none, in_2 = none;
    for(std::uint32_t g : cycle) {
      std::uint32_t& seen = last_visit_[halfedges_[g].target];
      if(seen != none && in_1 == none) {
        in_1 = seen;
        in_2 = g;
      }
      seen = g;
    }
    for(std::uint32_t g : cycle)
      last_visit_[halfedges_[g].target] = none;
    if(in_1 == none)
      return SIMPLE;
    if(in_2 == halfedges_[in_1].next || in_1 == halfedges_[in_2].next)
      return UNSPLITTABLE; // x -> x: no chord splits it (arcs never produce it)
    // The face is x, A1..Ap, x, B1..Bq with in_1 = Ap->x... pick the ear
    // (A_p, x, B_1): chord from B_1 to A_p, where A_p = source(in_2) and B_1 =
    // target(next(in_2)).
    const std::uint32_t out_2 = halfedges_[in_2].next; // x -> B1
    const std::uint32_t a = source(in_2), b = halfedges_[out_2].target;
    if(a == b)
      return UNSPLITTABLE;
    const std::uint32_t before_a = prev_in_face(in_2); // .. -> A_p
    const std::uint32_t after_b = halfedges_[out_2].next;
    // new halfedges: chord b -> a closes the ear, a -> b continues the rest
    const std::uint32_t ear_chord = std::uint32_t(halfedges_.size());
    const std::uint32_t rest_chord = ear_chord + 1;
    const std::uint32_t ear = std::uint32_t(face_halfedge_.size());
    halfedges_.push_back(Halfedge{a, rest_chord, in_2, ear});
    halfedges_.push_back(Halfedge{b, ear_chord, after_b, f});
    traced_halfedge_.insert(traced_halfedge_.end(), 2, none);
    face_halfedge_.push_back(in_2);
    halfedges_[in_2].face = ear;
    halfedges_[out_2].face = ear;
    halfedges_[out_2].next = ear_chord;
    halfedges_[before_a].next = rest_chord;
    face_halfedge_[f] = rest_chord;
    split_vertices_.push_back(a);
    return SPLIT;
  }

  std::uint32_t prev_in_face(std::uint32_t h) const
  {
    std::uint32_t g = h;
    while(halfedges_[g].next != h)
      g = halfedges_[g].next;
    return g;
  }

  void split_non_simple_faces()
  {
    for(std::uint32_t f = 0; f < face_halfedge_.size(); ++f) {
      Pinch result;
      while((result = split_at_pinch(f)) == SPLIT) {
      }
      if(result == UNSPLITTABLE)
        unsplittable_faces_.push_back(f);
    }
  }

  // ---------------------------------------------------------- broken pieces

  void drop_broken_pieces()
  {
    std::vector<std::uint32_t> parent(number_of_vertices_);
    std::iota(parent.begin(), parent.end(), 0u);
    for(std::uint32_t h = 0; h < halfedges_.size(); ++h)
      parent[union_find_root(parent, halfedges_[h].target)] = union_find_root(parent, source(h));
    std::vector<std::uint8_t> broken(number_of_vertices_, 0), has_halfedge(number_of_vertices_, 0);
    for(std::uint32_t h = 0; h < halfedges_.size(); ++h)
      has_halfedge[halfedges_[h].target] = 1;
    for(std::uint32_t f : unsplittable_faces_)
      broken[union_find_root(parent, halfedges_[face_halfedge_[f]].target)] = 1;
    for(std::uint32_t f = 0; f < face_halfedge_.size(); ++f) {
      const std::uint32_t h = face_halfedge_[f];
      const std::uint32_t h2 = halfedges_[halfedges_[h].next].next;
      const bool too_small = (h2 == h) || (halfedges_[h].next == h);
      const bool bad = too_small || halfedges_[h].face == halfedges_[halfedges_[h].twin].face;
      if(bad)
        broken[union_find_root(parent, halfedges_[h].target)] = 1;
    }
    kept_vertex_.assign(number_of_vertices_, false);
    std::vector<std::uint8_t> counted(number_of_vertices_, 0);
    for(std::uint32_t v = 0; v < number_of_vertices_; ++v) {
      if(!has_halfedge[v])
        continue;
      const std::uint32_t r = union_find_root(parent, v);
      kept_vertex_[v] = !broken[r];
      if(broken[r] && !counted[r]) {
        counted[r] = 1;
        ++dropped_pieces_;
      }
    }
    for(std::uint32_t f = 0; f < face_halfedge_.size(); ++f)
      if(!kept_vertex_[halfedges_[face_halfedge_[f]].target])
        face_halfedge_[f] = none;
    count_output_topology(parent);
    count_parallel_edges();
    // report only the repairs that are in the output
    digons_ = std::count_if(digon_vertices_.begin(), digon_vertices_.end(),
                            [this](std::uint32_t v) { return bool(kept_vertex_[v]); });
    boundary_digons_ = std::count_if(boundary_digon_vertices_.begin(), boundary_digon_vertices_.end(),
                                     [this](std::uint32_t v) { return bool(kept_vertex_[v]); });
    non_simple_faces_ = std::count_if(split_vertices_.begin(), split_vertices_.end(),
                                      [this](std::uint32_t v) { return bool(kept_vertex_[v]); });
  }

  void count_output_topology(std::vector<std::uint32_t>& parent)
  {
    std::vector<std::uint8_t> counted(number_of_vertices_, 0);
    for(std::uint32_t v = 0; v < number_of_vertices_; ++v)
      if(kept_vertex_[v]) {
        ++euler_characteristic_;
        const std::uint32_t r = union_find_root(parent, v);
        components_ += counted[r] ? 0 : 1;
        counted[r] = 1;
      }
    long kept_halfedges = 0;
    for(std::uint32_t h = 0; h < halfedges_.size(); ++h)
      kept_halfedges += kept_vertex_[halfedges_[h].target] ? 1 : 0;
    euler_characteristic_ -= kept_halfedges / 2;
    euler_characteristic_ += long(std::count_if(face_halfedge_.begin(), face_halfedge_.end(),
                                                [](std::uint32_t h) { return h != none; }));
  }

  /// The two vertices of each kept edge (lower first, as one key) and its halfedge
  /// from the lower one.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edge_ends() const
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> ends;
    for(std::uint32_t h = 0; h < halfedges_.size(); ++h) {
      const std::uint32_t u = source(h), v = halfedges_[h].target;
      if(u < v && kept_vertex_[v])
        ends.emplace_back(std::uint64_t(u) << 32 | v, h);
    }
    return ends;
  }

  void count_parallel_edges() { parallel_edges_ = parallel_halfedges().size(); }

  std::uint32_t number_of_vertices_;
  std::vector<bool> boundary_;
  std::vector<Traced_face_corner> traced_face_corners_;
  long traced_euler_characteristic_ = 0, euler_characteristic_ = 0;
  std::size_t components_ = 0;
  std::size_t alive_halfedges_ = 0; // in the rotation system, as traced
  // rotation system
  std::vector<std::uint32_t> twin_, ccw_next_, ccw_prev_;
  std::vector<std::uint8_t> alive_;
  std::vector<std::uint32_t> face_of_, orbit_start_, orbit_degree_;
  std::vector<bool> is_hole_; // per orbit
  // explicit halfedges
  std::vector<Halfedge> halfedges_;
  std::vector<std::uint32_t> traced_halfedge_; // by halfedge: see traced_halfedge()
  std::vector<std::uint32_t> face_halfedge_;
  std::vector<bool> kept_vertex_;
  std::vector<std::uint32_t> last_visit_, cycle_; // scratch of split_at_pinch()
  std::vector<std::uint32_t> unsplittable_faces_;
  std::vector<std::uint32_t> digon_vertices_, boundary_digon_vertices_, split_vertices_; // one vertex of each repair

  std::size_t digons_ = 0, boundary_digons_ = 0, non_simple_faces_ = 0, dropped_pieces_ = 0, parallel_edges_ = 0;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_COMPLEX_H
