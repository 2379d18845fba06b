// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_RELAX_ON_TANGENT_PLANES_H
#define CGAL_RANGE_SPACE_REMESHING_RELAX_ON_TANGENT_PLANES_H

#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Tangent_plane_relaxer.h>

#include <CGAL/Named_function_parameters.h>

#include <chrono>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

relaxes the vertices of `mesh` over the surface they sample (section 6 of the paper).
Each of the `number_of_relaxation_steps` steps (a) replaces every vertex's position
and normal by the average of its neighbours' (the normal renormalised), which spreads
the vertices evenly but shrinks and smooths, then (b) moves it back to the nearest
minimiser of the squared distances to its tangent planes, along the directions those
planes constrain and no other (directions whose eigenvalue in the planes' quadric is
below a tenth of the largest are free). The planes are weighted by how close their
points are to the averaged position (inverse square of the squared distance, softened,
and at least a tenth of the largest weight): a tangent plane strays from a curved
surface with the square of the distance to its point, so where the vertex has slid
towards one side of its planes, those on that side say where the surface is (weighted
alike, they leave the relaxed vertices off the surface: benchmark/RESULTS.md). This
undoes the shrinking: in a smooth region
the vertex moves along the normal only, as the paper's projection on the line
\f$v' + \lambda n'\f$ does, and slides freely on the surface; on a crease, where the
planes of both sides meet, it goes back onto the crease line, and at a corner onto the
corner, which the paper's single line could not reach.

A vertex whose tangent planes' points, in order, are the corners of a polygon that
encloses nothing (a segment, or a tree of segments) stays where it is: `dualize()`
gives those to the dual vertex of a primal face inside the zero-area strips of
creases opened by `insert_crease_triangles()` (or where strips meet), and puts it on
the crease. Its planes (the two sides', or blends of
them where the primal had no crease normals) would let the average of its neighbours pull it along or off the
crease, across the notch of a concave corner, where the fold test below cannot see
it (benchmark/RESULTS.md).

No iteration folds a face that was not folded: where the moves would turn a face
against its corners' normals, its corners keep their places (and the faces around
them are checked again, until none is left). The average of the neighbours can
pull a vertex across a concave crease or a notch where creases meet, which its planes
do not hold it from; the face then spans the notch (benchmark/RESULTS.md).

Border vertices (paper, section 7) are averaged with their two border neighbours only,
and put back on the border they sample, so that it does not shrink: with
`vertex_tangent_planes_map`, on the segment between the points of their two tangent
planes (a dual border vertex from `dualize()` has those of the ends of the primal
border edge it lies on; a border vertex with another number of planes stays where it
is); without, on their own two border edges as they were before the relaxation, and
corners of the border (where it turns by more than 30 degrees) stay.

\param mesh a polygon mesh (any `FaceGraph`, e.g. the output of `dualize()`);
  positions (and normals if given) are updated, the connectivity is not.
\param np optional named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{number_of_relaxation_steps}
      \cgalParamDescription{the steps}
      \cgalParamType{int}
      \cgalParamDefault{3}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_tangent_planes_map}
      \cgalParamDescription{the planes each vertex is projected on (e.g. from `dualize()` and `collapse_quads()`)}
      \cgalParamType{a readable property map, vertex -> `Tangent_planes`}
      \cgalParamDefault{the planes of each vertex's incident faces, so that vertices of a mesh that came without planes stay on its faces, creases and corners}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{unit normals; updated}
      \cgalParamType{a read-write property map, vertex -> 3-D vector}
      \cgalParamDefault{the average normal of each vertex's tangent planes}
    \cgalParamNEnd
    \cgalParamNBegin{progress_visitor}
      \cgalParamDescription{told how far the steps are and asked whether to go on, as for `remesh()`; on cancellation the mesh is left unchanged}
      \cgalParamType{a callable `bool(Remeshing_stage, double)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{read-write}
      \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\returns the time taken, in milliseconds.
\throws Remeshing_error of kind `BAD_PARAMETER` if `number_of_relaxation_steps` is
  negative or not whole.
*/
template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
double relax_on_tangent_planes(PolygonMesh& mesh, const NamedParameters& np = CGAL::parameters::default_values())
{
  static_assert(internal::check_named_parameters<
                struct relax_on_tangent_planes_np, NamedParameters, internal_np::vertex_tangent_planes_map_t,
                CGAL::internal_np::number_of_relaxation_steps_t, CGAL::internal_np::vertex_point_t,
                CGAL::internal_np::vertex_normal_map_t, internal_np::progress_visitor_t,
                CGAL::internal_np::vertex_index_t>());
  const auto start = std::chrono::steady_clock::now();
  const internal::Progress progress = internal::progress_of(np);
  const int iterations = int(internal::count_parameter(np, CGAL::internal_np::number_of_relaxation_steps, 3,
                                                       "number_of_relaxation_steps"));
  internal::Tangent_plane_relaxer<PolygonMesh, NamedParameters>(mesh, np, progress).run(iterations);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

namespace internal {

/// The squaring of `remesh()`'s quads after the untangling: `steps` steps of
/// `Tangent_plane_relaxer::square_up()`, with the parameters of
/// `relax_on_tangent_planes()`. Returns the time taken, in ms.
template <class PolygonMesh, class NamedParameters>
double square_quads(PolygonMesh& mesh, const NamedParameters& np, int steps)
{
  const auto start = std::chrono::steady_clock::now();
  const Progress progress = progress_of(np);
  Tangent_plane_relaxer<PolygonMesh, NamedParameters>(mesh, np, progress).square_up(steps);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// The untangling of `remesh()` (see `Untangle_statistics` and Quad_untangler.h), with
/// the parameters of `relax_on_tangent_planes()` but its steps: after the relaxation,
/// or in place of it.
template <class PolygonMesh, class NamedParameters>
Untangle_statistics untangle_faces(PolygonMesh& mesh, const NamedParameters& np)
{
  const Progress progress = progress_of(np);
  return Tangent_plane_relaxer<PolygonMesh, NamedParameters>(mesh, np, progress)
      .untangle(0, untangle_tries_per_vertex * num_vertices(mesh));
}

/// The untangling again, after the last resort's operations: from the tangled faces
/// with a corner where `start_at` is true; `tried_before`, `budget`: see
/// `Tangent_plane_relaxer::untangle()`.
template <class PolygonMesh, class NamedParameters, class StartAtMap>
Untangle_statistics untangle_faces_again(PolygonMesh& mesh, const NamedParameters& np, StartAtMap start_at,
                                         std::size_t tried_before, std::size_t budget)
{
  const Progress progress = progress_of(np);
  return Tangent_plane_relaxer<PolygonMesh, NamedParameters>(mesh, np, progress)
      .untangle(tried_before, budget, start_at);
}

/// The last untangling, where faces stay tangled after the others and the operations:
/// from the faces not convex in themselves (seen from their own vector area), whose
/// vertices, and those around them, may leave their tangent planes by a little (see
/// `Tangent_plane_relaxer::untangle()`). A face only folded against its corners'
/// normals (bent over a thin limb, convex) is left as it is.
template <class PolygonMesh, class NamedParameters>
Untangle_statistics untangle_faces_off_surface(PolygonMesh& mesh, const NamedParameters& np,
                                               std::size_t tried_before, std::size_t budget)
{
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  const Progress progress = progress_of(np);
  return Tangent_plane_relaxer<PolygonMesh, NamedParameters>(mesh, np, progress)
      .untangle(tried_before, budget, CGAL::Constant_property_map<vertex_descriptor, bool>(false), true);
}

} // namespace internal

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_RELAX_ON_TANGENT_PLANES_H
