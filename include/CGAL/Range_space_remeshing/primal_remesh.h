// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_PRIMAL_REMESH_H
#define CGAL_RANGE_SPACE_REMESHING_PRIMAL_REMESH_H

// `primal_remesh()`: its documentation, its named parameters checked, and the choice
// between one run at the given cell size and the search for a target vertex count.
// The steps of a run are in internal/Primal_run.h, the reading of the parameters in
// internal/Primal_parameters.h, the cell size in internal/Cell_size.h.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Sized_range_map.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Cell_size.h>
#include <CGAL/Range_space_remeshing/internal/Primal_parameters.h>
#include <CGAL/Range_space_remeshing/internal/Primal_run.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <cstddef>

namespace CGAL {
namespace Range_space_remeshing {

namespace internal {

/// `primal_remesh()`: at the cell size of `np`, or at the one found for
/// `number_of_target_vertices`; on cancellation `out` is left empty.
template <class TriangleMesh, class PolygonMesh, class NamedParametersIn, class NamedParametersOut,
          class Inspector, class ConcurrencyTag = CGAL::Sequential_tag>
Statistics primal_remesh_impl(const TriangleMesh& tm, PolygonMesh& out, const NamedParametersIn& np_in,
                              const NamedParametersOut& np_out, const Inspector& inspect,
                              ConcurrencyTag tag = ConcurrencyTag())
{
  refuse_same_mesh(tm, out, "primal_remesh()");
  if(num_faces(tm) == 0)
    throw Remeshing_error("the input mesh has no face");
  const Progress progress = progress_of(np_in);
  const std::size_t target = target_vertices_of(np_in);
  primal_run_options(np_in); // its refusals before the sizing field's solve
  // the sizing field's solve: its refusals leave the output as it is, a cancel empties it
  return emptied_on_cancel(out, [&] {
    return with_sizing_field(tm, np_in, [&](const auto& np) { return emptied_on_failure(out, [&] {
      remove_all_elements(out);
      if(target == 0)
        return primal_remesh_at(cell_size_of(tm, np), tm, out, np, np_out, inspect, progress, tag);
      const double h = first_cell_size_for_count(tm, np, target);
      Statistics stats;
      bool refine_around_defects = true;
      search_then_refine_around_defects(h, target, refine_around_defects, [&](double h_try) {
        remove_all_elements(out);
        stats = primal_remesh_at(h_try, tm, out, np, np_out, inspect, progress, tag, Parallel_edges::SPLIT,
                                 refine_around_defects);
        return stats.output_vertices;
      }, [&] { return stats.topology_checked && !stats.topology_preserved(); },
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::preserve_topology), false));
      return stats;
    }); });
  });
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

computes the primal remesh of `tm` under the range map f: the intersection of the
mapped surface f(`tm`) with a uniform grid of \f$\mathbb{R}^D\f$, into `out`.

Every output vertex is where the mapped surface crosses a grid edge (a
codimension-2 face of the grid); it has valence 4, except the two ends of a merged
digon (valence 3, counted in `Statistics::digons`). Every output face is the piece
of the surface inside one grid cell, so every coordinate of f varies by at most the
cell size over it. Where a part of the surface thinner than a cell crosses a grid
hyperplane, two edges join the same two vertices; a face-list file could not tell
them apart, so one of them is split by a vertex of valence 2 at a point of its arc
(counted in `Statistics::split_parallel_edges`). Positions (and, on request,
normals) of output vertices are sampled from `tm` at the crossing points (those
points of arcs); f is never inverted.

All combinatorial decisions are exact predicates on the mapped input coordinates,
with a symbolic perturbation of the grid for degenerate positions, so the result
is a closed 2-manifold whenever `tm` is one, and does not depend on rounding.

Borders are supported (paper, section 7): where an input border crosses a grid
hyperplane, a boundary vertex of valence 3 is placed on it, and boundary edges join
consecutive ones, so the output has the input's border cycles. A border cycle that
crosses no grid hyperplane (a hole inside one cell) is covered by the face around it
and counted in `Statistics::uncrossed_border_cycles` by the complete scan.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph`, a triangle
        mesh (with or without border).
\tparam PolygonMesh a model of `MutableFaceGraph`.

\param tm the input mesh: 2-manifold, triangles only, with or without border.
\param out receives the remesh, in place of what it held (its property maps are kept).
\param np_in optional named parameters for `tm`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{range_map}
      \cgalParamDescription{the map f: vertex -> point of the range space}
      \cgalParamType{a readable property map with `std::array<double, D>` values, 3 <= D <= 16}
      \cgalParamDefault{`Identity_range_map` of the vertex point map (D = 3)}
      \cgalParamExtra{evaluated lazily, once per input vertex of a visited triangle}
    \cgalParamNEnd
    \cgalParamNBegin{sizing_field}
      \cgalParamDescription{a scale s of f per input vertex: where s is 2 the cells are half as
                            large in f, and the output about twice as fine in each direction.
                            f is replaced by its `Sized_range_map`, whose differential is s df
                            in the least-squares sense; the cell size and the grid origin are
                            in its units}
      \cgalParamType{a readable property map, vertex -> positive finite double, its largest
                     value at most 10^12 times its smallest}
      \cgalParamDefault{none: the scale 1 everywhere}
      \cgalParamExtra{computed after the other parameters are checked and before `out` is
                      touched, by a sparse solve over all the input's vertices (also in the
                      seeded mode), reported to the visitor as the start of the scan}
    \cgalParamNEnd
    \cgalParamNBegin{grid_spacing}
      \cgalParamDescription{the cell size h of the grid, in units of f}
      \cgalParamType{double}
      \cgalParamDefault{`default_relative_cell_size` (1%) of the diagonal of the bounding box of
                        f over the input's vertices (a pass over them, even in the seeded mode)}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_target_vertices}
      \cgalParamDescription{the number of vertices wanted in `out`: the cell size is searched so that
                            the output has this many within 10%, in at most 12 runs (twice
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
    \cgalParamNBegin{grid_origin}
      \cgalParamDescription{a grid vertex}
      \cgalParamType{`std::array<double, D>`}
      \cgalParamDefault{the origin; where f lies more than 2^29 cells from it (a scan in
                        georeferenced coordinates), the grid vertex of that grid at or below the
                        lowest corner of f's bounding box}
    \cgalParamNEnd
    \cgalParamNBegin{seeding_method}
      \cgalParamDescription{`Seeding_method::COMPLETE_SCAN` (finds every piece, linear) or
                            `Seeding_method::SEEDED` (sublinear from given `seed_faces`;
                            without them, the search for one face per connected component
                            is a pass over the whole connectivity, which on a huge input
                            costs more than the complete scan itself)}
      \cgalParamDefault{`Seeding_method::COMPLETE_SCAN`}
    \cgalParamNEnd
    \cgalParamNBegin{seed_faces}
      \cgalParamDescription{faces to start from in seeded mode: at least one in each
                            connected component to be remeshed (a caller remeshing the same
                            connectivity frame after frame finds them once)}
      \cgalParamDefault{one face per connected component}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_number}
      \cgalParamDescription{cap on the number of intersection vertices; `Remeshing_error`
                            is thrown when it would be exceeded, before the output is
                            built if the estimate made from the faces' areas in the range
                            exceeds it}
      \cgalParamDefault{`default_maximum_number_of_vertices` (10,000,000)}
      \cgalParamExtra{memory: about 0.4 KB per vertex for `primal_remesh()`, 1.3 KB for
                      `remesh()`, so the default cap holds a run within about 13 GB}
    \cgalParamNEnd
    \cgalParamNBegin{check_topology}
      \cgalParamDescription{whether to check that the output has the topology of `tm`
                            (complete scan only): fills the topology fields of the
                            returned `Statistics`; see the manual's section on topology}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
      \cgalParamExtra{costs a few percent of the run where the cell size resolves the surface}
    \cgalParamNEnd
    \cgalParamNBegin{refine_around_defects}
      \cgalParamDescription{whether to refine the cells where the check finds defects, at the
                            cell size asked: the run repeats with f magnified twice around each
                            defect (a lens of the range space centred on its cell, on the surface
                            around it), at most 6 times, until the check finds none; the lenses
                            of one round each add to those of the rounds before.
                            `Statistics::local_refinements` and `Statistics::magnified_regions`
                            say what it did}
      \cgalParamType{bool}
      \cgalParamDefault{the value of `preserve_topology`}
      \cgalParamExtra{only with `check_topology`. Each face still lies in one cell of the magnified
                      map, so it spans at most a cell in f where no lens reaches, a cell divided
                      by the magnification in a lens, and up to \f$(4/3)^k\f$ cells radially in
                      the ring where a lens ends (k the rounds). A round whose output has more than
                      twice the intersection vertices of the run without lenses is undone,
                      and the refinement stops there (so many defects call for a smaller cell
                      size: `preserve_topology`); it also stops after two rounds that bring the
                      output no closer to the input's topology (Euler characteristic and
                      components first, then the defects), and the run closest to it is the
                      one returned, so the result is never further from it than without.}
    \cgalParamNEnd
    \cgalParamNBegin{preserve_topology}
      \cgalParamDescription{whether to make sure the output has the topology of `tm`: first by
                            `refine_around_defects` (unless it is set to `false`), and where defects
                            remain, by reducing the whole cell size (by factors of \f$1/\sqrt{2}\f$,
                            without lenses) until the check finds none; the size used is
                            `Statistics::cell_size`}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
      \cgalParamExtra{implies `check_topology`; needs the complete scan. Before each
                      refinement, the smallest part of the input still lost (a lost
                      component, or the pieces the primal dropped) says how small the cells
                      must become, about half its extent in f; a refinement whose output
                      would then pass four times the cap is refused at once, with that
                      extent in the message, rather than after the runs up to the cap.}
    \cgalParamNEnd
    \cgalParamNBegin{topology_visitor}
      \cgalParamDescription{called with each `Topology_defect` the check finds (the cells and
                            input faces concerned)}
      \cgalParamType{a callable taking a `const Topology_defect<face_descriptor>&`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{progress_visitor}
      \cgalParamDescription{told how far the run is and asked whether to go on, as for `remesh()`;
                            on cancellation `out` is left empty}
      \cgalParamType{a callable `bool(Remeshing_stage, double)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_color_map}
      \cgalParamDescription{the input's vertex colours, sampled at the output's vertices into
                            `np_out`'s map}
      \cgalParamType{a readable property map, vertex -> `CGAL::IO::Color` or `std::array<double, 3>`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_texture_map}
      \cgalParamDescription{the input's vertex texture coordinates (UV), sampled at the output's
                            vertices into `np_out`'s map}
      \cgalParamType{a readable property map, vertex -> a CGAL 2-D point or vector, or
                     `std::array<double, 2>`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_attribute_maps}
      \cgalParamDescription{any other vertex properties of the input, sampled at the output's
                            vertices into `np_out`'s maps of the same position}
      \cgalParamType{a readable property map, or a `std::tuple` of them; the values may be
                     numbers, `std::array`s of numbers, `CGAL::IO::Color` or CGAL 2-D and 3-D
                     points and vectors}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{unit normals of the input's vertices, from which the output's normals
                            (`np_out`) are interpolated}
      \cgalParamType{a readable property map, vertex -> `std::array<double, 3>` or a CGAL 3-D vector}
      \cgalParamDefault{area-weighted normals computed by the remesher (`Lazy_vertex_normal_map`'s)}
      \cgalParamExtra{pass the map a normal-based range map reads (see `compute_vertex_normals()`)
                      to save computing the normals twice}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}\cgalParamDefault{`get(CGAL::vertex_point, tm)`}\cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{a model of `RangeSpaceTraits` of dimension D}
      \cgalParamDefault{`Range_space_traits<D>`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}\cgalParamDefault{the mesh's, or one made for the run}\cgalParamNEnd
    \cgalParamNBegin{face_index_map}\cgalParamDefault{the mesh's, or one made for the run}\cgalParamNEnd
  \cgalNamedParamsEnd
\param np_out optional named parameters for `out`: `vertex_point_map`,
  `vertex_normal_map` (a writable map receiving unit normals interpolated from the
  input's vertex normals, those of `np_in` if given; inside a zero-area triangle whose
  corners include copies of one point, as `insert_crease_triangles()` makes, the
  normal of the side with the larger weight, not a blend of both), and
  `vertex_crease_normal_map` (a writable map receiving, at such a vertex, the normal
  of the other side, and the null vector elsewhere; for `dualize()`); and
  `vertex_color_map`, `vertex_texture_map` and `vertex_attribute_maps` (writable maps
  receiving the values of `np_in`'s maps interpolated with the barycentric coordinates of
  each output vertex in the input triangle it lies in; a property is carried only where
  both `np_in` and `np_out` give its map).

\returns what the run did, including per-stage times.
\throws Remeshing_error on an empty mesh, a non-triangle face, a non-finite map value or cell size, a cell size so small that
  the mapped input spans more than 2^29 cells (or lies that far from a given `grid_origin`), or when the output cap would be exceeded (also
  while `preserve_topology` refines the cell size); of kind `TOPOLOGY_NOT_PRESERVED` when
  `preserve_topology` still finds defects after 40 refinements, or where a lost part
  needs cells whose output would pass four times the cap; of kind `BAD_PARAMETER` with
  `preserve_topology` in the seeded mode, if `out` is `tm`, or if `maximum_number` or
  `number_of_target_vertices` is negative or not whole, or the target is above the cap.
  When it throws, `out` is untouched if the named parameters were refused (checked
  before any work), and left empty otherwise: never a partial remesh, nor the last
  cell size a failed target search tried.

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default) or `CGAL::Parallel_tag`
  (needs TBB: link `CGAL::TBB_support`). In parallel, the complete scan maps the
  vertices, records the faces and runs the exact tests on all threads; the result is
  the sequential one, vertex numbering included. The range map's `get()` must then be
  safe to call from several threads at once (all the package's maps are). The seeded
  traversal and the tracing stay sequential.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class PolygonMesh,
          class NamedParametersIn = CGAL::parameters::Default_named_parameters,
          class NamedParametersOut = CGAL::parameters::Default_named_parameters>
Statistics primal_remesh(const TriangleMesh& tm, PolygonMesh& out,
                         const NamedParametersIn& np_in = CGAL::parameters::default_values(),
                         const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  static_assert(internal::check_primal_remesh_parameters<struct primal_remesh_in, NamedParametersIn>());
  static_assert(internal::check_named_parameters<struct primal_remesh_out, NamedParametersOut,
                                                 CGAL::internal_np::vertex_point_t, CGAL::internal_np::vertex_normal_map_t,
                                                 internal_np::vertex_crease_normal_map_t,
                                                 CGAL::internal_np::vertex_color_map_t,
                                                 CGAL::internal_np::vertex_texture_map_t,
                                                 internal_np::vertex_attribute_maps_t>());
  if constexpr(!internal::has_usable_range_map<TriangleMesh, NamedParametersIn>()) {
    internal::refuse_range_map<typename internal::Range_map_of<TriangleMesh, NamedParametersIn>::type>();
    return Statistics();
  } else
    return internal::primal_remesh_impl(tm, out, np_in, np_out, internal::No_inspection(), ConcurrencyTag());
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_PRIMAL_REMESH_H
