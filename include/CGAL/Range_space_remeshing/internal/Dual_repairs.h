// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_REPAIRS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_REPAIRS_H

// The repairs of the dual: parallel edges (rotated, glued around pinches, or joined
// across) and pieces with faces that are not simple polygons (removed).

#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Number of edges that join the same two vertices as another edge.
template <class Mesh>
std::size_t number_of_parallel_edges(const Mesh& mesh)
{
  std::size_t parallel = 0;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> neighbours;
  for(auto v : vertices(mesh)) {
    neighbours.clear();
    for(auto w : CGAL::vertices_around_target(halfedge(v, mesh), mesh)) {
      if(v < w && std::find(neighbours.begin(), neighbours.end(), w) != neighbours.end())
        ++parallel;
      neighbours.push_back(w);
    }
  }
  return parallel;
}

/// One halfedge of each of two edges joining the same two vertices, from the lower one.
template <class Mesh>
std::vector<std::pair<typename boost::graph_traits<Mesh>::halfedge_descriptor,
                      typename boost::graph_traits<Mesh>::halfedge_descriptor>>
parallel_halfedge_pairs(const Mesh& mesh)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::vector<std::pair<halfedge_descriptor, halfedge_descriptor>> pairs;
  std::vector<std::pair<vertex_descriptor, halfedge_descriptor>> neighbours;
  for(vertex_descriptor v : vertices(mesh)) {
    neighbours.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_source(v, mesh)) {
      const vertex_descriptor w = target(h, mesh);
      for(const auto& [u, g] : neighbours)
        if(u == w && v < w)
          pairs.emplace_back(g, h);
      neighbours.emplace_back(w, h);
    }
  }
  return pairs;
}

/// Parallel edges (two edges joining the same two vertices: where two primal faces
/// share two edges, which coarse cells give around thin parts) cannot be stored in
/// face-list files. Each pair is undone by rotating one of its edges inside the
/// hexagon of its two quads: the faces stay quads, and the new diagonal is the
/// shorter one that joins two vertices not yet adjacent. Returns the pairs left.
template <class Mesh, class VertexPointMap>
std::size_t rotate_parallel_edges(Mesh& mesh, VertexPointMap vpm)
{
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::vector<halfedge_descriptor> parallel; // one halfedge of each pair's edges
  for(const auto& [g, h] : parallel_halfedge_pairs(mesh)) {
    parallel.push_back(g);
    parallel.push_back(h);
  }
  if(parallel.empty())
    return 0; // the common case: no second pass over the mesh
  auto length = [&](vertex_descriptor x, vertex_descriptor y) {
    const Vec3 d = difference(to_vec3(get(vpm, x)), to_vec3(get(vpm, y)));
    return dot(d, d);
  };
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> rotated_pairs;
  for(std::size_t i = 0; i < parallel.size(); i += 2) {
    const vertex_descriptor u = source(parallel[i], mesh), w = target(parallel[i], mesh);
    const std::pair<vertex_descriptor, vertex_descriptor> pair = u < w ? std::make_pair(u, w) : std::make_pair(w, u);
    if(std::find(rotated_pairs.begin(), rotated_pairs.end(), pair) != rotated_pairs.end())
      continue; // a third edge between the same vertices: one rotation per pair
    for(halfedge_descriptor g : {parallel[i], parallel[i + 1]}) {
      const halfedge_descriptor o = opposite(g, mesh);
      if(is_border(g, mesh) || is_border(o, mesh) || degree(face(g, mesh), mesh) != 4 ||
         degree(face(o, mesh), mesh) != 4)
        continue;
      // the hexagon a -> e -> f -> b -> c -> d once g = (a -> b) is removed
      const halfedge_descriptor into_c = next(g, mesh), into_d = next(into_c, mesh);
      const halfedge_descriptor into_e = next(o, mesh), into_f = next(into_e, mesh);
      const vertex_descriptor a = source(g, mesh), b = target(g, mesh), c = target(into_c, mesh),
                              d = target(into_d, mesh), e = target(into_e, mesh), f = target(into_f, mesh);
      const std::array<vertex_descriptor, 6> hexagon = {{a, e, f, b, c, d}};
      // a and b lose an edge: they must keep three, and stay off the border
      bool simple = face(g, mesh) != face(o, mesh) && degree(a, mesh) >= 4 && degree(b, mesh) >= 4 &&
                    !is_border(a, mesh) && !is_border(b, mesh);
      for(std::size_t k = 0; k < 6 && simple; ++k)
        simple = std::count(hexagon.begin(), hexagon.end(), hexagon[k]) == 1;
      if(!simple)
        continue; // the two quads share more than the edge: no hexagon to rotate in
      const bool ec = !halfedge(e, c, mesh).second, fd = !halfedge(f, d, mesh).second;
      if(!ec && !fd)
        continue;
      CGAL::Euler::join_face(g, mesh);
      if(ec && (!fd || length(e, c) <= length(f, d)))
        CGAL::Euler::split_face(into_e, into_c, mesh);
      else
        CGAL::Euler::split_face(into_f, into_d, mesh);
      rotated_pairs.push_back(pair);
      break;
    }
  }
  return number_of_parallel_edges(mesh);
}

/// Whether removing the inner vertex v of valence 2 (`Euler::remove_center_vertex()`)
/// merges its two faces into a simple polygon: they are distinct, share no corner but v
/// and its two neighbours, and have at least five corners between them.
template <class Mesh>
bool removal_keeps_face_simple(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& mesh)
{
  const auto h = halfedge(v, mesh), g = opposite(next(h, mesh), mesh);
  if(is_border(h, mesh) || is_border(g, mesh) || face(h, mesh) == face(g, mesh) ||
     degree(face(h, mesh), mesh) + degree(face(g, mesh), mesh) < 7)
    return false;
  std::set<typename boost::graph_traits<Mesh>::vertex_descriptor> corners;
  for(auto w : CGAL::vertices_around_face(h, mesh))
    corners.insert(w);
  for(auto w : CGAL::vertices_around_face(g, mesh))
    if(w != v && w != source(h, mesh) && w != target(next(h, mesh), mesh) && corners.count(w))
      return false;
  return true;
}

/// A pinch: an inner vertex x of valence 2 between two triangles (a, b, x) and (b, a, x).
/// It is the dual of a primal digon with valence-3 ends whose two neighbouring faces
/// meet again beyond both ends (two primal faces sharing two edges, around thin parts
/// at coarse cells). The two edges a-b are parallel, and the two quads across them
/// share more than the edge, so no rotation undoes them (`rotate_parallel_edges()`).
/// The pinch is a disk bounded by the two edges: it is removed and the two edges are
/// glued into one, which keeps the topology and the degrees of the other faces; a or b
/// left with valence 2 then has its two faces merged (two quads into one quad), as the
/// quad collapse does with doublets. Returns the number of pinches removed and lowers
/// the counts of dual vertices and faces.
template <class Mesh>
std::size_t remove_pinches(Mesh& mesh, std::size_t& number_of_vertices, std::size_t& number_of_faces)
{
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<Mesh>::halfedge_descriptor;
  auto is_inner_doublet = [&](vertex_descriptor v) { return degree(v, mesh) == 2 && !is_border(v, mesh); };
  // the halfedge across the side a-b of the triangle of h = a -> x
  auto across_third_side = [&](halfedge_descriptor h) { return opposite(next(next(h, mesh), mesh), mesh); };
  auto is_pinch = [&](vertex_descriptor x) { // x of valence 2: halfedges a -> x and b -> x
    const halfedge_descriptor h = halfedge(x, mesh), g = opposite(next(h, mesh), mesh);
    if(is_border(h, mesh) || is_border(g, mesh) || source(h, mesh) == source(g, mesh) ||
       degree(face(h, mesh), mesh) != 3 || degree(face(g, mesh), mesh) != 3)
      return false;
    // the faces across the two edges a-b, which are glued into one: two faces other
    // than the triangles (not a closed piece of two triangles)
    const halfedge_descriptor one = across_third_side(h), other = across_third_side(g);
    if(is_border(one, mesh) || is_border(other, mesh))
      return false;
    const auto outer = {face(one, mesh), face(other, mesh)};
    return face(one, mesh) != face(other, mesh) &&
           std::none_of(outer.begin(), outer.end(), [&](auto f) { return f == face(h, mesh) || f == face(g, mesh); });
  };
  // a worklist: the pinches, then the ends of removed pinches and the neighbours of
  // removed doublets, whose valence went down (they may have become pinches)
  std::vector<vertex_descriptor> work;
  for(vertex_descriptor v : vertices(mesh))
    if(is_inner_doublet(v) && is_pinch(v))
      work.push_back(v);
  std::set<vertex_descriptor> removed;
  std::size_t removed_pinches = 0;
  while(!work.empty()) {
    const vertex_descriptor x = work.back();
    work.pop_back();
    if(removed.count(x) || !is_inner_doublet(x))
      continue;
    const halfedge_descriptor h = halfedge(x, mesh);
    const vertex_descriptor a = source(h, mesh), b = target(next(h, mesh), mesh);
    if(is_pinch(x)) {
      // the two triangles become one 2-gon bounded by the two edges a-b, which is then
      // joined with the face across one of them: the edges are glued
      CGAL::Euler::join_face(CGAL::Euler::remove_center_vertex(h, mesh), mesh);
      ++removed_pinches;
      number_of_faces -= 2;
    } else if(removal_keeps_face_simple(x, mesh)) {
      CGAL::Euler::remove_center_vertex(h, mesh);
      --number_of_faces;
    } else {
      continue;
    }
    removed.insert(x);
    --number_of_vertices;
    work.push_back(a);
    work.push_back(b);
  }
  return removed_pinches;
}

/// Whether joining the two faces of halfedge h gives a face that visits each vertex
/// once: the faces must be distinct and share no vertex but the ends of h.
template <class Mesh>
bool join_keeps_face_simple(typename boost::graph_traits<Mesh>::halfedge_descriptor h,
                            const Mesh& mesh)
{
  const auto f = face(h, mesh), g = face(opposite(h, mesh), mesh);
  if(f == g)
    return false;
  std::set<typename boost::graph_traits<Mesh>::vertex_descriptor> corners;
  for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
    corners.insert(v);
  for(auto v : CGAL::vertices_around_face(halfedge(g, mesh), mesh))
    if(v != source(h, mesh) && v != target(h, mesh) && corners.count(v))
      return false;
  return true;
}

/// The last resort for a pair of parallel edges that neither `remove_pinches()` nor
/// `rotate_parallel_edges()` undoes (e.g. two triangles over the same three corners,
/// glued along one edge, between two pairs): one of its edges is removed by joining
/// its two faces, where that gives a simple polygon. The mesh then has a face with more
/// corners (a pentagon for a triangle and a quad) but can be stored in a file. Returns
/// the number of edges removed and lowers the count of faces.
template <class Mesh>
std::size_t join_across_parallel_edges(Mesh& mesh, std::size_t& number_of_faces)
{
  std::size_t joined = 0;
  // one join per sweep: it may remove edges that other pairs listed (a few pairs at most)
  for(bool progress = true; progress;) {
    progress = false;
    for(const auto& [g, h] : parallel_halfedge_pairs(mesh)) {
      for(auto e : {g, h})
        if(!is_border(edge(e, mesh), mesh) && join_keeps_face_simple(e, mesh)) {
          CGAL::Euler::join_face(e, mesh);
          progress = true;
          break;
        }
      if(progress)
        break;
    }
    if(progress) {
      ++joined;
      --number_of_faces;
    }
  }
  return joined;
}

/// Removes the connected components that have a face that is not a simple polygon
/// (degree below 3, or a vertex visited twice); returns their number and decreases
/// `number_of_faces` accordingly.
template <class Mesh>
std::size_t remove_pieces_with_non_simple_faces(Mesh& mesh, std::size_t& number_of_faces)
{
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  std::vector<face_descriptor> degenerate;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> corners;
  for(face_descriptor f : faces(mesh)) {
    corners.clear();
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      corners.push_back(v);
    bool repeated = corners.size() < 3;
    for(std::size_t i = 0; i < corners.size() && !repeated; ++i)
      repeated = std::find(corners.begin() + i + 1, corners.end(), corners[i]) != corners.end();
    if(repeated)
      degenerate.push_back(f);
  }
  std::size_t pieces = 0;
  std::set<face_descriptor> removed;
  for(face_descriptor seed : degenerate) {
    if(removed.count(seed))
      continue;
    ++pieces;
    std::vector<face_descriptor> piece;
    walk_component(seed, mesh, removed, [&piece](face_descriptor f) { piece.push_back(f); });
    // the whole component goes: remove its elements without any reconnection
    std::set<typename boost::graph_traits<Mesh>::edge_descriptor> edges_of_piece;
    std::set<typename boost::graph_traits<Mesh>::vertex_descriptor> vertices_of_piece;
    for(face_descriptor f : piece)
      for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        edges_of_piece.insert(edge(h, mesh));
        vertices_of_piece.insert(target(h, mesh));
      }
    for(face_descriptor f : piece)
      remove_face(f, mesh);
    for(auto e : edges_of_piece)
      remove_edge(e, mesh);
    for(auto v : vertices_of_piece)
      remove_vertex(v, mesh);
    number_of_faces -= piece.size();
  }
  return pieces;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_REPAIRS_H
