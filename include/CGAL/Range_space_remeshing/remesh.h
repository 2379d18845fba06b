// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_REMESH_H
#define CGAL_RANGE_SPACE_REMESHING_REMESH_H

#include <CGAL/Range_space_remeshing/dualize.h>
#include <CGAL/Range_space_remeshing/primal_remesh.h>
#include <CGAL/Range_space_remeshing/quad_collapse.h>
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Pooled_tangent_planes_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <chrono>
#include <cstddef>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef
What a run of `remesh()` did, stage by stage.
*/
struct Remesh_statistics
{
  Statistics primal;
  Dual_statistics dual;
  Collapse_statistics collapse;
  double time_relaxation_ms = 0;
  double time_total_ms = 0;

  /// Whether the quads have the input's topology as far as the checks tell: the
  /// primal's topology check found no defect and the dual dropped no piece.
  bool topology_preserved() const { return primal.topology_preserved() && dual.dropped_pieces == 0; }
};

/*!
\ingroup PkgRangeSpaceRemeshingRef

The whole pipeline: `primal_remesh()` of `tm`, `dualize()` of the result into
`quads`, `collapse_quads()`, then `relax_on_tangent_planes()`. When the cell size
resolves nothing (an empty primal, or only pieces without a dual), `quads` is left
as it was and the statistics say why (`dropped_pieces`, `uncrossed_border_cycles`).

\param tm the input triangle mesh, as for `primal_remesh()`.
\param quads receives the remesh (appended); a `MutableFaceGraph`.
\param np the named parameters of `primal_remesh()` (`range_map`, `grid_spacing`,
  `grid_origin`, `seeding_method`, `seed_faces`, `maximum_number`, `check_topology`,
  `preserve_topology`, `topology_visitor`, `vertex_point_map`, `vertex_normal_map`,
  `geom_traits`), plus `dual_placement` (default
  `Dual_placement::QEM`), `quad_collapse` (default `true`), `do_flip` (the collapse's
  edge rotations, default `true`) and `number_of_relaxation_steps` (default 3).
\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default) or `CGAL::Parallel_tag`, for
  the primal remesh (see `primal_remesh()`).
\param np_out `vertex_point_map` of `quads`; `vertex_color_map` (receives colours, if `np`
  has the input's `vertex_color_map`: sampled on the primal, averaged per quad; a
  collapsed pair keeps one of its two colours, the relaxation does not resample).
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class QuadMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
Remesh_statistics remesh(const TriangleMesh& tm, QuadMesh& quads,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Primal = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  using Out_VPM = typename GetVertexPointMap<QuadMesh, NamedParametersOut>::type;
  using Out_vector =
      typename CGAL::Kernel_traits<typename boost::property_traits<Out_VPM>::value_type>::Kernel::Vector_3;

  const auto start = std::chrono::steady_clock::now();
  Remesh_statistics stats;
  // vertex colours go along where the input has them (np) and the output wants them (np_out)
  constexpr bool wants_colors =
      !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_color_map_t>::value &&
      !CGAL::parameters::is_default_parameter<NamedParametersOut, CGAL::internal_np::vertex_color_map_t>::value;
  Primal primal;
  auto primal_normals = primal.add_property_map<typename Primal::Vertex_index, Vector>("v:normal").first;
  auto crease_normals = primal.add_property_map<typename Primal::Vertex_index, Vector>("v:crease_normal").first;
  const auto primal_out = parameters::vertex_crease_normal_map(crease_normals,
                                                               CGAL::parameters::vertex_normal_map(primal_normals));

  const Out_VPM out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                           get_property_map(CGAL::vertex_point, quads));
  // the planes by slot (see Pooled_tangent_planes_map.h): the dual and the collapse
  // collect the mesh's garbage, which copies vertex properties element by element
  internal::Tangent_planes_pool planes_pool;
  auto slots = get(CGAL::dynamic_vertex_property_t<std::size_t>(), quads);
  const internal::Pooled_tangent_planes_map<decltype(slots)> planes(slots, planes_pool);
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0) // copies a default value, T() (uninitialised) if not given
  auto normals = get(CGAL::dynamic_vertex_property_t<Out_vector>(), quads, Out_vector(CGAL::NULL_VECTOR));
#else
  auto normals = get(CGAL::dynamic_vertex_property_t<Out_vector>(), quads);
#endif
  const Dual_placement placement =
      choose_parameter(get_parameter(np, internal_np::dual_placement), Dual_placement::QEM);
  const auto dual_in = parameters::dual_placement(
      placement, parameters::vertex_crease_normal_map(crease_normals,
                                                      CGAL::parameters::vertex_normal_map(primal_normals)));
  const auto dual_out = parameters::vertex_tangent_planes_map(
      planes, CGAL::parameters::vertex_normal_map(normals).vertex_point_map(out_vpm));
  auto finish = [&] {
    stats.time_total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats;
  };
  // The primal remesh, and whether it has faces.
  auto remesh_primal = [&](const auto& np_primal_out) {
    stats.primal = primal_remesh<ConcurrencyTag>(tm, primal, np, np_primal_out);
    planes_pool.decompositions.reserve(num_faces(primal)); // one per dual vertex of a face
    return num_faces(primal) > 0;
  };
  // Nothing resolved at this cell size (or only pieces without a dual): an empty
  // result, which the statistics explain, rather than an error of a later stage.
  if constexpr(wants_colors) { // the primal carries colours only when they are wanted
    auto primal_colors = primal.add_property_map<typename Primal::Vertex_index, std::array<double, 3>>("v:color").first;
    if(!remesh_primal(primal_out.vertex_color_map(primal_colors)))
      return finish();
    stats.dual = dualize(primal, quads, dual_in.vertex_color_map(primal_colors),
                         dual_out.vertex_color_map(get_parameter(np_out, CGAL::internal_np::vertex_color_map)));
  } else {
    if(!remesh_primal(primal_out))
      return finish();
    stats.dual = dualize(primal, quads, dual_in, dual_out);
  }
  if(stats.dual.quads + stats.dual.non_quads == 0)
    return finish();

  if(choose_parameter(get_parameter(np, internal_np::quad_collapse), true))
    stats.collapse = collapse_quads(
        quads, parameters::vertex_tangent_planes_map(
                   planes, CGAL::parameters::vertex_normal_map(normals).vertex_point_map(out_vpm).do_flip(
                               choose_parameter(get_parameter(np, CGAL::internal_np::do_flip), true))));

  const int steps = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxation_steps), 3);
  if(steps > 0)
    stats.time_relaxation_ms = relax_on_tangent_planes(
        quads, parameters::vertex_tangent_planes_map(planes, CGAL::parameters::number_of_iterations(steps)
                                                                 .vertex_normal_map(normals)
                                                                 .vertex_point_map(out_vpm)));
  return finish();
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_REMESH_H
