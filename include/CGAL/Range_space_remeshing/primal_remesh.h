// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_PRIMAL_REMESH_H
#define CGAL_RANGE_SPACE_REMESHING_PRIMAL_REMESH_H

#include <CGAL/Range_space_remeshing/Identity_range_map.h>
#include <CGAL/Range_space_remeshing/Range_space_traits.h>
#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Grid_tracer.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>
#include <CGAL/Range_space_remeshing/internal/Primal_output.h>
#include <CGAL/Range_space_remeshing/internal/Topology_check.h>
#include <CGAL/Range_space_remeshing/Topology_defect.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef
The default cap on the intersection vertices of a remesh (named parameter
`maximum_number`). A cell size far too small for the input is refused with a
`Remeshing_error` rather than exhausting the memory: at about 1.3 KB per vertex for the
whole pipeline (`remesh()`, measured on CGAL's refined_elephant), this cap keeps a run
within about 13 GB.
*/
constexpr std::size_t default_maximum_number_of_vertices = 10000000;

namespace internal {

template <class RangeMap>
constexpr int range_dimension()
{
  using Value = std::decay_t<typename boost::property_traits<RangeMap>::value_type>;
  return int(std::tuple_size<Value>::value);
}

inline double milliseconds_since(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

/// One seed face per connected component of the input (connectivity only: the map
/// is not evaluated here).
template <class TriangleMesh, class FaceIndexMap>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
one_face_per_component(const TriangleMesh& tm, FaceIndexMap face_index)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::vector<face_descriptor> seeds, stack;
  std::vector<std::uint8_t> seen(num_faces(tm), 0);
  for(face_descriptor f : faces(tm)) {
    if(seen[get(face_index, f)])
      continue;
    seeds.push_back(f);
    seen[get(face_index, f)] = 1;
    stack.push_back(f);
    while(!stack.empty()) {
      const face_descriptor g = stack.back();
      stack.pop_back();
      // three steps, not a circulation: on a broken structure a circulation may not end
      const auto h0 = halfedge(g, tm), h1 = next(h0, tm), h2 = next(h1, tm);
      if(next(h2, tm) != h0)
        throw Remeshing_error("the input has a face that is not a triangle, or a broken halfedge structure (face " +
                              std::to_string(get(face_index, g)) + ")");
      for(auto h : {h0, h1, h2}) {
        const auto o = opposite(h, tm);
        if(is_border(o, tm))
          continue;
        const face_descriptor n = face(o, tm);
        if(!seen[get(face_index, n)]) {
          seen[get(face_index, n)] = 1;
          stack.push_back(n);
        }
      }
    }
  }
  return seeds;
}

} // namespace internal

namespace internal {

struct No_inspection
{
  template <class Tracer, class Complex>
  void operator()(Tracer&, const Complex&) const {}
};

struct No_topology_visitor
{
  template <class Defect>
  void operator()(const Defect&) const {}
};

// preserve_topology: the cell size shrinks by this factor until the check passes,
// at most this many times (a factor of 2^-20 in all)
constexpr double topology_refinement_factor = 0.70710678118654752;
constexpr std::size_t maximum_topology_refinements = 40;

/// Scans (or seeds) and traces with `tracer`, and builds the faces: the run up to
/// the output, with its statistics. `count_pieces` prepares the closed-loop check.
template <class TriangleMesh, class Tracer, class NamedParametersIn, bool parallel>
std::unique_ptr<Primal_complex> trace_primal_complex(const TriangleMesh& tm, Tracer& tracer,
                                                     const NamedParametersIn& np_in, bool seeded,
                                                     bool count_pieces, std::integral_constant<bool, parallel>,
                                                     Statistics& stats,
                                                     std::chrono::steady_clock::time_point& start)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  stats.input_vertices = num_vertices(tm);
  stats.input_faces = num_faces(tm);
  if(!seeded) {
    if(count_pieces)
      tracer.count_untraced_pieces();
#if defined(CGAL_LINKED_WITH_TBB)
    if constexpr(parallel) {
      tracer.map_and_record_in_parallel();
      tracer.refuse_too_large_output();
      tracer.scan_in_parallel();
    } else
#endif
    {
      tracer.map_all_vertices();
      tracer.scan_all_faces(); // refuses too large outputs; checks every face is a triangle
    }
    stats.seeds = tracer.intersection_vertices().size();
    if(tracer.has_seen_border())
      stats.uncrossed_border_cycles = tracer.number_of_uncrossed_border_cycles();
  } else {
    // not choose_parameter(): its default argument, a pass over the whole mesh, would be
    // evaluated even when the user gives the seeds
    if constexpr(is_default_parameter<NamedParametersIn, internal_np::seed_faces_t>::value) {
      for(auto f : one_face_per_component(tm, tracer.face_index_map()))
        stats.seeds += tracer.seed_from(f) ? 1 : 0;
    } else {
      for(auto f : get_parameter(np_in, internal_np::seed_faces))
        stats.seeds += tracer.seed_from(f) ? 1 : 0;
    }
    stats.uncrossed_border_cycles = tracer.number_of_border_cycles_of_empty_components();
  }
  stats.time_seeding_ms = milliseconds_since(start);

  tracer.trace(/*create vertices at arc ends*/ seeded);
  stats.time_tracing_ms = milliseconds_since(start);

  const auto& vertices = tracer.intersection_vertices();
  std::vector<std::uint32_t> links(4 * vertices.size());
  std::vector<bool> positive(vertices.size()), boundary(vertices.size());
  for(std::size_t v = 0; v < vertices.size(); ++v) {
    std::copy(vertices[v].link.begin(), vertices[v].link.end(), links.begin() + 4 * v);
    positive[v] = vertices[v].orientation > 0;
    boundary[v] = vertices[v].is_boundary();
  }
  auto complex = std::make_unique<Primal_complex>(std::move(links), positive, boundary);
  stats.time_faces_ms = milliseconds_since(start);

  stats.mapped_vertices = tracer.number_of_mapped_vertices();
  stats.visited_faces = tracer.number_of_visited_faces();
  stats.tracing_steps = tracer.number_of_tracing_steps();
  stats.intersection_vertices = vertices.size();
  stats.digons = complex->number_of_digons();
  stats.boundary_digons = complex->number_of_boundary_digons();
  stats.boundary_corners = tracer.number_of_corners();
  stats.non_simple_faces = complex->number_of_non_simple_faces();
  stats.dropped_pieces = complex->number_of_dropped_pieces();
  return complex;
}

// The whole run; `inspect(tracer, complex)` sees the intermediate structures
// before the output is written (tests check the invariants there).
template <class TriangleMesh, class PolygonMesh, class NamedParametersIn,
          class NamedParametersOut, class Inspector, class ConcurrencyTag = CGAL::Sequential_tag>
Statistics primal_remesh_impl(const TriangleMesh& tm, PolygonMesh& out,
                              const NamedParametersIn& np_in,
                              const NamedParametersOut& np_out, const Inspector& inspect,
                              ConcurrencyTag = ConcurrencyTag())
{
#if !defined(CGAL_LINKED_WITH_TBB)
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
  constexpr bool parallel = false;
#else
  constexpr bool parallel = std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#endif
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  auto start = std::chrono::steady_clock::now();
  const auto start_total = start;

  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParametersIn>::const_type;
  const VPM vpm = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  using Default_map = Identity_range_map<VPM>;
  using Range_map = typename CGAL::internal_np::Lookup_named_param_def<
      internal_np::range_map_t, NamedParametersIn, Default_map>::type;
  const Range_map range_map =
      choose_parameter(get_parameter(np_in, internal_np::range_map), Default_map(vpm));
  constexpr int D = range_dimension<Range_map>();
  using Default_traits = Range_space_traits<D>;
  using Traits = typename CGAL::internal_np::Lookup_named_param_def<
      CGAL::internal_np::geom_traits_t, NamedParametersIn, Default_traits>::type;
  static_assert(Traits::dimension == D,
                "the traits' dimension differs from the range map's dimension");
  const Traits traits = choose_parameter<Traits>(get_parameter(np_in, CGAL::internal_np::geom_traits));
  using Point_d = typename Traits::Point_d;

  const double cell_size = choose_parameter(get_parameter(np_in, CGAL::internal_np::grid_spacing), 1.);
  const Point_d origin = choose_parameter(get_parameter(np_in, internal_np::grid_origin), Point_d{});
  const Seeding_method seeding = choose_parameter(
      get_parameter(np_in, CGAL::internal_np::seeding_method), Seeding_method::COMPLETE_SCAN);
  const std::size_t maximum_vertices = std::size_t(choose_parameter(
      get_parameter(np_in, CGAL::internal_np::maximum_number), default_maximum_number_of_vertices));

  if(!(cell_size > 0) || !std::isfinite(cell_size))
    throw Remeshing_error("the cell size must be a positive finite number");
  for(double x : origin)
    if(!std::isfinite(x))
      throw Remeshing_error("the grid origin must be finite");
  if(num_faces(tm) == 0)
    throw Remeshing_error("the input mesh has no face");

  const bool preserve = choose_parameter(get_parameter(np_in, internal_np::preserve_topology), false);
  const bool check = preserve || choose_parameter(get_parameter(np_in, internal_np::check_topology), false);
  const bool seeded = (seeding == Seeding_method::SEEDED);
  if(preserve && seeded)
    throw Remeshing_error("preserve_topology needs the complete scan (Seeding_method::COMPLETE_SCAN)");
  const auto visitor =
      choose_parameter(get_parameter(np_in, internal_np::topology_visitor), No_topology_visitor());

  auto face_index = CGAL::get_initialized_face_index_map(tm, np_in);
  auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np_in);
  using Tracer = Grid_tracer<TriangleMesh, Range_map, decltype(face_index),
                                       decltype(vertex_index), Traits>;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  double h = cell_size;
  for(std::size_t refinements = 0;; ++refinements) {
    start = std::chrono::steady_clock::now();
    try {
      Tracer tracer(tm, range_map, face_index, vertex_index, origin, h, maximum_vertices, traits);
      Statistics stats;
      stats.cell_size = h;
      stats.topology_refinements = refinements;
      const std::unique_ptr<Primal_complex> complex =
          trace_primal_complex(tm, tracer, np_in, seeded, check, std::integral_constant<bool, parallel>(),
                               stats, start);

      std::vector<Topology_defect<face_descriptor>> defects;
      if(check && !seeded) {
        defects = Topology_check<Tracer, face_descriptor>(tracer, *complex).run(stats);
        stats.time_topology_ms = milliseconds_since(start);
      }
      if(preserve && !stats.topology_preserved()) {
        if(refinements == maximum_topology_refinements)
          throw Remeshing_error("defects remain at every cell size tried");
        h *= topology_refinement_factor;
        continue;
      }
      for(const auto& defect : defects)
        visitor(defect);
      inspect(tracer, *complex);

      write_primal_complex(tm, vpm, vertex_index, tracer, *complex, out, np_in, np_out, stats);
      stats.time_output_ms = milliseconds_since(start);
      stats.time_total_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_total).count();
      return stats;
    } catch(const Remeshing_error& error) {
      if(refinements == 0)
        throw;
      throw Remeshing_error("preserve_topology could not reach a cell size without topology defects (" +
                            std::to_string(refinements) + " refinements, to cell size " + std::to_string(h) +
                            "): " + error.what());
    }
  }
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

computes the primal remesh of `tm` under the range map f: the intersection of the
mapped surface f(`tm`) with a uniform grid of \f$\mathbb{R}^D\f$, and appends it to
`out`.

Every output vertex is where the mapped surface crosses a grid edge (a
codimension-2 face of the grid); it has valence 4, except the two ends of a merged
digon (valence 3, counted in `Statistics::digons`). Every output face is the piece
of the surface inside one grid cell, so every coordinate of f varies by at most the
cell size over it. Positions (and, on request, normals) of output vertices are
sampled from `tm` at the crossing points; f is never inverted.

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
\param out receives the remesh (appended).
\param np_in optional named parameters for `tm`:
  \cgalNamedParamsBegin
    \cgalParamNBegin{range_map}
      \cgalParamDescription{the map f: vertex -> point of the range space}
      \cgalParamType{a readable property map with `std::array<double, D>` values, 3 <= D <= 16}
      \cgalParamDefault{`Identity_range_map` of the vertex point map (D = 3)}
      \cgalParamExtra{evaluated lazily, once per input vertex of a visited triangle}
    \cgalParamNEnd
    \cgalParamNBegin{grid_spacing}
      \cgalParamDescription{the cell size h of the grid, in units of f}
      \cgalParamType{double}
      \cgalParamDefault{1}
    \cgalParamNEnd
    \cgalParamNBegin{grid_origin}
      \cgalParamDescription{a grid vertex}
      \cgalParamType{`std::array<double, D>`}
      \cgalParamDefault{the origin}
    \cgalParamNEnd
    \cgalParamNBegin{seeding_method}
      \cgalParamDescription{`Seeding_method::COMPLETE_SCAN` (finds every piece, linear) or
                            `Seeding_method::SEEDED` (sublinear from given `seed_faces`;
                            without them, the search for one face per connected component
                            is a pass over the whole connectivity, which on a huge input
                            costs more than the complete scan: 760 against 430 ms on
                            5.7 million triangles, 260 ms from given seeds)}
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
    \cgalParamNBegin{preserve_topology}
      \cgalParamDescription{whether to reduce the cell size (by factors of \f$1/\sqrt{2}\f$)
                            until the check finds no defect; the size used is
                            `Statistics::cell_size`}
      \cgalParamType{bool}
      \cgalParamDefault{`false`}
      \cgalParamExtra{implies `check_topology`; needs the complete scan}
    \cgalParamNEnd
    \cgalParamNBegin{topology_visitor}
      \cgalParamDescription{called with each `Topology_defect` the check finds (the cells and
                            input faces concerned)}
      \cgalParamType{a callable taking a `const Topology_defect<face_descriptor>&`}
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
  \cgalNamedParamsEnd
\param np_out optional named parameters for `out`: `vertex_point_map`,
  `vertex_normal_map` (a writable map receiving unit normals interpolated from the
  input's vertex normals, those of `np_in` if given; inside a zero-area triangle whose
  corners include copies of one point, as `insert_crease_triangles()` makes, the
  normal of the side with the larger weight, not a blend of both), and
  `vertex_crease_normal_map` (a writable map receiving, at such a vertex, the normal
  of the other side, and the null vector elsewhere; for `dualize()`).

\returns what the run did, including per-stage times.
\throws Remeshing_error on an empty mesh, a non-triangle face, a non-finite map value or cell size, a cell size so small that
  range coordinates exceed 2^29 cells, or when the output cap would be exceeded (also
  while `preserve_topology` refines the cell size), or with `preserve_topology` in the
  seeded mode.

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
  return internal::primal_remesh_impl(tm, out, np_in, np_out, internal::No_inspection(), ConcurrencyTag());
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_PRIMAL_REMESH_H
