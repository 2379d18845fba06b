// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_SMOOTH_VERTEX_NORMALS_H
#define CGAL_RANGE_SPACE_REMESHING_SMOOTH_VERTEX_NORMALS_H

// Vertex normals averaged over a few rings of the mesh, for the normal-based maps. A
// scan or a coarse tessellation has sharp edges between its facets, where the vertex
// normal turns by tens of degrees over one short edge: a step of f's normal part that
// no cell resolves, and which the grid cuts into closed loops and pieces that change
// the topology (benchmark/RESULTS.md, man with position-normal). The bound the remesh
// keeps on the normal part then holds for these normals.

#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// By face index: whether two consecutive corners of the face are one point, as in
/// the triangles of an opened crease (a test of equality, whatever the mesh's scale).
template <class TriangleMesh, class NamedParameters>
std::vector<char> faces_with_coincident_corners(const TriangleMesh& tm, const NamedParameters& np)
{
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<char> coincident(index_bound(faces(tm), face_index), 0);
  for(auto f : faces(tm))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      if(get(vpm, source(h, tm)) == get(vpm, target(h, tm)))
        coincident[get(face_index, f)] = 1;
  return coincident;
}

/// Whether a sum of `terms` unit vectors (or zeros) is too short to give a direction:
/// the terms cancel up to rounding.
inline bool cancels(const Vec3& sum, std::size_t terms)
{
  return !(dot(sum, sum) > 1e-24 * double(terms) * double(terms));
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingMaps

replaces each vertex normal of `tm` in `normals` by the unit sum of its own and its
neighbours' (the vertices it shares an edge with), as many times as asked: after k
iterations a normal is a weighted mean over the vertices within k edges. All are
read before any is written, so the result does not depend on the order of the
vertices. A vertex whose sum cancels up to rounding (a thin sheet folded onto itself)
keeps its normal; a zero normal (see `compute_vertex_normals()`) adds nothing to its
neighbours' in the first round, and has their mean from then on.

An edge joins two normals only where a face on it has no two corners at one point:
the triangles of a crease opened by `insert_crease_triangles()` join nothing, so each
side of the crease keeps its own normals, but where the crease ends (its last vertex
is not duplicated, the sides meet there). A crease left closed is smoothed over about
k edges on either side.

\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` (its faces may be
        polygons).
\tparam VertexNormalMap a read-write property map, vertex -> `std::array<double, 3>` or
        a CGAL 3-D vector.
\tparam NamedParameters a sequence of named parameters.

\param tm the mesh.
\param normals the unit normals of its vertices, replaced.
\param np an optional sequence of named parameters among those below.

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the rounds of averaging}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`1`}
    \cgalParamExtra{a whole number from 0 to 10^6: `Remeshing_error` (`BAD_PARAMETER`) otherwise}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with vertex descriptor as key type and a 3-D CGAL point as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
    \cgalParamType{a class model of `ReadablePropertyMap` with vertex descriptor as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
    \cgalParamType{a class model of `ReadablePropertyMap` with face descriptor as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd

The cost is linear in the mesh's edges, per iteration.
*/
template <class TriangleMesh, class VertexNormalMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void smooth_vertex_normals(const TriangleMesh& tm, VertexNormalMap normals,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Normal = typename boost::property_traits<VertexNormalMap>::value_type;
  static_assert(internal::check_named_parameters<struct smooth_vertex_normals_np, NamedParameters,
                                                 CGAL::internal_np::number_of_iterations_t,
                                                 CGAL::internal_np::vertex_point_t,
                                                 CGAL::internal_np::vertex_index_t,
                                                 CGAL::internal_np::face_index_t>());
  const std::size_t iterations = internal::count_parameter(np, CGAL::internal_np::number_of_iterations, 1,
                                                           "smooth_vertex_normals: number_of_iterations", 1000000);
  const auto index = CGAL::get_initialized_vertex_index_map(tm, np);
  const std::vector<char> crease = internal::faces_with_coincident_corners(tm, np);
  const auto face_index = CGAL::get_initialized_face_index_map(tm, np);
  auto joins = [&](auto h) { // an edge on a face that is not a crease triangle
    for(auto g : {face(h, tm), face(opposite(h, tm), tm)})
      if(g != boost::graph_traits<TriangleMesh>::null_face() && !crease[get(face_index, g)])
        return true;
    return false;
  };
  std::vector<internal::Vec3> current(internal::index_bound(vertices(tm), index));
  for(vertex_descriptor v : vertices(tm))
    current[get(index, v)] = internal::to_vec3(get(normals, v));
  std::vector<internal::Vec3> smoothed(current.size());
  for(std::size_t round = 0; round < iterations; ++round) {
    for(vertex_descriptor v : vertices(tm)) {
      internal::Vec3 sum = current[get(index, v)];
      std::size_t terms = 1;
      if(halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge())
        for(auto h : CGAL::halfedges_around_target(halfedge(v, tm), tm))
          if(joins(h)) {
            for(int d = 0; d < 3; ++d)
              sum[d] += current[get(index, source(h, tm))][d];
            ++terms;
          }
      smoothed[get(index, v)] = internal::cancels(sum, terms) ? current[get(index, v)] : internal::normalized(sum);
    }
    current.swap(smoothed);
  }
  for(vertex_descriptor v : vertices(tm))
    put(normals, v, internal::make_vector<Normal>(current[get(index, v)]));
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_SMOOTH_VERTEX_NORMALS_H
