// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_REMESH_H
#define CGAL_RANGE_SPACE_REMESHING_REMESH_H

#include <CGAL/Range_space_remeshing/dualize.h>
#include <CGAL/Range_space_remeshing/primal_remesh.h>
#include <CGAL/Range_space_remeshing/quad_collapse.h>
#include <CGAL/Range_space_remeshing/internal/Quad_completion.h>
#include <CGAL/Range_space_remeshing/relax_on_tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Attribute_resampling.h>
#include <CGAL/Range_space_remeshing/internal/Pooled_tangent_planes_map.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_attributes.h>
#include <CGAL/Range_space_remeshing/internal/Working_frame.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <functional>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef
What a run of `remesh()` did, stage by stage.
*/
struct Remesh_statistics
{
  /// the primal stage: grid, traced complex, topology check (with `preserve_topology`,
  /// of the run whose output was kept)
  Statistics primal;
  /// the dual stage: quads, repairs, dropped pieces
  Dual_statistics dual;
  /// the faces of the dual that were not quads, made quads before the collapse
  All_quads_statistics all_quads;
  /// the quad collapse and edge rotations (all zero if not asked for)
  Collapse_statistics collapse;
  /// time of the relaxation on tangent planes
  double time_relaxation_ms = 0;
  /// the last stage: folded and non-convex faces before and after it
  Untangle_statistics untangle;
  /// time of the sampling of the vertex attributes at the output's final points (zero
  /// if there are none)
  double time_attributes_ms = 0;
  /// time of the run that gave the output, from the primal stage to the last, and of
  /// the sampling of the vertex attributes
  double time_total_ms = 0;

  /// Whether the quads have the input's topology as far as the checks tell: the
  /// primal's topology check found no defect, the dual dropped no piece, and every
  /// piece could be made all quads.
  bool topology_preserved() const
  {
    return primal.topology_preserved() && dual.dropped_pieces == 0 && all_quads.non_quads_after == 0;
  }
};

namespace internal {

// preserve_topology in remesh(): the dual's refinements, each by this factor, at most
constexpr double dual_refinement_factor = 0.70710678118654752;
constexpr int maximum_dual_refinements = 10;

/// What `remesh()` does to the quads after the dual.
struct Quad_improvement
{
  bool collapse = true;
  bool rotate_edges = true;
  std::size_t collapse_passes = 10;
  std::size_t relaxation_steps = 3;
  // With a target vertex count, the untangling runs only in a run that the search
  // accepts (it moves vertices, and its last resort removes a few, which the search
  // then counts): not in the runs it throws away.
  std::size_t untangle_near_target = 0;
  // false in the target search's first runs: refine_around_defects only once a cell
  // size near the target is found (it adds a few vertices, for thrice the runs)
  bool refine_around_defects = true;
};

template <class NamedParameters>
Quad_improvement quad_improvement_of(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Quad_improvement improvement;
  improvement.collapse = choose_parameter(get_parameter(np, internal_np::quad_collapse), true);
  improvement.rotate_edges = choose_parameter(get_parameter(np, CGAL::internal_np::do_flip), true);
  improvement.collapse_passes = count_parameter(np, internal_np::number_of_collapse_passes,
                                                improvement.collapse_passes, "number_of_collapse_passes");
  improvement.relaxation_steps = count_parameter(np, CGAL::internal_np::number_of_relaxation_steps,
                                                 improvement.relaxation_steps, "number_of_relaxation_steps");
  return improvement;
}

/// A later run of the untangling, `run`, added to the stage's statistics: its counts
/// after are the stage's, its tries counted on from the stage's (see
/// `Tangent_plane_relaxer::untangle()`).
inline void add_untangling_run(Untangle_statistics& stats, const Untangle_statistics& run)
{
  stats.folded_after = run.folded_after;
  stats.non_convex_after = run.non_convex_after;
  stats.moves += run.moves;
  stats.rounds += run.rounds;
  stats.tries = run.tries;
  stats.time_ms += run.time_ms;
}

/// The faces left tangled, untangled once more with their vertices free to leave their
/// tangent planes by a little (`off_surface_reach`), with as many tries again as the
/// first untangling.
template <class QuadMesh, class NamedParameters>
void untangle_off_surface(QuadMesh& quads, const NamedParameters& np, Untangle_statistics& stats)
{
  const std::size_t budget = stats.tries + untangle_off_surface_tries_per_vertex * stats.vertices_before;
  const Untangle_statistics last = untangle_faces_off_surface(quads, np, stats.tries, budget);
  add_untangling_run(stats, last);
  stats.moves_off_surface = last.moves;
}

/// The last stage: the untangling, and where it leaves faces tangled, with the
/// collapse's parameters (`improvement.collapse`: without it the dual's connectivity
/// stays; `rotate_edges`), the collapses and rotations that remove them, each round of
/// them followed by the untangling again from the faces they made, until a round finds
/// nothing to do (at most `maximum_rounds_of_removal`); then, for the faces still
/// tangled and again with `improvement.collapse` only, the untangling off the tangent
/// planes (`untangle_off_surface()`). The first untangling tries at most as many
/// vertices as the mesh has (see `untangle_tries_per_vertex`), the runs after it as
/// many again together (`untangle_again_tries_per_vertex`); once that is spent (a large
/// part of the mesh tangled: the cause is upstream) only the operations go on.
template <class QuadMesh, class NamedParameters>
Untangle_statistics untangle(QuadMesh& quads, const NamedParameters& np, const Quad_improvement& improvement)
{
  // Each operation leaves the faces it changes less tangled, and the moves make no face
  // worse, so the rounds end by themselves; this only bounds them.
  constexpr int maximum_rounds_of_removal = 10;
  Untangle_statistics stats = untangle_faces(quads, np);
  // per vertex of the mesh the stage starts with (the collapses remove some)
  stats.vertices_before = num_vertices(quads);
  const std::size_t budget = (untangle_tries_per_vertex + untangle_again_tries_per_vertex) * stats.vertices_before;
  // where the operations changed faces: the untangling again starts from there only (it
  // left the others as they are, and would spend its tries on them again)
  auto changed = get(CGAL::dynamic_vertex_property_t<bool>(), quads);
  for(int round = 0; improvement.collapse && round < maximum_rounds_of_removal &&
                     stats.folded_after + stats.non_convex_after > 0;
      ++round) {
    for(auto v : vertices(quads))
      put(changed, v, false);
    const std::size_t operations = stats.collapses + stats.rotations;
    const auto start = std::chrono::steady_clock::now();
    remove_tangled_quads(quads, np.do_flip(improvement.rotate_edges), stats, changed);
    stats.time_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if(stats.collapses + stats.rotations == operations)
      break;
    add_untangling_run(stats, untangle_faces_again(quads, np, changed, stats.tries, budget));
  }
  if(improvement.collapse && stats.folded_after + stats.non_convex_after > 0)
    untangle_off_surface(quads, np, stats);
  return stats;
}

/// The steps of the squaring after the untangling (`square_quads()`).
constexpr int squaring_steps = 20;

/// One run of the pipeline at cell size `h`, into `quads` (empty).
template <class ConcurrencyTag, class TriangleMesh, class QuadMesh, class NamedParameters, class NamedParametersOut>
Remesh_statistics remesh_at(double h, const TriangleMesh& tm, QuadMesh& quads, const NamedParameters& np,
                            const NamedParametersOut& np_out, const Quad_improvement& improvement,
                            const Progress& progress)
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
  Primal primal;
  auto primal_normals = primal.add_property_map<typename Primal::Vertex_index, Vector>("v:normal").first;
  auto crease_normals = primal.add_property_map<typename Primal::Vertex_index, Vector>("v:crease_normal").first;
  const auto primal_out = parameters::vertex_crease_normal_map(crease_normals).vertex_normal_map(primal_normals);

  const Out_VPM out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                           get_property_map(CGAL::vertex_point, quads));
  // the planes by slot (see Pooled_tangent_planes_map.h): the dual and the collapse
  // collect the mesh's garbage, which copies vertex properties element by element
  Tangent_planes_pool planes_pool;
  auto slots = get(CGAL::dynamic_vertex_property_t<std::size_t>(), quads);
  const Pooled_tangent_planes_map<decltype(slots)> planes(slots, planes_pool);
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0) // copies a default value, T() (uninitialised) if not given
  auto normals = get(CGAL::dynamic_vertex_property_t<Out_vector>(), quads, Out_vector(CGAL::NULL_VECTOR));
#else
  auto normals = get(CGAL::dynamic_vertex_property_t<Out_vector>(), quads);
#endif
  const Dual_placement placement =
      choose_parameter(get_parameter(np, internal_np::dual_placement), Dual_placement::QEM);
  const auto dual_in = parameters::dual_placement(placement)
                           .vertex_crease_normal_map(crease_normals)
                           .vertex_normal_map(primal_normals);
  const auto dual_out = parameters::vertex_tangent_planes_map(planes).vertex_normal_map(normals).vertex_point_map(out_vpm);
  // the stages below run with the visitor of this run
  const auto stage_parameters = parameters::vertex_tangent_planes_map(planes)
                                    .vertex_normal_map(normals)
                                    .vertex_point_map(out_vpm)
                                    .progress_visitor(std::cref(progress));
  // the stages after the primal work where its extent is about 1 (see Working_frame.h)
  Working_frame frame;
  auto finish = [&] {
    frame.move_back(quads, out_vpm);
    stats.time_total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats;
  };
  // The primal remesh, and whether it has faces.
  auto remesh_primal = [&](const auto& np_primal_out) {
    // parallel edges kept: the dual undoes them (a vertex of valence 2 would give it a digon)
    stats.primal = primal_remesh_at(h, tm, primal, np, np_primal_out, No_inspection(), progress, ConcurrencyTag(),
                                    Parallel_edges::KEEP, improvement.refine_around_defects);
    frame = Working_frame::of(primal, primal.points());
    frame.move_into(primal, primal.points());
    planes_pool.decompositions.reserve(num_faces(primal)); // one per dual vertex of a face
    return num_faces(primal) > 0;
  };
  // Nothing resolved at this cell size (or only pieces without a dual): an empty
  // result, which the statistics explain, rather than an error of a later stage.
  if(!remesh_primal(primal_out))
    return finish();
  try {
    stats.dual = build_dual(primal, quads, dual_in, dual_out, progress);
    if(stats.dual.quads + stats.dual.non_quads == 0)
      return finish();

    stats.all_quads = complete_quads(quads, stage_parameters);
    if(improvement.collapse)
      stats.collapse = collapse_quads(quads, stage_parameters.do_flip(improvement.rotate_edges)
                                                 .number_of_collapse_passes(improvement.collapse_passes));
    if(improvement.relaxation_steps > 0)
      stats.time_relaxation_ms =
          relax_on_tangent_planes(quads, stage_parameters.number_of_relaxation_steps(improvement.relaxation_steps));
    if(improvement.untangle_near_target == 0 || is_near_target(num_vertices(quads), improvement.untangle_near_target))
      stats.untangle = untangle(quads, stage_parameters, improvement);
    if(improvement.relaxation_steps > 0)
      stats.time_relaxation_ms += square_quads(quads, stage_parameters, squaring_steps);
  } catch(const Remeshing_cancelled&) {
    // cancelled after a refined primal: the last size refined from had defects
    if(stats.primal.topology_refinements == 0)
      throw;
    throw Remeshing_cancelled(stats.primal.topology_refinements,
                              stats.primal.cell_size / topology_refinement_factor);
  }
  return finish();
}

/// Whether the dual lost something the primal had: a dropped piece, or parallel edges
/// (kept, or undone by joining two faces into one that is not a quad).
inline bool dual_lost_topology(const Dual_statistics& dual)
{
  return dual.parallel_edges + dual.joined_parallel_edges + dual.dropped_pieces > 0;
}

/// `remesh_at()`; with `preserve_topology`, the cell size is also refined from the one
/// the primal needed until the dual keeps the topology too, in quads.
template <class ConcurrencyTag, class TriangleMesh, class QuadMesh, class NamedParameters, class NamedParametersOut>
Remesh_statistics remesh_keeping_topology(double h, const TriangleMesh& tm, QuadMesh& quads,
                                          const NamedParameters& np, const NamedParametersOut& np_out,
                                          const Quad_improvement& improvement, const Progress& progress)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Remesh_statistics stats = remesh_at<ConcurrencyTag>(h, tm, quads, np, np_out, improvement, progress);
  if(!choose_parameter(get_parameter(np, internal_np::preserve_topology), false))
    return stats;
  for(int refinement = 0; dual_lost_topology(stats.dual); ++refinement) {
    if(refinement == maximum_dual_refinements)
      throw Remeshing_error("preserve_topology: the dual loses the topology at every cell size tried",
                            Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED);
    remove_all_elements(quads);
    const std::size_t earlier_refinements = stats.primal.topology_refinements + 1; // and this one
    const double finest_with_defects = stats.primal.cell_size;
    try {
      stats = remesh_at<ConcurrencyTag>(finest_with_defects * dual_refinement_factor, tm, quads, np, np_out,
                                        improvement, progress);
    } catch(const Remeshing_cancelled& cancelled) {
      throw Remeshing_cancelled(earlier_refinements + cancelled.refinements(),
                                cancelled.refinements() > 0 ? cancelled.finest_cell_size() : finest_with_defects);
    }
    stats.primal.topology_refinements += earlier_refinements;
  }
  return stats;
}

} // namespace internal

namespace internal {

/// The vertex attributes (colours, texture coordinates, `vertex_attribute_maps`) where
/// the input has them (np) and the output wants them (np_out), sampled at the output's
/// final points (see Attribute_resampling.h). Returns the time taken, in ms.
template <class TriangleMesh, class QuadMesh, class NamedParameters, class NamedParametersOut>
double sample_vertex_attributes(const TriangleMesh& tm, const QuadMesh& quads, const NamedParameters& np,
                                const NamedParametersOut& np_out, const Progress& progress)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto attributes = vertex_attributes_of(np, np_out);
  if constexpr(std::decay_t<decltype(attributes)>::empty)
    return 0;
  else {
    const auto start = std::chrono::steady_clock::now();
    sample_attributes_at_nearest_points(tm,
                                        choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                         get_const_property_map(CGAL::vertex_point, tm)),
                                        quads,
                                        choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                                         get_const_property_map(CGAL::vertex_point, quads)),
                                        attributes, progress);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
}

/// Refuses, before the remesh, an input on which the vertex attributes asked for
/// cannot be sampled (see check_scale_range()).
template <class TriangleMesh, class NamedParameters, class NamedParametersOut>
void check_vertex_attributes(const TriangleMesh& tm, const NamedParameters& np, const NamedParametersOut& np_out)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if constexpr(!std::decay_t<decltype(vertex_attributes_of(np, np_out))>::empty)
    check_attributes_can_be_sampled(tm, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                         get_const_property_map(CGAL::vertex_point, tm)));
}

/// The body of `remesh()`.
template <class ConcurrencyTag, class TriangleMesh, class QuadMesh, class NamedParameters, class NamedParametersOut>
Remesh_statistics remesh_impl(const TriangleMesh& tm, QuadMesh& quads, const NamedParameters& np_in,
                              const NamedParametersOut& np_out)
{
  refuse_same_mesh(tm, quads, "remesh()");
  if(num_faces(tm) == 0)
    throw Remeshing_error("the input mesh has no face");
  const Progress progress = progress_of(np_in);
  const std::size_t target = target_vertices_of(np_in);
  Quad_improvement improvement = quad_improvement_of(np_in); // refused before the first run
  improvement.untangle_near_target = target;
  check_vertex_attributes(tm, np_in, np_out);
  primal_run_options(np_in); // its refusals before the sizing field's solve
  // the sizing field's solve: its refusals leave the output as it is, a cancel empties it
  return emptied_on_cancel(quads, [&] {
    return with_sizing_field(tm, np_in, [&](const auto& np) { return emptied_on_failure(quads, [&] {
      remove_all_elements(quads);
      const double h = target == 0 ? cell_size_of(tm, np) : first_cell_size_for_count(tm, np, target);
      Remesh_statistics stats;
      if(target == 0)
        stats = remesh_keeping_topology<ConcurrencyTag>(h, tm, quads, np, np_out, improvement, progress);
      else
        search_then_refine_around_defects(h, target, improvement.refine_around_defects, [&](double h_try) {
          remove_all_elements(quads);
          stats = remesh_keeping_topology<ConcurrencyTag>(h_try, tm, quads, np, np_out, improvement, progress);
          return std::size_t(num_vertices(quads));
        }, [&] { return stats.primal.topology_checked && !stats.primal.topology_preserved(); },
        CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::preserve_topology), false));
      stats.time_attributes_ms = sample_vertex_attributes(tm, quads, np, np_out, progress);
      stats.time_total_ms += stats.time_attributes_ms;
      return stats;
    }); });
  });
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

The whole pipeline: `primal_remesh()` of `tm`, `dualize()` of the result into
`quads`, the faces of the dual that are not quads made quads (see
`All_quads_statistics`; a piece that cannot be all quads keeps one and is counted),
`collapse_quads()`, `relax_on_tangent_planes()`, then an untangling: the
vertices of the quads left folded or non-convex (see `Untangle_statistics`), and where
needed those around them, move on their tangent planes to raise the least corner
quality of their faces, never making a face's shape worse; a quad that moves leave
tangled is collapsed along a diagonal, or an edge of it rotated, where that leaves
the faces it changes less tangled (all quads and the topology kept); faces still tangled
then (where the input folds) get one more untangling whose moves may leave the tangent
planes along the vertex normals, by at most a tenth of a vertex's mean edge length
(`Untangle_statistics::moves_off_surface`). With the relaxation, the quads are then
squared: 20 steps move each vertex inside the surface whose faces are all quads, in
the plane of its quads, towards the mean of the points that would make each of them a
square at its corner, a move taken back where it makes a face's shape worse (its time
counts in `time_relaxation_ms`). When the cell size
resolves nothing (an empty primal, or only pieces without a dual), `quads` is left
empty and the statistics say why (`dropped_pieces`, `uncrossed_border_cycles`).

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph`, a triangle mesh.
\tparam QuadMesh a model of `MutableFaceGraph`.
\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default) or `CGAL::Parallel_tag`, for
  the primal remesh (see `primal_remesh()`).

\param tm the input triangle mesh, as for `primal_remesh()`.
\param quads receives the remesh, in place of what it held (its property maps are kept).
\param np optional named parameters: those of `primal_remesh()`'s `np_in`, and
  \cgalNamedParamsBegin
    \cgalParamNBegin{grid_spacing}
      \cgalParamDescription{the cell size h of the grid, in units of f}
      \cgalParamType{double}
      \cgalParamDefault{`default_relative_cell_size` (1%) of the diagonal of the mapped input's bounding box}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_target_vertices}
      \cgalParamDescription{the number of vertices wanted in `quads`: the cell size is searched so that
                            the output has this many within 10%, in at most 12 runs of the pipeline (twice
                            as many and one more with `refine_around_defects`), from `grid_spacing`
                            or its default; unless the mapped triangles would meet more than four
                            times or less than a quarter as many cells there (by the areas of
                            their projections on the coordinate planes of the range space; not
                            with the seeded traversal): then from the size where they would meet
                            that many}
      \cgalParamType{std::size_t}
      \cgalParamDefault{none: the cell size is used as given}
      \cgalParamExtra{`Remeshing_error` of kind `TARGET_NOT_REACHED` if no cell size tried gives the count}
    \cgalParamNEnd
    \cgalParamNBegin{preserve_topology}
      \cgalParamDescription{as for `primal_remesh()`, and then the cell size is refined further (by
                            factors of \f$1/\sqrt{2}\f$, at most 10 times) until the dual drops no piece
                            and has no parallel edges: the quads keep the input's topology as far as
                            the checks tell (`Remesh_statistics::topology_preserved()`)}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{dual_placement}
      \cgalParamDescription{where `dualize()` puts the dual vertices}
      \cgalParamType{`Dual_placement`}
      \cgalParamDefault{`Dual_placement::QEM`}
    \cgalParamNEnd
    \cgalParamNBegin{quad_collapse}
      \cgalParamDescription{whether `collapse_quads()` runs, and the untangling's collapses and rotations}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{do_flip}
      \cgalParamDescription{whether the collapse (and the untangling's last resort) also rotates edges}
      \cgalParamType{bool}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_collapse_passes}
      \cgalParamDescription{the most passes of `collapse_quads()`}
      \cgalParamType{int}
      \cgalParamDefault{10}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_relaxation_steps}
      \cgalParamDescription{the steps of `relax_on_tangent_planes()` (0: no relaxation)}
      \cgalParamType{int}
      \cgalParamDefault{3}
    \cgalParamNEnd
    \cgalParamNBegin{progress_visitor}
      \cgalParamDescription{told how far the run is, and asked whether to go on: called with the
                            `Remeshing_stage` and the fraction of it done (0 to 1) on the calling
                            thread, many times per stage (at least every few milliseconds of work);
                            returning `false` cancels the run, which then throws
                            `Remeshing_cancelled` and leaves `quads` empty}
      \cgalParamType{a callable `bool(Remeshing_stage, double)`, copied once}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_color_map}
      \cgalParamDescription{the input's vertex colours, carried to `np_out`'s map: each output
                            vertex gets the colour at its nearest point of `tm` (interpolated
                            with barycentric coordinates), where it ends after the relaxation}
      \cgalParamType{a readable property map, vertex -> `CGAL::IO::Color` or `std::array<double, 3>`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_texture_map}
      \cgalParamDescription{the input's vertex texture coordinates (UV), carried to `np_out`'s map
                            as the colours are}
      \cgalParamType{a readable property map, vertex -> a CGAL 2-D point or vector, or
                     `std::array<double, 2>`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_attribute_maps}
      \cgalParamDescription{any other vertex properties of the input, carried to `np_out`'s maps of
                            the same position as the colours are}
      \cgalParamType{a readable property map, or a `std::tuple` of them; the values may be
                     numbers, `std::array`s of numbers, `CGAL::IO::Color` or CGAL 2-D and 3-D
                     points and vectors}
      \cgalParamDefault{none}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\param np_out optional named parameters for `quads`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}\cgalParamDefault{`get(CGAL::vertex_point, quads)`}\cgalParamNEnd
    \cgalParamNBegin{vertex_color_map}
      \cgalParamDescription{receives the colours, if `np` has the input's}
      \cgalParamType{a writable property map, vertex -> colour}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_texture_map}
      \cgalParamDescription{receives the texture coordinates, if `np` has the input's}
      \cgalParamType{a writable property map, vertex -> UV}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_attribute_maps}
      \cgalParamDescription{receives the properties of `np`'s maps of the same position; these and
                            the maps above are written once the run ends, for the vertices
                            `quads` then has}
      \cgalParamType{a writable property map, or a `std::tuple` of as many as `np` gives}
      \cgalParamDefault{none}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\returns what each stage did.
\throws Remeshing_error as `primal_remesh()` does, and of kind `BAD_PARAMETER` if
  `number_of_collapse_passes` or `number_of_relaxation_steps` is negative or not whole
  (before any work); `Remeshing_cancelled` when the visitor asks to stop. As for
  `primal_remesh()`, `quads` is then untouched (a refused parameter) or empty.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class QuadMesh,
          class NamedParameters = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
Remesh_statistics remesh(const TriangleMesh& tm, QuadMesh& quads,
                         const NamedParameters& np = CGAL::parameters::default_values(),
                         const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  static_assert(internal::check_primal_remesh_parameters<
                struct remesh_np, NamedParameters, internal_np::dual_placement_t, internal_np::quad_collapse_t,
                CGAL::internal_np::do_flip_t, internal_np::number_of_collapse_passes_t,
                CGAL::internal_np::number_of_relaxation_steps_t>());
  static_assert(internal::check_named_parameters<struct remesh_np_out, NamedParametersOut,
                                                 CGAL::internal_np::vertex_point_t,
                                                 CGAL::internal_np::vertex_color_map_t,
                                                 CGAL::internal_np::vertex_texture_map_t,
                                                 internal_np::vertex_attribute_maps_t>());
  if constexpr(!internal::has_usable_range_map<TriangleMesh, NamedParameters>()) {
    internal::refuse_range_map<typename internal::Range_map_of<TriangleMesh, NamedParameters>::type>();
    return Remesh_statistics();
  } else
    return internal::remesh_impl<ConcurrencyTag>(tm, quads, np, np_out);
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_REMESH_H
