// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_COPY_IN_SPATIAL_ORDER_H
#define CGAL_RANGE_SPACE_REMESHING_COPY_IN_SPATIAL_ORDER_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Hilbert_face_order.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

copies a polygon mesh so that its elements are stored in spatial order: the faces
along a Hilbert curve through their centroids, the vertices in the order in which
those faces first use them. The copy is the same surface, with the same connectivity
and points.

Why: the remeshers walk from face to neighbouring face, and read each face and vertex
where the input's numbering puts it. Files often store their faces in the order a
modeller or a refinement made them, scattered over memory for a walk on the surface;
the contouring of the copy is then faster, and a deforming mesh remeshed frame after
frame gets more frames per second (benchmark/RESULTS.md says by how much). The copy costs about as much as several
remeshes, so it pays for a mesh remeshed many times, or stored once in this order.

Elements are appended to `out` (as `CGAL::copy_face_graph()` does); properties other
than the points are not copied: the maps of `np_in` tell where each element went, to
copy them.

\tparam PolygonMesh a model of `FaceListGraph`.
\tparam PolygonMeshOut a model of `MutableFaceGraph` and `VertexListGraph`.
\param tm the mesh to copy: a valid polygon mesh.
\param out receives the copy.
\param np_in optional named parameters for `tm`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_to_vertex_map}
      \cgalParamDescription{receives, for each vertex of `tm`, its copy}
      \cgalParamType{a writable property map, vertex of `tm` -> vertex of `out`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{face_to_face_map}
      \cgalParamDescription{receives, for each face of `tm`, its copy}
      \cgalParamType{a writable property map, face of `tm` -> face of `out`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\param np_out optional named parameters for `out`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDefault{`get(CGAL::vertex_point, out)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\throws Remeshing_error if `out` is `tm`, if a point of a face has a NaN or infinite coordinate (`out`
  is then unchanged), or if a face of `tm` cannot be added to `out` (`tm` is not a
  valid polygon mesh; `out` then holds a part of the copy).
*/
template <class PolygonMesh, class PolygonMeshOut, class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
void copy_in_spatial_order(const PolygonMesh& tm, PolygonMeshOut& out,
                           const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                           const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  static_assert(internal::check_named_parameters<struct copy_in_spatial_order_in, NamedParametersIn,
                                                 CGAL::internal_np::vertex_point_t, CGAL::internal_np::vertex_index_t,
                                                 CGAL::internal_np::vertex_to_vertex_map_t,
                                                 CGAL::internal_np::face_to_face_map_t>());
  static_assert(internal::check_named_parameters<struct copy_in_spatial_order_out, NamedParametersOut,
                                                 CGAL::internal_np::vertex_point_t>());
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using out_vertex = typename boost::graph_traits<PolygonMeshOut>::vertex_descriptor;
  using out_face = typename boost::graph_traits<PolygonMeshOut>::face_descriptor;
  using Out_point = typename boost::property_traits<
      typename GetVertexPointMap<PolygonMeshOut, NamedParametersOut>::type>::value_type;
  internal::refuse_same_mesh(tm, out, "copy_in_spatial_order()");
  using In_point = typename boost::property_traits<
      typename GetVertexPointMap<PolygonMesh, NamedParametersIn>::const_type>::value_type;

  const auto vpm = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                        get_property_map(CGAL::vertex_point, out));
  const auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np_in);
  // a constant map ignores what is put in it: nothing to tell when no map is given
  auto vertex_to_vertex = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_to_vertex_map),
                                           CGAL::Constant_property_map<vertex_descriptor, out_vertex>());
  auto face_to_face = choose_parameter(get_parameter(np_in, CGAL::internal_np::face_to_face_map),
                                       CGAL::Constant_property_map<face_descriptor, out_face>());

  // the point itself where both meshes have the same point type, else its coordinates
  // in double precision
  auto copied_point = [&](vertex_descriptor v) -> Out_point {
    if constexpr(std::is_same<In_point, Out_point>::value)
      return get(vpm, v);
    else {
      const internal::Vec3 p = internal::to_vec3(get(vpm, v));
      return Out_point(p[0], p[1], p[2]);
    }
  };
  const out_vertex not_copied = boost::graph_traits<PolygonMeshOut>::null_vertex();
  std::vector<out_vertex> copy_of(internal::index_bound(vertices(tm), vertex_index), not_copied);
  // the copy of v, made on its first use
  auto copy_vertex = [&](vertex_descriptor v) {
    out_vertex& w = copy_of[get(vertex_index, v)];
    if(w == not_copied) {
      w = add_vertex(out);
      put(out_vpm, w, copied_point(v));
      put(vertex_to_vertex, v, w);
    }
    return w;
  };
  std::vector<out_vertex> corners;
  for(face_descriptor f : internal::faces_in_hilbert_order(tm, vpm)) {
    corners.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      corners.push_back(copy_vertex(v));
    const out_face g = CGAL::Euler::add_face(corners, out);
    if(g == boost::graph_traits<PolygonMeshOut>::null_face())
      throw Remeshing_error("copy_in_spatial_order: a face of the input cannot be added to the copy: the input "
                            "is not a valid polygon mesh");
    put(face_to_face, f, g);
  }
  // vertices on no face come last, in the input's order
  for(vertex_descriptor v : vertices(tm))
    copy_vertex(v);
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_COPY_IN_SPATIAL_ORDER_H
