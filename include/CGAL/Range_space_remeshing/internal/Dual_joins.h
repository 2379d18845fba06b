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
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  const std::size_t n = num_vertices(primal);
  std::vector<std::size_t> parent(n), charge(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    parent[i] = i;
  auto root = [&](std::size_t x) { return union_find_root(parent, x); };
  std::vector<halfedge_descriptor> low_edges; // edges with an end whose dual face is not a quad
  for(std::size_t i = 0; i < n; ++i)
    charge[i] = std::size_t(std::max<long>(0, long(corners_of_dual_face[i]) - 2));
  for(auto e : edges(primal)) {
    const halfedge_descriptor h = halfedge(e, primal);
    const auto s = source(h, primal), t = target(h, primal);
    if(!is_border(e, primal) && has_dual_face(s) && has_dual_face(t) &&
       (corners_of_dual_face[get(vertex_index, s)] < 4 || corners_of_dual_face[get(vertex_index, t)] < 4))
      low_edges.push_back(h);
  }
  auto groups = [&](halfedge_descriptor h) {
    return std::make_pair(root(get(vertex_index, source(h, primal))),
                          root(get(vertex_index, target(h, primal))));
  };
  std::vector<halfedge_descriptor> joined;
  auto join = [&](halfedge_descriptor h) {
    const auto [a, b] = groups(h);
    parent[a] = b;
    charge[b] += charge[a];
    joined.push_back(h);
  };
  // joins every edge whose two groups are distinct and have the given charges
  auto join_all = [&](std::size_t c1, std::size_t c2) {
    for(halfedge_descriptor h : low_edges) {
      const auto [a, b] = groups(h);
      if(a != b && ((charge[a] == c1 && charge[b] == c2) || (charge[a] == c2 && charge[b] == c1)))
        join(h);
    }
  };
  join_all(0, 0); // chains of valence-2 vertices
  join_all(0, 1); // ... take a valence-3 end
  std::vector<halfedge_descriptor> options;
  std::vector<std::size_t> count(n, 0); // by group: its options; zeroed after each round
  std::vector<std::size_t> counted;       // the groups whose count is not zero
  Work_meter meter(progress, Remeshing_stage::DUAL);
  for(;;) { // match charge-1 groups, most constrained first, until none is left
    meter.add(low_edges.size(), 0.8); // a round reads them all
    options.clear();
    for(halfedge_descriptor h : low_edges) {
      const auto [a, b] = groups(h);
      if(a != b && charge[a] == 1 && charge[b] == 1) {
        options.push_back(h);
        for(std::size_t group : {a, b})
          if(count[group]++ == 0)
            counted.push_back(group);
      }
    }
    if(options.empty())
      break;
    bool forced = false;
    for(halfedge_descriptor h : options) {
      const auto [a, b] = groups(h);
      if(a != b && charge[a] == 1 && charge[b] == 1 && (count[a] == 1 || count[b] == 1)) {
        join(h);
        forced = true;
      }
    }
    if(!forced) // only cycles of choices left: any edge of them
      join(options.front());
    for(std::size_t group : counted)
      count[group] = 0;
    counted.clear();
  }
  // what is left of valence-2 chains joins one valence-4 neighbour, or failing
  // that any neighbour: a group of charge 0 would be a face of degree 2. Its vertices
  // have charge 0 too (no charge is negative), so fewer than 4 dual corners: the edges
  // with such an end are all low edges.
  for(std::size_t wanted : {std::size_t(2), std::size_t(1), std::size_t(3)})
    for(halfedge_descriptor h : low_edges) {
      const auto [a, b] = groups(h);
      if(a != b && ((charge[a] == 0 && charge[b] >= wanted) || (charge[a] >= wanted && charge[b] == 0)))
        join(h);
    }
  return joined;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_JOINS_H
