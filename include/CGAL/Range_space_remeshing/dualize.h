// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
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
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

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
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

namespace internal {

/// Position and normal of the dual vertex of a primal face with tangent planes `planes`.
inline std::pair<Vec3, Vec3> place_dual_vertex(const Tangent_planes& planes, Dual_placement placement)
{
  Vec3 mass = {{0, 0, 0}}, normal = {{0, 0, 0}};
  Quadric quadric;
  for(const auto& plane : planes) {
    for(int d = 0; d < 3; ++d) {
      mass[d] += plane.first[d] / double(planes.size());
      normal[d] += plane.second[d];
    }
    quadric.add_plane(plane.first, plane.second);
  }
  const Vec3 unit_normal = normalized(normal);
  const Vec3 position = placement == Dual_placement::QEM ? quadric.minimiser(mass, 0.1, &unit_normal) : mass;
  return {position, unit_normal};
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

/// Primal edges across which the dual faces are joined so that the dual is all quads.
/// A dual face has as many corners as its primal vertex has edges, and joining the
/// faces of a tree of primal vertices gives sum(valence - 2) + 2 corners: every group
/// must reach a charge sum(valence - 2) of exactly 2. Valence-4 vertices stand alone;
/// valence-2 vertices (in two merged digons) chain together and join valence-3 ends
/// (charge 1) or, failing those, one valence-4 neighbour; charge-1 groups are matched
/// along primal edges, the most constrained first.
template <class PolygonMesh, class VertexIndexMap>
std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>
edges_to_join(const PolygonMesh& primal, VertexIndexMap vertex_index)
{
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  const std::size_t n = num_vertices(primal);
  std::vector<std::size_t> parent(n), charge(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    parent[i] = i;
  auto root = [&](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<halfedge_descriptor> low_edges; // edges with an end of valence below 4
  for(auto v : vertices(primal))
    charge[get(vertex_index, v)] = std::size_t(std::max<long>(0, long(degree(v, primal)) - 2));
  for(auto e : edges(primal)) {
    const halfedge_descriptor h = halfedge(e, primal);
    if(degree(source(h, primal), primal) < 4 || degree(target(h, primal), primal) < 4)
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
  for(;;) { // match charge-1 groups, most constrained first, until none is left
    std::vector<halfedge_descriptor> options;
    std::vector<std::size_t> count(n, 0);
    for(halfedge_descriptor h : low_edges) {
      const auto [a, b] = groups(h);
      if(a != b && charge[a] == 1 && charge[b] == 1) {
        options.push_back(h);
        ++count[a];
        ++count[b];
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
  }
  // what is left of valence-2 chains joins one valence-4 neighbour, or failing
  // that any neighbour: a group of charge 0 would be a face of degree 2
  for(std::size_t wanted : {std::size_t(2), std::size_t(1), std::size_t(3)})
    for(auto e : edges(primal)) {
      const halfedge_descriptor h = halfedge(e, primal);
      const auto [a, b] = groups(h);
      if(a != b && ((charge[a] == 0 && charge[b] >= wanted) || (charge[a] >= wanted && charge[b] == 0)))
        join(h);
    }
  return joined;
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

builds the dual of the closed polygon mesh `primal` into `quads`: one vertex per
primal face, one face per primal vertex (its incident faces in rotation order).
When every primal vertex has valence 4, as in the output of `primal_remesh()`, every
dual face is a quad. The ends of merged digons (valence 3, or 2 for a vertex in two
digons) give triangles and 2-gons; they are joined across the merged edges into quads.

The dual vertex of a primal face is placed at the average of the face's vertices
(`Dual_placement::AVERAGE`) or at the minimiser of the squared distances to their
tangent planes (`Dual_placement::QEM`, the default), solved by a truncated
eigen-decomposition around the average so that flat and rank-deficient faces stay
well placed. Its normal is the normalised average of the vertices' normals.

\param primal a closed polygon mesh (any `FaceListGraph`).
\param quads receives the dual (appended); a `MutableFaceGraph`.
\param np_in `vertex_point_map`, `vertex_normal_map` (unit normals of the primal
  vertices; default: computed from the mesh), `dual_placement`, `vertex_color_map`
  (colours of the primal vertices, `CGAL::IO::Color` or triples in [0, 1]).
\param np_out `vertex_point_map`, `vertex_normal_map` (receives the dual normals),
  `vertex_color_map` (receives the average colour of each primal face),
  `vertex_tangent_planes_map` (receives each dual vertex's `Tangent_planes`, which
  `relax_on_tangent_planes()` uses).
\throws Remeshing_error if `primal` is empty or has a border.
*/
template <class PolygonMesh, class QuadMesh,
          class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
Dual_statistics dualize(const PolygonMesh& primal, QuadMesh& quads,
                        const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                        const NamedParametersOut& np_out = CGAL::parameters::default_values())
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
  for(halfedge_descriptor h : halfedges(primal))
    if(is_border(h, primal))
      throw Remeshing_error("dualize: the primal mesh has a border (not supported yet)");

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
      return internal::to_vec3(CGAL::Polygon_mesh_processing::compute_vertex_normal(
          v, primal, CGAL::parameters::vertex_point_map(vpm)));
  };

  using Out_VPM = typename GetVertexPointMap<QuadMesh, NamedParametersOut>::type;
  Out_VPM out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                     get_property_map(CGAL::vertex_point, quads));
  using Out_point = typename boost::property_traits<Out_VPM>::value_type;
  using Out_vector = typename CGAL::Kernel_traits<Out_point>::Kernel::Vector_3;
  constexpr bool wants_normals =
      !is_default_parameter<NamedParametersOut, CGAL::internal_np::vertex_normal_map_t>::value;
  auto out_normals = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_normal_map),
                                      CGAL::Constant_property_map<dual_vertex, Out_vector>());
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

  // a dual vertex per primal face
  std::vector<dual_vertex> dual_of_face(num_faces(primal));
  Tangent_planes planes;
  for(auto f : faces(primal)) {
    planes.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, primal), primal))
      planes.emplace_back(point_of[get(vertex_index, v)], normal_of[get(vertex_index, v)]);
    const auto placed = internal::place_dual_vertex(planes, placement);
    const dual_vertex dv = add_vertex(quads);
    put(out_vpm, dv, Out_point(placed.first[0], placed.first[1], placed.first[2]));
    if constexpr(wants_normals)
      put(out_normals, dv, Out_vector(placed.second[0], placed.second[1], placed.second[2]));
    if constexpr(wants_planes)
      put(out_planes, dv, planes);
    if constexpr(wants_colors) {
      internal::Vec3 rgb = {{0, 0, 0}};
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, primal), primal)) {
        const internal::Vec3 c = internal::to_rgb(get(in_colors, v));
        for(int d = 0; d < 3; ++d)
          rgb[d] += c[d] / double(planes.size());
      }
      put(out_colors, dv, internal::from_rgb<Out_color>(rgb));
    }
    dual_of_face[get(face_index, f)] = dv;
  }

  // A dual halfedge d(h) per primal halfedge h, from the dual of face(h) to the dual
  // of face(opposite(h)), in the dual face of target(h); next(d(h)) = d(prev(opposite(h)))
  // turns counter-clockwise around target(h), so the dual has the primal's orientation.
  std::vector<dual_halfedge> dual_of_halfedge(num_halfedges(primal));
  for(auto e : edges(primal)) {
    const halfedge_descriptor h = halfedge(e, primal);
    const auto de = add_edge(quads);
    dual_of_halfedge[get(halfedge_index, h)] = halfedge(de, quads);
    dual_of_halfedge[get(halfedge_index, opposite(h, primal))] = opposite(halfedge(de, quads), quads);
  }
  auto d = [&](halfedge_descriptor h) { return dual_of_halfedge[get(halfedge_index, h)]; };
  Dual_statistics stats;
  for(vertex_descriptor v : vertices(primal)) {
    const dual_face df = add_face(quads);
    set_halfedge(df, d(halfedge(v, primal)), quads);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, primal), primal)) {
      const dual_halfedge dh = d(h);
      const dual_vertex target_vertex = dual_of_face[get(face_index, face(opposite(h, primal), primal))];
      set_target(dh, target_vertex, quads);
      set_halfedge(target_vertex, dh, quads);
      set_next(dh, d(prev(opposite(h, primal), primal)), quads);
      set_face(dh, df, quads);
    }
    ++stats.dual_faces;
  }
  stats.dual_vertices = num_faces(primal);

  // Where the primal has vertices of valence 3 and 2 (the ends of merged digons),
  // join the dual faces across the primal edges chosen by `edges_to_join()`: each
  // group of joined faces then has exactly four corners.
  for(halfedge_descriptor h : internal::edges_to_join(primal, vertex_index)) {
    const dual_halfedge dh = d(h);
    if(!internal::join_keeps_face_simple(dh, quads))
      continue; // left as two faces: counted in non_quads
    CGAL::Euler::join_face(dh, quads);
    ++stats.joined_triangle_pairs;
    --stats.dual_faces;
  }
  stats.dropped_pieces = internal::remove_pieces_with_non_simple_faces(quads, stats.dual_faces);
  internal::collect_garbage_if_any(quads);
  for(auto f : faces(quads))
    (degree(f, quads) == 4 ? stats.quads : stats.non_quads) += 1;
  stats.parallel_edges = internal::number_of_parallel_edges(quads);
  stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_DUALIZE_H
