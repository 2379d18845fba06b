// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_JOINS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_JOINS_H

// Which dual faces are joined so that the dual is all quads, where the primal has
// vertices of valence 2 and 3 (the ends of merged digons).

#include <CGAL/Range_space_remeshing/Remeshing_stage.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Union_find.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// By vertex index: whether the vertex is on the border, and the number of corners of
/// its dual face, its valence plus one on the border (the dual vertex of the border
/// chain arriving closes the face). One walk around each vertex: `degree()` and
/// `is_border()` would each walk it.
template <class PolygonMesh, class VertexIndexMap>
void count_corners_of_dual_faces(const PolygonMesh& primal, VertexIndexMap vertex_index,
                                 std::vector<std::uint8_t>& on_border, std::vector<std::size_t>& corners)
{
  on_border.assign(num_vertices(primal), 0);
  corners.assign(num_vertices(primal), 0);
  for(auto v : vertices(primal)) {
    std::size_t valence = 0;
    bool border = false;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, primal), primal)) {
      ++valence;
      border = border || is_border(h, primal);
    }
    on_border[get(vertex_index, v)] = border;
    corners[get(vertex_index, v)] = valence + (border ? 1 : 0);
  }
}

/// The primal edges with an end whose dual face is not a quad and both ends with a
/// dual face: the only edges ever joined across.
template <class PolygonMesh, class VertexIndexMap, class HasDualFace>
std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>
low_edges_of(const PolygonMesh& primal, VertexIndexMap vertex_index, const HasDualFace& has_dual_face,
             const std::vector<std::size_t>& corners_of_dual_face)
{
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> low_edges;
  for(auto e : edges(primal)) {
    const auto h = halfedge(e, primal);
    const auto s = source(h, primal), t = target(h, primal);
    if(!is_border(e, primal) && has_dual_face(s) && has_dual_face(t) &&
       (corners_of_dual_face[get(vertex_index, s)] < 4 || corners_of_dual_face[get(vertex_index, t)] < 4))
      low_edges.push_back(h);
  }
  return low_edges;
}

/// The groups of primal vertices whose dual faces are joined (a union-find forest by
/// vertex index), each with its charge sum(valence - 2), and the edges joined so far.
/// The steps of `edges_to_join()` are its members, in the order they run.
template <class PolygonMesh, class VertexIndexMap>
class Dual_face_joiner
{
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;

public:
  Dual_face_joiner(const PolygonMesh& primal, VertexIndexMap vertex_index,
                   const std::vector<std::size_t>& corners_of_dual_face, std::vector<halfedge_descriptor> low_edges)
      : primal_(primal), vertex_index_(vertex_index), parent_(num_vertices(primal)),
        charge_(num_vertices(primal), 0), low_edges_(std::move(low_edges))
  {
    for(std::size_t i = 0; i < parent_.size(); ++i)
      parent_[i] = i;
    for(std::size_t i = 0; i < charge_.size(); ++i)
      charge_[i] = std::size_t(std::max<long>(0, long(corners_of_dual_face[i]) - 2));
  }

  /// Joins every edge whose two groups are distinct and have the charges `c1` and `c2`.
  void join_all(std::size_t c1, std::size_t c2)
  {
    for(halfedge_descriptor h : low_edges_) {
      const auto [a, b] = groups(h);
      if(a != b && ((charge_[a] == c1 && charge_[b] == c2) || (charge_[a] == c2 && charge_[b] == c1)))
        join(h);
    }
  }

  /// Matches charge-1 groups, the most constrained first (a group with one option
  /// takes it), until none is left; only cycles of choices left: any edge of them.
  void match_charge_one_groups(const Progress& progress)
  {
    std::vector<halfedge_descriptor> options;
    std::vector<std::size_t> count(parent_.size(), 0); // by group: its options; zeroed after each round
    std::vector<std::size_t> counted;                  // the groups whose count is not zero
    Work_meter meter(progress, Remeshing_stage::DUAL);
    for(;;) {
      meter.add(low_edges_.size(), 0.8); // a round reads them all
      options.clear();
      for(halfedge_descriptor h : low_edges_) {
        const auto [a, b] = groups(h);
        if(a != b && charge_[a] == 1 && charge_[b] == 1) {
          options.push_back(h);
          for(std::size_t group : {a, b})
            if(count[group]++ == 0)
              counted.push_back(group);
        }
      }
      if(options.empty())
        return;
      bool forced = false;
      for(halfedge_descriptor h : options) {
        const auto [a, b] = groups(h);
        if(a != b && charge_[a] == 1 && charge_[b] == 1 && (count[a] == 1 || count[b] == 1)) {
          join(h);
          forced = true;
        }
      }
      if(!forced)
        join(options.front());
      for(std::size_t group : counted)
        count[group] = 0;
      counted.clear();
    }
  }

  /// What is left of valence-2 chains joins one valence-4 neighbour, or failing that
  /// any neighbour: a group of charge 0 would be a face of degree 2. Its vertices have
  /// charge 0 too (no charge is negative), so fewer than 4 dual corners: the edges with
  /// such an end are all low edges.
  void join_leftover_chains()
  {
    for(std::size_t wanted : {std::size_t(2), std::size_t(1), std::size_t(3)})
      for(halfedge_descriptor h : low_edges_) {
        const auto [a, b] = groups(h);
        if(a != b && ((charge_[a] == 0 && charge_[b] >= wanted) || (charge_[a] >= wanted && charge_[b] == 0)))
          join(h);
      }
  }

  std::vector<halfedge_descriptor> take_joined() { return std::move(joined_); }

private:
  std::pair<std::size_t, std::size_t> groups(halfedge_descriptor h)
  {
    return std::make_pair(union_find_root(parent_, std::size_t(get(vertex_index_, source(h, primal_)))),
                          union_find_root(parent_, std::size_t(get(vertex_index_, target(h, primal_)))));
  }

  void join(halfedge_descriptor h)
  {
    const auto [a, b] = groups(h);
    parent_[a] = b;
    charge_[b] += charge_[a];
    joined_.push_back(h);
  }

  const PolygonMesh& primal_;
  VertexIndexMap vertex_index_;
  std::vector<std::size_t> parent_, charge_;
  std::vector<halfedge_descriptor> low_edges_, joined_;
};

/// Primal edges across which the dual faces are joined so that the dual is all quads.
/// A dual face has as many corners as its primal vertex has edges, and joining the
/// faces of a tree of primal vertices gives sum(valence - 2) + 2 corners: every group
/// must reach a charge sum(valence - 2) of exactly 2. Valence-4 vertices stand alone;
/// valence-2 vertices (in two merged digons) chain together and join valence-3 ends
/// (charge 1) or, failing those, one valence-4 neighbour; charge-1 groups are matched
/// along primal edges, the most constrained first.
/// A border vertex's dual face has one corner more (the border closes it); vertices
/// without a dual face (`has_dual_face(v)` false) take no part.
/// `corners_of_dual_face`: by vertex index, from `count_corners_of_dual_faces()`.
template <class PolygonMesh, class VertexIndexMap, class HasDualFace>
std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>
edges_to_join(const PolygonMesh& primal, VertexIndexMap vertex_index, const HasDualFace& has_dual_face,
              const std::vector<std::size_t>& corners_of_dual_face, const Progress& progress)
{
  Dual_face_joiner<PolygonMesh, VertexIndexMap> joiner(
      primal, vertex_index, corners_of_dual_face, low_edges_of(primal, vertex_index, has_dual_face, corners_of_dual_face));
  joiner.join_all(0, 0); // chains of valence-2 vertices
  joiner.join_all(0, 1); // ... take a valence-3 end
  joiner.match_charge_one_groups(progress);
  joiner.join_leftover_chains();
  return joiner.take_joined();
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_JOINS_H
