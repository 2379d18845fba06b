// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INSERT_CREASE_TRIANGLES_H
#define CGAL_RANGE_SPACE_REMESHING_INSERT_CREASE_TRIANGLES_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Crease_triangles.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

returns whether the edge `e` of `tm` is sharper than `sharp_angle_degrees`: the unit
normals of its two faces make an angle above it (a face without area has the zero
normal, and its edges are sharp for any angle below 90 degrees). This is
`insert_crease_triangles()`'s rule, for an `edge_is_constrained_map` that adds edges
of one's own to the sharp ones.

\param e an edge with a face on each side.
\param tm a triangle mesh.
\param sharp_angle_degrees the angle, in degrees.
\param np optional named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_sharp_edge(typename boost::graph_traits<TriangleMesh>::edge_descriptor e, const TriangleMesh& tm,
                   double sharp_angle_degrees, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  static_assert(internal::check_named_parameters<struct is_sharp_edge_np, NamedParameters,
                                                 CGAL::internal_np::vertex_point_t>());
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto h = halfedge(e, tm);
  return internal::is_sharper_than(h, tm, vpm, internal::cosine_of_degrees(sharp_angle_degrees));
}

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
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
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
  const double cos_sharp = internal::cosine_of_degrees(sharp_angle_degrees);
  auto is_feature = [&](halfedge_descriptor h) {
    if constexpr(user_features)
      return bool(get(user_map, edge(h, tm)));
    else
      return internal::is_sharper_than(h, tm, vpm, cos_sharp);
  };

  auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np);
  auto halfedge_index = CGAL::get_initialized_halfedge_index_map(tm, np);
  return internal::Crease_triangles<TriangleMesh, decltype(vpm), decltype(vertex_index), decltype(halfedge_index)>(
             tm, vpm, vertex_index, halfedge_index)
      .run(is_feature, out);
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INSERT_CREASE_TRIANGLES_H
