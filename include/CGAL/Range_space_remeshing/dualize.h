// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_DUALIZE_H
#define CGAL_RANGE_SPACE_REMESHING_DUALIZE_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Color.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Pooled_tangent_planes_map.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_kernel.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>
#include <CGAL/Range_space_remeshing/internal/Union_find.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <set>

#include <array>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

namespace internal {

/// The quadric of a dual vertex's planes and its decomposition, which the relaxation
/// can reuse (see `remember_decomposition()`).
struct Decomposed_quadric
{
  Quadric quadric;
  Quadric_eigen eigen;
};

/// Position and normal of the dual vertex of a primal face with tangent planes `planes`;
/// with the QEM placement, `decomposed` receives the quadric it solved.
inline std::pair<Vec3, Vec3> place_dual_vertex(const Tangent_planes& planes, Dual_placement placement,
                                               std::optional<Decomposed_quadric>& decomposed)
{
  decomposed.reset();
  Vec3 mass = {{0, 0, 0}}, normal = {{0, 0, 0}};
  for(const auto& plane : planes)
    for(int d = 0; d < 3; ++d) {
      mass[d] += plane.first[d] / double(planes.size());
      normal[d] += plane.second[d];
    }
  const Vec3 unit_normal = normalized(normal);
  if(placement == Dual_placement::AVERAGE)
    return {mass, unit_normal};
  if(placement == Dual_placement::QEM) {
    Quadric quadric;
    quadric.add_planes(planes);
    decomposed = Decomposed_quadric{quadric, Quadric_eigen(quadric)};
    return {Quadric_projection(decomposed->eigen, quadric_truncation)(mass), unit_normal};
  }
  std::vector<Vec3> polygon;
  polygon.reserve(planes.size());
  for(const auto& plane : planes)
    polygon.push_back(plane.first);
  return {into_face(polygon, normal, sharp_feature_minimiser(planes, mass)), unit_normal};
}

/// Marks in `ends_chain` the valence-2 vertices where the border cycle `cycle` (its
/// vertices in order, the last with a dual face) is cut so that it has at least three
/// chains: those of a cycle with one or two vertices with a dual face, taken evenly
/// along the longest chains.
template <class Vertex, class HasDualFace, class VertexIndexMap>
void split_short_border_cycle(const std::vector<Vertex>& cycle, const HasDualFace& has_dual_face,
                              std::vector<std::uint8_t>& ends_chain, VertexIndexMap vertex_index)
{
  std::vector<std::vector<Vertex>> insides(1); // of each chain, the vertices without dual face
  for(Vertex v : cycle) {
    if(has_dual_face(v))
      insides.emplace_back();
    else
      insides.back().push_back(v);
  }
  insides.pop_back(); // after the last vertex: empty
  if(insides.size() >= 3)
    return;
  auto cut = [&](const std::vector<Vertex>& inside, std::size_t parts) {
    for(std::size_t k = 1; k < parts && inside.size() >= parts - 1; ++k)
      ends_chain[get(vertex_index, inside[k * inside.size() / parts])] = 1;
  };
  if(insides.size() == 1)
    cut(insides[0], 3);
  else
    cut(insides[0].size() >= insides[1].size() ? insides[0] : insides[1], 2);
}

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
    std::vector<face_descriptor> piece(1, seed), stack(1, seed);
    removed.insert(seed);
    while(!stack.empty()) {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        const auto o = opposite(h, mesh);
        if(!is_border(o, mesh) && removed.insert(face(o, mesh)).second) {
          piece.push_back(face(o, mesh));
          stack.push_back(face(o, mesh));
        }
      }
    }
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

namespace internal {

/// The body of `dualize()`.
template <class PolygonMesh, class QuadMesh, class NamedParametersIn, class NamedParametersOut>
Dual_statistics build_dual(const PolygonMesh& primal, QuadMesh& quads, const NamedParametersIn& np_in,
                           const NamedParametersOut& np_out, const Progress& progress)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using dual_vertex = typename boost::graph_traits<QuadMesh>::vertex_descriptor;
  using dual_halfedge = typename boost::graph_traits<QuadMesh>::halfedge_descriptor;
  using dual_face = typename boost::graph_traits<QuadMesh>::face_descriptor;

  const auto start = std::chrono::steady_clock::now();
  if(num_faces(primal) == 0)
    throw Remeshing_error("dualize: the primal mesh has no face");

  const auto vpm = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, primal));
  constexpr bool has_normals =
      !is_default_parameter<NamedParametersIn, CGAL::internal_np::vertex_normal_map_t>::value;
  const auto normal_map = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_normal_map),
                                           CGAL::Constant_property_map<vertex_descriptor, int>(0));
  const Dual_placement placement = choose_parameter(
      get_parameter(np_in, internal_np::dual_placement), Dual_placement::QEM);
  auto primal_normal = [&](vertex_descriptor v) -> internal::Vec3 {
    if constexpr(has_normals)
      return internal::to_vec3(get(normal_map, v));
    else
      return internal::area_weighted_vertex_normal(v, primal, vpm);
  };

  using Out_VPM = typename GetVertexPointMap<QuadMesh, NamedParametersOut>::type;
  Out_VPM out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                     get_property_map(CGAL::vertex_point, quads));
  using Out_point = typename boost::property_traits<Out_VPM>::value_type;
  using Out_vector = typename CGAL::Kernel_traits<Out_point>::Kernel::Vector_3;
  constexpr bool wants_normals =
      !is_default_parameter<NamedParametersOut, CGAL::internal_np::vertex_normal_map_t>::value;
  auto out_normals = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_normal_map),
                                      CGAL::Constant_property_map<dual_vertex, Out_vector>(CGAL::NULL_VECTOR));
  constexpr bool wants_planes =
      !is_default_parameter<NamedParametersOut, internal_np::vertex_tangent_planes_map_t>::value;
  auto out_planes = choose_parameter(get_parameter(np_out, internal_np::vertex_tangent_planes_map),
                                     CGAL::Constant_property_map<dual_vertex, Tangent_planes>());

  auto face_index = CGAL::get_initialized_face_index_map(primal, np_in);
  auto vertex_index = CGAL::get_initialized_vertex_index_map(primal, np_in);
  auto halfedge_index = CGAL::get_initialized_halfedge_index_map(primal, np_in);

  // primal vertex data, once
  std::vector<internal::Vec3> point_of(num_vertices(primal)), normal_of(num_vertices(primal));
  for(vertex_descriptor v : vertices(primal)) {
    point_of[get(vertex_index, v)] = internal::to_vec3(get(vpm, v));
    normal_of[get(vertex_index, v)] = internal::normalized(primal_normal(v));
  }
  // a vertex inside an opened crease: the other side's normal, a second tangent plane
  constexpr bool has_crease_normals =
      !is_default_parameter<NamedParametersIn, internal_np::vertex_crease_normal_map_t>::value;
  const auto crease_normal_map = choose_parameter(get_parameter(np_in, internal_np::vertex_crease_normal_map),
                                                  CGAL::Constant_property_map<vertex_descriptor, int>(0));
  std::vector<internal::Vec3> crease_normal_of;
  if constexpr(has_crease_normals) {
    crease_normal_of.resize(num_vertices(primal));
    for(vertex_descriptor v : vertices(primal))
      crease_normal_of[get(vertex_index, v)] = internal::normalized(internal::to_vec3(get(crease_normal_map, v)));
  }

  // colours: the average of the primal face's, where the primal has them (np_in) and
  // the dual wants them (np_out)
  constexpr bool wants_colors =
      !is_default_parameter<NamedParametersIn, CGAL::internal_np::vertex_color_map_t>::value &&
      !is_default_parameter<NamedParametersOut, CGAL::internal_np::vertex_color_map_t>::value;
  const auto in_colors = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_color_map),
                                          CGAL::Constant_property_map<vertex_descriptor, CGAL::IO::Color>());
  auto out_colors = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_color_map),
                                     CGAL::Constant_property_map<dual_vertex, CGAL::IO::Color>());
  using Out_color = typename boost::property_traits<decltype(out_colors)>::value_type;

  // The border (paper, section 7, here with a dual that keeps the primal's topology):
  // a border vertex of valence 3 or more has a dual face too, closed on the outside by
  // dual vertices on the primal border. Those sit one per border chain, the primal
  // border between two consecutive such vertices (the vertices of valence 2 inside a
  // chain, ends of merged digons and corners, have no dual face). A chain's dual
  // vertex lies on the primal border and is placed from primal border data only, so
  // the dual border cannot shrink away from it.
  constexpr std::size_t no_chain = std::size_t(-1);
  std::vector<std::uint8_t> on_border;
  std::vector<std::size_t> corners_of_dual_face;
  internal::count_corners_of_dual_faces(primal, vertex_index, on_border, corners_of_dual_face);
  std::vector<std::uint8_t> has_dual_face_(num_vertices(primal), 0);
  for(std::size_t i = 0; i < has_dual_face_.size(); ++i) // on the border: valence 3 or more
    has_dual_face_[i] = !on_border[i] || corners_of_dual_face[i] >= 4;
  auto has_dual_face = [&](vertex_descriptor v) { return bool(has_dual_face_[get(vertex_index, v)]); };
  // Chains end at those vertices, and also at a few valence-2 vertices, where a border
  // cycle would otherwise have fewer than three chains (a dual border cycle of one or
  // two edges): the dual border passes there through the dual vertex of their face.
  std::vector<std::uint8_t> ends_chains(has_dual_face_);
  auto ends_chain = [&](vertex_descriptor v) { return bool(ends_chains[get(vertex_index, v)]); };
  {
    std::vector<std::uint8_t> walked(num_halfedges(primal), 0);
    std::vector<vertex_descriptor> cycle; // starting after a vertex with a dual face
    for(halfedge_descriptor h : halfedges(primal)) {
      if(!is_border(h, primal) || walked[get(halfedge_index, h)] || !has_dual_face(source(h, primal)))
        continue;
      cycle.clear();
      for(halfedge_descriptor g : CGAL::halfedges_around_face(h, primal)) {
        walked[get(halfedge_index, g)] = 1;
        cycle.push_back(target(g, primal));
      }
      internal::split_short_border_cycle(cycle, has_dual_face, ends_chains, vertex_index);
    }
  }
  struct Border_chain {
    halfedge_descriptor first, last; // border halfedges (null face), in border order
  };
  std::vector<Border_chain> chains;
  std::vector<std::size_t> chain_of(num_halfedges(primal), no_chain); // of border halfedges
  for(halfedge_descriptor h : halfedges(primal)) {
    if(!is_border(h, primal) || chain_of[get(halfedge_index, h)] != no_chain ||
       !ends_chain(source(h, primal)))
      continue;
    halfedge_descriptor last = h;
    for(;;) {
      chain_of[get(halfedge_index, last)] = chains.size();
      if(ends_chain(target(last, primal)))
        break;
      last = next(last, primal);
    }
    chains.push_back({h, last});
  }
  // at most: a vertex per primal face and per chain, an edge per primal edge and per
  // chain (the closing edges), a face per primal vertex
  internal::reserve_if_possible(quads, num_faces(primal) + chains.size(), num_edges(primal) + chains.size(),
                                num_vertices(primal));

  Tangent_planes planes;
  std::vector<std::pair<vertex_descriptor, double>> color_sources; // with weights
  auto add_dual_vertex = [&](const internal::Vec3& position, const internal::Vec3& normal) {
    const dual_vertex dv = add_vertex(quads);
    put(out_vpm, dv, Out_point(position[0], position[1], position[2]));
    if constexpr(wants_normals)
      put(out_normals, dv, Out_vector(normal[0], normal[1], normal[2]));
    if constexpr(wants_planes)
      put(out_planes, dv, planes);
    if constexpr(wants_colors) {
      internal::Vec3 rgb = {{0, 0, 0}};
      for(const auto& [v, weight] : color_sources) {
        const internal::Vec3 c = internal::to_rgb(get(in_colors, v));
        for(int d = 0; d < 3; ++d)
          rgb[d] += weight * c[d];
      }
      put(out_colors, dv, internal::from_rgb<Out_color>(rgb));
    }
    return dv;
  };
  std::vector<dual_vertex> dual_of_face(num_faces(primal));
  std::optional<Decomposed_quadric> decomposed;
  std::size_t placed_faces = 0;
  for(auto f : faces(primal)) {
    progress.report_every(Remeshing_stage::DUAL, placed_faces++, 2 * num_faces(primal)); // half the work
    planes.clear();
    color_sources.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, primal), primal)) {
      const std::size_t i = get(vertex_index, v);
      planes.emplace_back(point_of[i], normal_of[i]);
      if constexpr(has_crease_normals)
        if(crease_normal_of[i] != internal::Vec3{{0, 0, 0}})
          planes.emplace_back(point_of[i], crease_normal_of[i]);
      if constexpr(wants_colors)
        color_sources.emplace_back(v, 1.); // weighted equally: the face's mean colour
    }
    if constexpr(wants_colors)
      for(auto& source : color_sources)
        source.second /= double(color_sources.size());
    const auto placed = internal::place_dual_vertex(planes, placement, decomposed);
    const dual_vertex dv = add_dual_vertex(placed.first, placed.second);
    if constexpr(wants_planes)
      if(decomposed)
        internal::remember_decomposition(out_planes, dv, decomposed->quadric, decomposed->eigen);
    dual_of_face[get(face_index, f)] = dv;
  }
  // a chain's dual vertex: half-way along it, with the tangent planes of the ends of
  // the primal border edge it lies on (along which the relaxation lets it slide)
  auto add_dual_vertex_on_chain = [&](const Border_chain& chain) {
    auto point = [&](vertex_descriptor v) { return point_of[get(vertex_index, v)]; };
    auto length = [&](halfedge_descriptor h) {
      const internal::Vec3 edge = internal::difference(point(target(h, primal)), point(source(h, primal)));
      return std::sqrt(internal::dot(edge, edge));
    };
    double half = 0;
    for(halfedge_descriptor h = chain.first;; h = next(h, primal)) {
      half += length(h) / 2;
      if(h == chain.last)
        break;
    }
    halfedge_descriptor h = chain.first;
    while(h != chain.last && length(h) < half) {
      half -= length(h);
      h = next(h, primal);
    }
    const vertex_descriptor a = source(h, primal), b = target(h, primal);
    const double t = length(h) > 0 ? (std::min)(half / length(h), 1.) : 0.5;
    const std::size_t ia = get(vertex_index, a), ib = get(vertex_index, b);
    internal::Vec3 position, normal;
    for(int d = 0; d < 3; ++d) {
      position[d] = (1 - t) * point_of[ia][d] + t * point_of[ib][d];
      normal[d] = (1 - t) * normal_of[ia][d] + t * normal_of[ib][d];
    }
    planes.assign({{point_of[ia], normal_of[ia]}, {point_of[ib], normal_of[ib]}});
    color_sources.assign({{a, 1 - t}, {b, t}});
    return add_dual_vertex(position, internal::normalized(normal));
  };
  std::vector<dual_vertex> dual_of_chain;
  for(const Border_chain& chain : chains)
    dual_of_chain.push_back(add_dual_vertex_on_chain(chain));
  Dual_statistics stats;
  stats.dual_vertices = num_faces(primal) + chains.size();

  // the dual vertex on the side of face(h) of the primal edge of h
  auto dual_on_side = [&](halfedge_descriptor h) {
    return is_border(h, primal) ? dual_of_chain[chain_of[get(halfedge_index, h)]]
                                : dual_of_face[get(face_index, face(h, primal))];
  };

  // A dual halfedge d(h) per primal halfedge h, from the dual vertex on the side of h
  // to the one on the side of opposite(h), in the dual face of target(h); the border
  // halfedges of a chain share one dual edge. next(d(h)) = d(prev(opposite(h))) turns
  // counter-clockwise around target(h), so the dual has the primal's orientation.
  std::vector<dual_halfedge> dual_of_halfedge(num_halfedges(primal));
  auto d = [&](halfedge_descriptor h) { return dual_of_halfedge[get(halfedge_index, h)]; };
  auto add_dual_edge = [&](halfedge_descriptor h) {
    const dual_halfedge dh = halfedge(add_edge(quads), quads);
    set_target(dh, dual_on_side(opposite(h, primal)), quads);
    set_target(opposite(dh, quads), dual_on_side(h), quads);
    return dh;
  };
  for(auto e : edges(primal)) {
    halfedge_descriptor h = halfedge(e, primal);
    if(is_border(opposite(h, primal), primal))
      h = opposite(h, primal);
    const std::size_t chain = is_border(h, primal) ? chain_of[get(halfedge_index, h)] : no_chain;
    if(is_border(h, primal) && (chain == no_chain || h != chains[chain].last))
      continue; // inside a chain (done with its last edge), or a face without a dual
    const dual_halfedge dh = add_dual_edge(h);
    for(halfedge_descriptor g = h;; g = prev(g, primal)) {
      dual_of_halfedge[get(halfedge_index, g)] = dh;
      dual_of_halfedge[get(halfedge_index, opposite(g, primal))] = opposite(dh, quads);
      if(!is_border(g, primal) || g == chains[chain].first)
        break;
    }
  }

  // The dual faces; a border vertex's is closed by a dual edge from the dual vertex
  // of the chain leaving it to that of the chain arriving, whose opposite is on the
  // dual border.
  progress.report(Remeshing_stage::DUAL, 0.6);
  const auto null_face = boost::graph_traits<QuadMesh>::null_face();
  std::vector<dual_halfedge> closing_of_vertex(num_vertices(primal)); // dual face's border side
  for(vertex_descriptor v : vertices(primal)) {
    if(!has_dual_face(v))
      continue;
    const dual_face df = add_face(quads);
    halfedge_descriptor first = halfedge(v, primal);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, primal), primal))
      if(is_border(h, primal))
        first = h;
    set_halfedge(df, d(first), quads);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(first, primal)) {
      set_face(d(h), df, quads);
      set_halfedge(target(d(h), quads), d(h), quads);
      if(!is_border(opposite(h, primal), primal)) {
        set_next(d(h), d(prev(opposite(h, primal), primal)), quads);
        continue;
      }
      const dual_halfedge closing = halfedge(add_edge(quads), quads);
      set_target(closing, dual_on_side(first), quads);
      set_target(opposite(closing, quads), dual_on_side(opposite(h, primal)), quads);
      set_face(closing, df, quads);
      set_face(opposite(closing, quads), null_face, quads);
      set_next(d(h), closing, quads);
      set_next(closing, d(first), quads);
      closing_of_vertex[get(vertex_index, v)] = closing;
    }
    ++stats.dual_faces;
  }
  // A face whose corners have no dual face is a whole component bounded by one border
  // cycle of valence-2 vertices: it has no dual.
  std::size_t faces_without_dual = 0;
  for(auto f : faces(primal)) {
    const auto corners = CGAL::vertices_around_face(halfedge(f, primal), primal);
    if(std::none_of(corners.begin(), corners.end(), has_dual_face)) {
      remove_vertex(dual_of_face[get(face_index, f)], quads);
      ++faces_without_dual;
    }
  }
  stats.dual_vertices -= faces_without_dual;
  // The dual border, in the primal border's direction: a chain's dual vertex is
  // between the closings of its ends, or, at an end without a dual face, the dual
  // edge of the chain to the dual vertex of the face there.
  for(const Border_chain& chain : chains) {
    const vertex_descriptor from = source(chain.first, primal), to = target(chain.last, primal);
    const dual_halfedge arriving = has_dual_face(from) ? opposite(closing_of_vertex[get(vertex_index, from)], quads)
                                                       : d(opposite(chain.first, primal));
    const dual_halfedge leaving = has_dual_face(to) ? opposite(closing_of_vertex[get(vertex_index, to)], quads)
                                                    : d(chain.last);
    set_next(arriving, leaving, quads);
    set_halfedge(target(arriving, quads), arriving, quads);
    if(!has_dual_face(to)) { // through the dual vertex of the face at `to`
      const dual_halfedge onwards = d(opposite(next(chain.last, primal), primal));
      set_face(leaving, null_face, quads);
      set_face(onwards, null_face, quads);
      set_next(leaving, onwards, quads);
      set_halfedge(target(leaving, quads), leaving, quads);
    }
  }

  progress.report(Remeshing_stage::DUAL, 0.8);
  // Where the primal has vertices of valence 3 and 2 (the ends of merged digons),
  // join the dual faces across the primal edges chosen by `edges_to_join()`: each
  // group of joined faces then has exactly four corners.
  const auto to_join = internal::edges_to_join(primal, vertex_index, has_dual_face, corners_of_dual_face, progress);
  progress.report(Remeshing_stage::DUAL, 0.82);
  Work_meter meter(progress, Remeshing_stage::DUAL);
  for(halfedge_descriptor h : to_join) {
    meter.add(1, 0.82);
    const dual_halfedge dh = d(h);
    if(!internal::join_keeps_face_simple(dh, quads))
      continue; // left as two faces: counted in non_quads
    CGAL::Euler::join_face(dh, quads);
    ++stats.joined_triangle_pairs;
    --stats.dual_faces;
  }
  progress.report(Remeshing_stage::DUAL, 0.85);
  stats.dropped_pieces = faces_without_dual + internal::remove_pieces_with_non_simple_faces(quads, stats.dual_faces);
  progress.report(Remeshing_stage::DUAL, 0.9);
  stats.removed_pinches = internal::remove_pinches(quads, stats.dual_vertices, stats.dual_faces);
  progress.report(Remeshing_stage::DUAL, 0.95);
  stats.parallel_edges = internal::rotate_parallel_edges(quads, out_vpm);
  if(stats.parallel_edges > 0) {
    stats.joined_parallel_edges = internal::join_across_parallel_edges(quads, stats.dual_faces);
    stats.parallel_edges = internal::number_of_parallel_edges(quads);
  }
  progress.report(Remeshing_stage::DUAL, 0.97);
  internal::collect_garbage_if_any(quads);
  for(auto f : faces(quads))
    (degree(f, quads) == 4 ? stats.quads : stats.non_quads) += 1;
  stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

builds the dual of the polygon mesh `primal` into `quads`: one vertex per primal
face, one face per primal vertex (its incident faces in rotation order). When every
primal vertex has valence 4, as in the output of `primal_remesh()`, every dual face is
a quad. The ends of merged digons (valence 3, or 2 for a vertex in two digons) give
triangles and 2-gons; they are joined across the merged edges into quads. Where two
primal faces share two edges (around parts thinner than a cell), their dual vertices
are joined by two parallel edges, which face-list files cannot store: a pair around a
pinch (two triangles around a dual vertex of valence 2, the dual of a digon between
the two faces) is glued into one edge and the pinch removed
(`Dual_statistics::removed_pinches`); a pair between two quads has one of its edges
rotated; a pair neither undoes loses one edge by joining its two faces where that
gives a simple polygon (`Dual_statistics::joined_parallel_edges`); what is left is
counted in `Dual_statistics::parallel_edges`.

On a border (paper, section 7), the primal border is cut into chains at its vertices
of valence 3 or more (the regular valence there, as from `primal_remesh()`); each
chain has a dual vertex half-way along it, on the primal border, and each such border
vertex a dual face closed by a dual border edge between the dual vertices of its two
chains: a quad for valence 3. The dual so has the primal's Euler characteristic and
border cycles, and its border lies on the primal's: it cannot shrink away from it.
Border vertices of valence 2 inside a chain have no dual face (but one, a triangle,
where a border cycle would otherwise have a single chain), and a face whose vertices
all lack one (a piece made of one face) has no dual; it counts as a dropped piece.

The dual vertex of a primal face is placed at the average of the face's vertices
(`Dual_placement::AVERAGE`) or at the minimiser of the squared distances to their
tangent planes (`Dual_placement::QEM`, the default), solved by a truncated
eigen-decomposition around the average so that flat and rank-deficient faces stay
well placed. Its normal is the normalised average of the vertices' normals.

\param primal a polygon mesh (any `FaceListGraph`), with or without border.
\param quads receives the dual (appended); a `MutableFaceGraph`.
\param np_in optional named parameters for `primal`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{dual_placement}
      \cgalParamDescription{where the dual vertices go}
      \cgalParamType{`Dual_placement`}
      \cgalParamDefault{`Dual_placement::QEM`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{unit normals of the primal vertices}
      \cgalParamType{a readable property map, vertex -> 3-D vector}
      \cgalParamDefault{computed from the mesh}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_crease_normal_map}
      \cgalParamDescription{from `primal_remesh()`: a vertex inside an opened crease adds the tangent plane of the crease's other side to its faces' planes}
      \cgalParamType{a readable property map, vertex -> 3-D vector}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_color_map}
      \cgalParamDescription{colours of the primal vertices}
      \cgalParamType{a readable property map, vertex -> `CGAL::IO::Color` or triples in [0, 1]}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{progress_visitor}
      \cgalParamDescription{told how far the run is and asked whether to go on, as for `remesh()`; on cancellation `quads` is left empty}
      \cgalParamType{a callable `bool(Remeshing_stage, double)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDefault{`get(CGAL::vertex_point, primal)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
    \cgalParamNBegin{halfedge_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\param np_out optional named parameters for `quads`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDefault{`get(CGAL::vertex_point, quads)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{receives the dual normals}
      \cgalParamType{a writable property map, vertex -> 3-D vector}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_color_map}
      \cgalParamDescription{receives the average colour of each primal face}
      \cgalParamType{a writable property map}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_tangent_planes_map}
      \cgalParamDescription{receives each dual vertex's `Tangent_planes`, which `collapse_quads()` and `relax_on_tangent_planes()` use}
      \cgalParamType{a writable property map, vertex -> `Tangent_planes`}
      \cgalParamDefault{none}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\throws Remeshing_error if `primal` is empty, or is `quads`.
*/
template <class PolygonMesh, class QuadMesh,
          class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
Dual_statistics dualize(const PolygonMesh& primal, QuadMesh& quads,
                        const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                        const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  namespace np = internal_np;
  namespace cgal_np = CGAL::internal_np;
  static_assert(internal::check_named_parameters<struct dualize_in, NamedParametersIn, cgal_np::vertex_point_t,
                                                 cgal_np::vertex_normal_map_t, np::dual_placement_t,
                                                 np::vertex_crease_normal_map_t, cgal_np::vertex_color_map_t,
                                                 np::progress_visitor_t, cgal_np::vertex_index_t,
                                                 cgal_np::face_index_t, cgal_np::halfedge_index_t>());
  static_assert(internal::check_named_parameters<struct dualize_out, NamedParametersOut, cgal_np::vertex_point_t,
                                                 cgal_np::vertex_normal_map_t, np::vertex_tangent_planes_map_t,
                                                 cgal_np::vertex_color_map_t>());
  internal::refuse_same_mesh(primal, quads, "dualize()");
  const internal::Progress progress = internal::progress_of(np_in);
  return internal::emptied_on_cancel(
      quads, [&] { return internal::build_dual(primal, quads, np_in, np_out, progress); });
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_DUALIZE_H
