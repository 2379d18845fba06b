// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_DUALIZE_H
#define CGAL_RANGE_SPACE_REMESHING_DUALIZE_H

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Dual_builder.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Range_space_remeshing {

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
Border vertices of valence 2 inside a chain have no dual face, and a face whose
vertices all lack one (a piece made of one face) has no dual; it counts as a dropped
piece. A border cycle with fewer than three chains (a small hole) is also cut at one
or two of its vertices of valence 2, so that its dual border has no fewer than three
edges: each has a dual face, a quad whose fourth corner is a dual vertex at the cut
vertex itself, on the primal border.

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
    \cgalParamNBegin{vertex_texture_map}
      \cgalParamDescription{texture coordinates (UV) of the primal vertices}
      \cgalParamType{a readable property map, vertex -> a CGAL 2-D point or vector, or `std::array<double, 2>`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_attribute_maps}
      \cgalParamDescription{any other vertex properties of the primal}
      \cgalParamType{a readable property map, or a `std::tuple` of them (value types as for `primal_remesh()`)}
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
    \cgalParamNBegin{vertex_texture_map}
      \cgalParamDescription{receives the texture coordinates, mixed as the colours are}
      \cgalParamType{a writable property map}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_attribute_maps}
      \cgalParamDescription{receives the properties of `np_in`'s maps of the same position, mixed as
                            the colours are}
      \cgalParamType{a writable property map, or a `std::tuple` of as many as `np_in` gives}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_tangent_planes_map}
      \cgalParamDescription{receives each dual vertex's `Tangent_planes`, which `collapse_quads()` and `relax_on_tangent_planes()` use}
      \cgalParamType{a writable property map, vertex -> `Tangent_planes`}
      \cgalParamDefault{none}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\throws Remeshing_error if `primal` is `quads` (nothing touched), or is empty (`quads`
  then left empty, as on any exception during the construction).
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
                                                 cgal_np::vertex_texture_map_t, np::vertex_attribute_maps_t,
                                                 np::progress_visitor_t, cgal_np::vertex_index_t,
                                                 cgal_np::face_index_t, cgal_np::halfedge_index_t>());
  static_assert(internal::check_named_parameters<struct dualize_out, NamedParametersOut, cgal_np::vertex_point_t,
                                                 cgal_np::vertex_normal_map_t, np::vertex_tangent_planes_map_t,
                                                 cgal_np::vertex_color_map_t, cgal_np::vertex_texture_map_t,
                                                 np::vertex_attribute_maps_t>());
  internal::refuse_same_mesh(primal, quads, "dualize()");
  const internal::Progress progress = internal::progress_of(np_in);
  return internal::emptied_on_failure(
      quads, [&] { return internal::build_dual(primal, quads, np_in, np_out, progress); });
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_DUALIZE_H
