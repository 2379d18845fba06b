// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INSERT_CREASE_TRIANGLES_H
#define CGAL_RANGE_SPACE_REMESHING_INSERT_CREASE_TRIANGLES_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>
#include <CGAL/Range_space_remeshing/internal/Soup_to_mesh.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/// What `insert_crease_triangles()` did.
struct Crease_statistics
{
  std::size_t feature_edges = 0;
  /// vertices on creases, duplicated once per smooth sector around them
  std::size_t added_vertices = 0;
  /// zero-area triangles along the creases and at their corners
  std::size_t crease_triangles = 0;
};

/*!
\ingroup PkgRangeSpaceRemeshingRef

prepares a mesh with sharp creases for maps that use normals (section 8 of the paper).
A normal field must be continuous for the Gauss map and the position + normal maps; at
a crease it is not. This function writes into `out` the same surface where every
vertex on a crease is duplicated once per smooth sector of faces around it, and the
cracks so opened are closed by triangles of zero area: two per crease edge, and a
fan at each corner where three or more sectors meet. The geometry is unchanged, but
the vertices on each side of a crease now carry that side's normal (area-weighted
normals ignore the zero-area triangles), so the normal jumps across the zero-area
strip and the remesh places arcs along the crease.

\param tm a closed triangle mesh.
\param out receives the result (cleared first); a `MutableFaceGraph` of the same point type.
\param sharp_angle_degrees an edge is a crease where the normals of its two faces make
  an angle above this (ignored if `edge_is_constrained_map` is given).
\param np optional named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{edge_is_constrained_map}
      \cgalParamDescription{the creases}
      \cgalParamType{a readable property map, edge -> bool}
      \cgalParamDefault{the edges sharper than `sharp_angle_degrees`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\throws Remeshing_error if `tm` is not a closed triangle mesh.
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Crease_statistics insert_crease_triangles(const TriangleMesh& tm, TriangleMesh& out, double sharp_angle_degrees,
                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
  using internal::Vec3;
  static_assert(internal::check_named_parameters<struct insert_crease_triangles_np, NamedParameters,
                                                 CGAL::internal_np::vertex_point_t,
                                                 CGAL::internal_np::edge_is_constrained_t>());

  if(num_faces(tm) == 0 || !CGAL::is_triangle_mesh(tm) || !CGAL::is_closed(tm))
    throw Remeshing_error("insert_crease_triangles: the input must be a non-empty closed triangle mesh");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  constexpr bool user_features = !is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value;
  const auto user_map = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                         CGAL::Constant_property_map<edge_descriptor, bool>(false));
  auto face_normal = [&](halfedge_descriptor h) {
    const Vec3 a = internal::to_vec3(get(vpm, source(h, tm))), b = internal::to_vec3(get(vpm, target(h, tm))),
               c = internal::to_vec3(get(vpm, target(next(h, tm), tm)));
    return internal::normalized(internal::cross(internal::difference(b, a), internal::difference(c, a)));
  };
  const double cos_sharp = std::cos(sharp_angle_degrees * 3.14159265358979323846 / 180);
  auto is_feature = [&](halfedge_descriptor h) {
    if constexpr(user_features)
      return bool(get(user_map, edge(h, tm)));
    else
      return internal::dot(face_normal(h), face_normal(opposite(h, tm))) < cos_sharp;
  };

  Crease_statistics stats;
  auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np);
  auto halfedge_index = CGAL::get_initialized_halfedge_index_map(tm, np);
  std::vector<char> feature(num_halfedges(tm), 0);
  for(edge_descriptor e : edges(tm))
    if(is_feature(halfedge(e, tm))) {
      feature[get(halfedge_index, halfedge(e, tm))] = feature[get(halfedge_index, opposite(halfedge(e, tm), tm))] = 1;
      ++stats.feature_edges;
    }

  // a copy of each vertex per sector: the faces around it between two creases. The
  // copy used by the corner of face(h) at target(h) is copy_of[h].
  std::vector<Vec3> points;
  std::vector<std::size_t> copy_of(num_halfedges(tm));
  std::vector<std::vector<std::size_t>> copies(num_vertices(tm)); // by vertex index, in ccw order
  for(vertex_descriptor v : vertices(tm)) {
    halfedge_descriptor start = halfedge(v, tm); // target v; a sector starts after a crease
    std::size_t creases = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
      if(feature[get(halfedge_index, h)]) {
        start = h;
        ++creases;
      }
    const Vec3 p = internal::to_vec3(get(vpm, v));
    if(creases < 2) { // one crease ending here does not split the faces around v
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
        copy_of[get(halfedge_index, h)] = points.size();
      copies[get(vertex_index, v)].push_back(points.size());
      points.push_back(p);
      continue;
    }
    // around the target, halfedges_around_target goes clockwise... walk from `start`:
    // each crease halfedge begins a new sector
    halfedge_descriptor h = start;
    do {
      if(feature[get(halfedge_index, h)]) {
        copies[get(vertex_index, v)].push_back(points.size());
        points.push_back(p);
      }
      copy_of[get(halfedge_index, h)] = points.size() - 1;
      h = opposite(next(h, tm), tm);
    } while(h != start);
    stats.added_vertices += copies[get(vertex_index, v)].size() - 1;
  }

  std::vector<std::array<std::size_t, 3>> triangles;
  for(auto f : faces(tm)) {
    const halfedge_descriptor h = halfedge(f, tm);
    triangles.push_back({{copy_of[get(halfedge_index, prev(h, tm))], copy_of[get(halfedge_index, h)],
                          copy_of[get(halfedge_index, next(h, tm))]}});
  }
  // two zero-area triangles per crease edge, closing the crack between its sides:
  // f has a_f -> b_f, g has b_g -> a_g; the strip is b_f, a_f, a_g, b_g
  for(edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    if(!feature[get(halfedge_index, h)])
      continue;
    const std::size_t b_f = copy_of[get(halfedge_index, h)], a_f = copy_of[get(halfedge_index, prev(h, tm))];
    const std::size_t a_g = copy_of[get(halfedge_index, o)], b_g = copy_of[get(halfedge_index, prev(o, tm))];
    if(a_f != a_g) {
      triangles.push_back({{b_f, a_f, a_g}});
      ++stats.crease_triangles;
    }
    if(b_f != b_g) {
      triangles.push_back({{b_f, a_g, b_g}});
      ++stats.crease_triangles;
    }
  }
  // at a vertex with three or more sectors, the copies bound a zero-size polygon
  std::vector<std::vector<std::size_t>> polygons(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    polygons[t].assign(triangles[t].begin(), triangles[t].end());
  clear(out);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  std::vector<Point> out_points;
  for(const Vec3& p : points)
    out_points.emplace_back(p[0], p[1], p[2]);
  // the package's builder, not CGAL's polygon_soup_to_polygon_mesh(), which looks each
  // new edge up around its vertex: k^2 steps at a vertex of valence k
  internal::soup_to_mesh(out_points, polygons, out);
  std::vector<halfedge_descriptor> holes;
  for(auto h : halfedges(out))
    if(is_border(h, out))
      holes.push_back(h);
  std::vector<char> filled(num_halfedges(out), 0);
  auto out_halfedge_index = CGAL::get_initialized_halfedge_index_map(out);
  for(halfedge_descriptor h : holes) {
    if(filled[get(out_halfedge_index, h)] || !is_border(h, out))
      continue;
    for(halfedge_descriptor g : CGAL::halfedges_around_face(h, out))
      filled[get(out_halfedge_index, g)] = 1;
    CGAL::Euler::fill_hole(h, out);
    halfedge_descriptor g = h;
    while(degree(face(g, out), out) > 3) { // fan from one corner
      g = prev(CGAL::Euler::split_face(g, next(next(g, out), out), out), out);
      ++stats.crease_triangles;
    }
    ++stats.crease_triangles;
  }
  return stats;
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INSERT_CREASE_TRIANGLES_H
