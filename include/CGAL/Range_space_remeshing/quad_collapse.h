// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_QUAD_COLLAPSE_H
#define CGAL_RANGE_SPACE_REMESHING_QUAD_COLLAPSE_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>
#include <CGAL/Range_space_remeshing/internal/Quad_collapser.h>
#include <CGAL/Range_space_remeshing/internal/Tangled_quad_removal.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

namespace internal {

/// Puts the unit normals the operations kept by vertex index (and updated for merged
/// vertices) into `normal_map`, while the indices still name the mesh's vertices.
template <class PolygonMesh, class VertexIndexMap, class NormalMap>
void write_back_normals(const PolygonMesh& mesh, VertexIndexMap vertex_index, const std::vector<Vec3>& normals,
                        NormalMap normal_map)
{
  using Vector = typename boost::property_traits<NormalMap>::value_type;
  for(auto v : vertices(mesh)) {
    const Vec3& n = normals[get(vertex_index, v)];
    put(normal_map, v, Vector(n[0], n[1], n[2]));
  }
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

collapses quads of `mesh` along a diagonal, and rotates edges between quads, where that
makes the vertex valences more regular (section 6 of the paper, and beyond it).
Collapsing the quad (a, b, c, d) along (a, c) merges a and c into one vertex and removes the quad; the edges a-b and b-c become one,
and so do c-d and d-a, so an all-quad mesh stays all quads. A collapse is done when it
lowers the valence energy \f$\sum (\mathrm{valence} - 4)^2\f$ of the vertices
involved, and only if the result stays a valid manifold mesh:
- a and c share no neighbour but b and d and no face but the quad (link condition:
  no parallel edge, no face visiting a vertex twice, no non-manifold vertex);
- b and d keep a valence of at least 3 (no doublet);
- no face around the merged vertex folds over: each triangle of its fan from the merged
  vertex keeps a positive orientation with respect to the face's normal before the collapse;
- a and c are not constrained (`vertex_is_constrained_map`).

Before the collapses, and again after them, the doublets go: a vertex of valence 2
inside the surface, whose two faces are distinct quads sharing two edges, is removed
and its two quads become one (unless it is constrained, a neighbour on the border
would drop below valence 2, the merged quad would visit a vertex twice, or it would
face against the two). A neighbour of valence 3 this leaves with valence 2 (if it is
inside, not constrained, and its third face is a quad) is a doublet in turn and is
tried next. The second sweep takes those the first had to leave and the passes'
operations since freed.

The collapses are interleaved with edge rotations (unless `do_flip` is `false`): the
edge u-v between the quads (u, v, f1, f2) and (v, u, g1, g2) turns to join f1 and g1
(or f2 and g2), when that lowers the same energy. No vertex moves and the counts stay:
a rotation evens out valences where no collapse can, e.g. a valence-5 vertex beside a
valence-3 one that is not across a quad from another valence-3 vertex. A rotation is
done only if u and v keep a valence of at least 3 (2 on the border) and are not
constrained, the two quads' six corners are distinct vertices, the new edge joins two
vertices not yet joined, and both new quads are convex and face like the old pair.

What no single operation mends are mostly dipoles: a valence-3 vertex beside a
valence-5 one. Once nothing lowers the energy, the dipoles are walked (also part of
`do_flip`): a rotation that keeps the energy moves a dipole one step, and it is kept
only if a collapse or a rotation around its four vertices then lowers the energy
(two dipoles cancel); else it is turned back. Every kept pair lowers the energy, so
the passes end.

The merged vertex takes the union of the two vertices' tangent planes (their quadric
error), and is placed as in the relaxation: the midpoint moved to the nearest
minimiser of the squared distances to the merged tangent planes, along the directions
they constrain (the normal in a smooth region; onto the crease line where the planes
of two sides meet). A vertex whose tangent planes' points enclose nothing (the dual
vertex of a primal face inside a crease opened by `insert_crease_triangles()`) keeps
its place, and two such vertices meet on one of their faces' sides: the midpoint of
vertices on two creases of a concave corner lies in the notch between them, which
the planes of a side do not keep it out of. Collapses and rotations are tried in passes, in decreasing order of
energy decrease, until a pass (or a walk of the dipoles, which counts as one) changes
nothing or `number_of_collapse_passes` passes have run.

\tparam PolygonMesh a model of `MutableFaceGraph` (e.g. `Surface_mesh`, `Polyhedron_3`).
\param mesh a polygon mesh, valid, with or without border, whose faces are simple polygons. A
  `Surface_mesh` is garbage-collected at the end, so that its indices stay contiguous.
\param np optional named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{number_of_collapse_passes}
      \cgalParamDescription{the most passes}
      \cgalParamType{int}
      \cgalParamDefault{10}
    \cgalParamNEnd
    \cgalParamNBegin{do_flip}
      \cgalParamDescription{whether edges are rotated too}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_tangent_planes_map}
      \cgalParamDescription{the planes merged vertices are placed on (e.g. from `dualize()`); updated}
      \cgalParamType{a read-write property map, vertex -> `Tangent_planes`}
      \cgalParamDefault{the planes of each vertex's incident faces, so that merged vertices stay on the mesh's faces, creases and corners}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{unit normals; updated}
      \cgalParamType{a read-write property map, vertex -> 3-D vector}
      \cgalParamDefault{the average normal of each vertex's tangent planes}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map}
      \cgalParamDescription{vertices never merged nor moved}
      \cgalParamType{a readable property map, vertex -> bool}
      \cgalParamDefault{none constrained}
    \cgalParamNEnd
    \cgalParamNBegin{progress_visitor}
      \cgalParamDescription{told how far the passes are and asked whether to go on, as for `remesh()`; on cancellation the mesh is left valid, with the collapses and rotations done so far}
      \cgalParamType{a callable `bool(Remeshing_stage, double)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{read-write}
      \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{the 3-D kernel}
      \cgalParamDefault{the kernel of the point type}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
  \cgalNamedParamsEnd
Border vertices are never moved nor merged (so no border cycle moves or joins
another); their regular valence is 3 in the energy.
\throws Remeshing_error if the mesh is empty, or (`BAD_PARAMETER`) if
  `number_of_collapse_passes` is negative or not whole.
*/
template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Collapse_statistics collapse_quads(PolygonMesh& mesh,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using GeomTraits = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;
  using Vector = typename GeomTraits::Vector_3;
  static_assert(internal::check_named_parameters<
                struct collapse_quads_np, NamedParameters, CGAL::internal_np::vertex_point_t,
                CGAL::internal_np::geom_traits_t, CGAL::internal_np::vertex_normal_map_t,
                internal_np::vertex_tangent_planes_map_t, CGAL::internal_np::vertex_is_constrained_t,
                CGAL::internal_np::do_flip_t, internal_np::number_of_collapse_passes_t, internal_np::progress_visitor_t,
                CGAL::internal_np::vertex_index_t, CGAL::internal_np::face_index_t>());

  const auto start = std::chrono::steady_clock::now();
  if(num_faces(mesh) == 0)
    throw Remeshing_error("collapse_quads: the mesh has no face");

  using VPM = typename GetVertexPointMap<PolygonMesh, NamedParameters>::type;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, mesh));
  const int passes = int(internal::count_parameter(np, internal_np::number_of_collapse_passes, 10,
                                                   "number_of_collapse_passes"));
  const internal::Progress progress = internal::progress_of(np);
  const bool rotate_edges = choose_parameter(get_parameter(np, CGAL::internal_np::do_flip), true);
  auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                      CGAL::Constant_property_map<vertex_descriptor, bool>(false));
  auto vertex_index = CGAL::get_initialized_vertex_index_map(mesh, np);
  const std::size_t index_bound = internal::index_bound(vertices(mesh), vertex_index);

  constexpr bool has_planes = !is_default_parameter<NamedParameters, internal_np::vertex_tangent_planes_map_t>::value;
  constexpr bool has_normals = !is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value;
  auto normal_map = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_normal_map),
                                     CGAL::Constant_property_map<vertex_descriptor, Vector>(CGAL::NULL_VECTOR));

  // Unit normals, by vertex index: what the projection of merged vertices uses.
  std::vector<internal::Vec3> normals(index_bound);
  std::vector<Tangent_planes> own_planes;
  if constexpr(!has_planes)
    own_planes = internal::planes_of_incident_faces(mesh, vpm, vertex_index);
  auto planes = choose_parameter(get_parameter(np, internal_np::vertex_tangent_planes_map),
                                 boost::make_iterator_property_map(own_planes.begin(), vertex_index));
  for(vertex_descriptor v : vertices(mesh))
    normals[get(vertex_index, v)] = internal::normalized(
        has_normals ? internal::to_vec3(get(normal_map, v)) : internal::average_normal(get(planes, v)));

  auto face_index = CGAL::get_initialized_face_index_map(mesh, np);
  internal::Quad_collapser<PolygonMesh, VPM, decltype(planes), decltype(constrained),
                           decltype(vertex_index), decltype(face_index)>
      collapser(mesh, vpm, planes, constrained, vertex_index, face_index, normals, rotate_edges);
  // the mesh is valid after each collapse or rotation: a cancellation keeps those done
  auto finish = [&] {
    if constexpr(has_normals) // before the garbage collection: indices still match
      internal::write_back_normals(mesh, vertex_index, normals, normal_map);
    internal::collect_garbage_if_any(mesh);
  };
  Collapse_statistics stats;
  try {
    stats = collapser.run(passes, progress);
  } catch(const Remeshing_cancelled&) {
    finish();
    throw;
  }
  finish();
  stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

namespace internal {

/// The last resort of the untangling (see Tangled_quad_removal.h), with the
/// parameters of `collapse_quads()` and, required, its tangent planes and normals.
/// Adds the collapses and rotations done to the statistics; sets `changed` (vertex ->
/// bool) at a corner of every face they made.
template <class PolygonMesh, class NamedParameters, class ChangedMap>
void remove_tangled_quads(PolygonMesh& mesh, const NamedParameters& np, Untangle_statistics& stats,
                          ChangedMap changed)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using VPM = typename GetVertexPointMap<PolygonMesh, NamedParameters>::type;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, mesh));
  auto constrained = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                      CGAL::Constant_property_map<vertex_descriptor, bool>(false));
  auto vertex_index = CGAL::get_initialized_vertex_index_map(mesh, np);
  auto face_index = CGAL::get_initialized_face_index_map(mesh, np);
  auto planes = get_parameter(np, internal_np::vertex_tangent_planes_map);
  auto normal_map = get_parameter(np, CGAL::internal_np::vertex_normal_map);
  std::vector<Vec3> normals(index_bound(vertices(mesh), vertex_index));
  for(vertex_descriptor v : vertices(mesh))
    normals[get(vertex_index, v)] = normalized(to_vec3(get(normal_map, v)));
  Tangled_quad_remover<PolygonMesh, VPM, decltype(planes), decltype(constrained), decltype(vertex_index),
                       decltype(face_index)>
      remover(mesh, vpm, planes, constrained, vertex_index, face_index, normals,
              choose_parameter(get_parameter(np, CGAL::internal_np::do_flip), true));
  remover.run(stats.collapses, stats.rotations, changed);
  write_back_normals(mesh, vertex_index, normals, normal_map); // before the garbage collection
  collect_garbage_if_any(mesh);
}

} // namespace internal

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_QUAD_COLLAPSE_H
