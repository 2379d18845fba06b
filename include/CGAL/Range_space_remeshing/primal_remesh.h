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
#include <CGAL/Range_space_remeshing/internal/Progress.h>
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
#include <limits>
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

/*!
\ingroup PkgRangeSpaceRemeshingRef
The cell size used when none is given (named parameters `grid_spacing` and
`number_of_target_vertices` absent), as a fraction of the diagonal of the bounding box of
the mapped input (of f(v) over the input vertices on a face).
*/
constexpr double default_relative_cell_size = 0.01;

namespace internal {

/// The cap on the output's vertices: `maximum_number`, or the default.
template <class NamedParameters>
std::size_t maximum_vertices_of(const NamedParameters& np)
{
  return count_parameter(np, CGAL::internal_np::maximum_number, default_maximum_number_of_vertices, "maximum_number",
                         std::numeric_limits<std::size_t>::max());
}

/// `number_of_target_vertices` (0 if not given), refused above the cap on the output: a
/// count the cap forbids would only be searched for in vain.
template <class NamedParameters>
std::size_t target_vertices_of(const NamedParameters& np)
{
  const std::size_t target = count_parameter(np, internal_np::number_of_target_vertices, 0,
                                             "number_of_target_vertices", std::numeric_limits<std::size_t>::max());
  const std::size_t cap = maximum_vertices_of(np);
  if(target > cap)
    throw Remeshing_error("number_of_target_vertices (" + std::to_string(target) + ") is above maximum_number (" +
                              std::to_string(cap) + "), the cap on the output's vertices",
                          Remeshing_error::Kind::BAD_PARAMETER);
  return target;
}

/// The range map of `np` (`range_map`), or the identity of the vertex point map.
template <class TriangleMesh, class NamedParameters>
struct Range_map_of
{
  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  using Default = Identity_range_map<VPM>;
  using type = typename CGAL::internal_np::Lookup_named_param_def<internal_np::range_map_t, NamedParameters,
                                                                  Default>::type;
};

template <class TriangleMesh, class NamedParameters>
typename Range_map_of<TriangleMesh, NamedParameters>::type range_map_of(const TriangleMesh& tm,
                                                                       const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Default = typename Range_map_of<TriangleMesh, NamedParameters>::Default;
  return choose_parameter(get_parameter(np, internal_np::range_map),
                          Default(choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                   get_const_property_map(CGAL::vertex_point, tm))));
}

// The dimension of a range point type: D for `std::array<double, D>`, 0 for anything else.
template <class Value>
struct Range_point_dimension : std::integral_constant<int, 0>
{};
template <std::size_t D>
struct Range_point_dimension<std::array<double, D>> : std::integral_constant<int, int(D)>
{};

template <class RangeMap>
constexpr int range_dimension()
{
  return Range_point_dimension<std::decay_t<typename boost::property_traits<RangeMap>::value_type>>::value;
}

/// Whether the range map of `NamedParameters` is one the remesher can use: its values
/// `std::array<double, D>`, 3 <= D <= 16. The public functions check it first, with one
/// message, and compile nothing else for a map that is not.
template <class TriangleMesh, class NamedParameters>
constexpr bool has_usable_range_map()
{
  constexpr int D = range_dimension<typename Range_map_of<TriangleMesh, NamedParameters>::type>();
  return D >= minimum_range_dimension && D <= maximum_range_dimension;
}

template <class T>
struct Always_false : std::false_type
{};

/// Refuses, with one message, a range map whose values are not `std::array<double, D>`
/// with 3 <= D <= 16 (the instance of `T`, the map, names it in the compiler's output).
template <class T>
void refuse_range_map()
{
  static_assert(Always_false<T>::value,
                "the range_map's value_type must be std::array<double, D> with 3 <= D <= 16 "
                "(convert a Point_3, a std::array<float, D> or a vector in the map's get())");
}

inline double milliseconds_since(std::chrono::steady_clock::time_point& start)
{
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

/// `default_relative_cell_size` times the diagonal of the bounding box of f over the
/// vertices on a face (an isolated vertex is never mapped by the remesh).
template <class TriangleMesh, class RangeMap>
double default_cell_size(const TriangleMesh& tm, const RangeMap& range_map)
{
  constexpr int D = range_dimension<RangeMap>();
  std::array<double, D> low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for(auto v : vertices(tm)) {
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      continue;
    const auto& x = get(range_map, v);
    for(int q = 0; q < D; ++q) {
      if(!std::isfinite(double(x[q])))
        throw Remeshing_error("the range map gives a NaN or infinite value");
      low[q] = (std::min)(low[q], double(x[q]));
      high[q] = (std::max)(high[q], double(x[q]));
    }
  }
  // the diagonal, scaled by the longest side: the squares of huge or tiny sides would
  // overflow or underflow
  double longest = 0, sum = 0;
  for(int q = 0; q < D; ++q)
    longest = (std::max)(longest, high[q] - low[q]);
  if(!(longest > 0) || !std::isfinite(longest))
    throw Remeshing_error("the mapped input has no extent (a single point, or no face): give a grid_spacing",
                          Remeshing_error::Kind::BAD_INPUT);
  for(int q = 0; q < D; ++q)
    sum += ((high[q] - low[q]) / longest) * ((high[q] - low[q]) / longest);
  return default_relative_cell_size * longest * std::sqrt(sum);
}

// number_of_target_vertices: the counts accepted, and the runs tried at most
constexpr double target_tolerance = 0.1;
constexpr int maximum_target_runs = 12;

/// Whether a run's vertex count is one that `search_cell_size()` accepts for `target`.
inline bool is_near_target(std::size_t count, std::size_t target)
{
  const double n = double((std::max)(count, std::size_t(1)));
  return std::abs(n - double(target)) <= target_tolerance * double(target);
}

/// Searches a cell size, from `h`, whose run gives `target` output vertices within
/// `target_tolerance`: the count goes roughly as h^-2, refined by secant steps in
/// log-log scale. `run(h)` does a run and returns its vertex count; the last run is the
/// one found. A cell size refused as too small is doubled. `keeps_topology`: the runs
/// refine the cell size until the topology is kept (said if the count stays above).
template <class Run>
double search_cell_size(double h, std::size_t target, const Run& run, bool keeps_topology)
{
  double previous_h = 0, previous_log_n = 0, n = 0;
  const double log_target = std::log(double(target));
  for(int attempt = 0; attempt < maximum_target_runs; ++attempt) {
    try {
      n = double((std::max)(run(h), std::size_t(1)));
    } catch(const Remeshing_error& error) {
      if(error.kind() != Remeshing_error::Kind::OUTPUT_TOO_LARGE)
        throw;
      previous_h = 0;
      h *= 2;
      continue;
    }
    if(is_near_target(std::size_t(n), target))
      return h;
    double slope = -2; // d log n / d log h
    if(previous_h > 0) {
      const double s = (std::log(n) - previous_log_n) / (std::log(h) - std::log(previous_h));
      if(std::isfinite(s) && s < -0.5 && s > -4)
        slope = s;
    }
    previous_h = h;
    previous_log_n = std::log(n);
    h = std::exp(std::log(h) + (log_target - std::log(n)) / slope);
  }
  const bool kept_finer = keeps_topology && n > double(target);
  throw Remeshing_error("no cell size tried gives " + std::to_string(target) + " output vertices within " +
                            std::to_string(int(100 * target_tolerance)) + "% (the last gave " +
                            std::to_string(std::size_t(n)) + ")" +
                            (kept_finer ? "; keeping the input's topology (preserve_topology) needs smaller "
                                          "cells than that count: ask for more vertices, or allow the topology "
                                          "to change"
                                        : ""),
                        Remeshing_error::Kind::TARGET_NOT_REACHED);
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

// What a run reads of `np_in` besides the maps, checked.
struct Primal_run_options
{
  bool seeded, preserve, check;
  std::size_t maximum_vertices;
};

template <class NamedParametersIn>
Primal_run_options primal_run_options(const NamedParametersIn& np_in)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Primal_run_options options;
  options.seeded = choose_parameter(get_parameter(np_in, CGAL::internal_np::seeding_method),
                                    Seeding_method::COMPLETE_SCAN) == Seeding_method::SEEDED;
  options.preserve = choose_parameter(get_parameter(np_in, internal_np::preserve_topology), false);
  options.check = options.preserve || choose_parameter(get_parameter(np_in, internal_np::check_topology), false);
  options.maximum_vertices = maximum_vertices_of(np_in);
  if(options.preserve && options.seeded)
    throw Remeshing_error("preserve_topology needs the complete scan (Seeding_method::COMPLETE_SCAN)",
                          Remeshing_error::Kind::BAD_PARAMETER);
  return options;
}

template <class Point_d>
void check_grid(double cell_size, const Point_d& origin)
{
  if(!(cell_size > 0) || !std::isfinite(cell_size))
    throw Remeshing_error("the cell size must be a positive finite number", Remeshing_error::Kind::BAD_PARAMETER);
  for(double x : origin)
    if(!std::isfinite(x))
      throw Remeshing_error("the grid origin must be finite", Remeshing_error::Kind::BAD_PARAMETER);
}

// The error of a refined run (past the first), for which the refinement could not
// finish; an error of the first run, or a cancel, is rethrown as it is.
inline Remeshing_error refinement_failure(const Remeshing_error& error, std::size_t refinements, double h)
{
  return Remeshing_error("preserve_topology could not reach a cell size without topology defects (" +
                             std::to_string(refinements) + " refinements, to cell size " + std::to_string(h) +
                             "): " + error.what(),
                         Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED);
}

// The whole run at cell size `cell_size`, on a mesh with faces (the callers check);
// `inspect(tracer, complex)` sees the intermediate structures before the output is
// written (tests check the invariants there).
template <class TriangleMesh, class PolygonMesh, class NamedParametersIn, class NamedParametersOut,
          class Inspector, class ConcurrencyTag>
Statistics primal_remesh_at(double cell_size, const TriangleMesh& tm, PolygonMesh& out,
                            const NamedParametersIn& np_in, const NamedParametersOut& np_out,
                            const Inspector& inspect, const Progress& progress, ConcurrencyTag)
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
  using Range_map = typename Range_map_of<TriangleMesh, NamedParametersIn>::type;
  const Range_map range_map = range_map_of(tm, np_in);
  constexpr int D = range_dimension<Range_map>();
  using Default_traits = Range_space_traits<D>;
  using Traits = typename CGAL::internal_np::Lookup_named_param_def<
      CGAL::internal_np::geom_traits_t, NamedParametersIn, Default_traits>::type;
  static_assert(Traits::dimension == D,
                "the traits' dimension differs from the range map's dimension");
  const Traits traits = choose_parameter<Traits>(get_parameter(np_in, CGAL::internal_np::geom_traits));
  using Point_d = typename Traits::Point_d;

  const Point_d origin = choose_parameter(get_parameter(np_in, internal_np::grid_origin), Point_d{});
  check_grid(cell_size, origin);
  const Primal_run_options options = primal_run_options(np_in);
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
      Tracer tracer(tm, range_map, face_index, vertex_index, origin, h, options.maximum_vertices, traits);
      tracer.set_progress(progress);
      Statistics stats;
      stats.cell_size = h;
      stats.topology_refinements = refinements;
      const std::unique_ptr<Primal_complex> complex =
          trace_primal_complex(tm, tracer, np_in, options.seeded, options.check, std::integral_constant<bool, parallel>(),
                               stats, start);

      std::vector<Topology_defect<face_descriptor>> defects;
      if(options.check && !options.seeded) {
        defects = Topology_check<Tracer, face_descriptor>(tracer, *complex).run(stats, progress);
        stats.time_topology_ms = milliseconds_since(start);
      }
      if(options.preserve && !stats.topology_preserved()) {
        if(refinements == maximum_topology_refinements)
          throw Remeshing_error("defects remain at every cell size tried",
                                Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED);
        h *= topology_refinement_factor;
        continue;
      }
      for(const auto& defect : defects)
        visitor(defect);
      inspect(tracer, *complex);

      progress.report(Remeshing_stage::PRIMAL_OUTPUT, 0);
      write_primal_complex(tm, vpm, vertex_index, tracer, *complex, out, np_in, np_out, stats);
      progress.report(Remeshing_stage::PRIMAL_OUTPUT, 1);
      stats.time_output_ms = milliseconds_since(start);
      stats.time_total_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_total).count();
      return stats;
    } catch(const Remeshing_error& error) {
      if(refinements == 0 || error.kind() == Remeshing_error::Kind::CANCELLED)
        throw; // as it is: a Remeshing_cancelled stays one
      throw refinement_failure(error, refinements, h);
    }
  }
}

/// `check_named_parameters()` with the parameters `primal_remesh()` reads for its
/// input, and `More...`.
template <class Function, class NamedParameters, class... More>
constexpr bool check_primal_remesh_parameters()
{
  namespace np = internal_np;
  namespace cgal_np = CGAL::internal_np;
  return check_named_parameters<Function, NamedParameters, np::range_map_t, cgal_np::grid_spacing_t,
                                np::number_of_target_vertices_t, np::grid_origin_t, cgal_np::seeding_method_t,
                                np::seed_faces_t, cgal_np::maximum_number_t, np::check_topology_t,
                                np::preserve_topology_t, np::topology_visitor_t, np::progress_visitor_t,
                                cgal_np::vertex_normal_map_t, cgal_np::vertex_color_map_t, cgal_np::vertex_texture_map_t,
                                np::vertex_attribute_maps_t, cgal_np::vertex_point_t,
                                cgal_np::geom_traits_t, cgal_np::vertex_index_t, cgal_np::face_index_t, More...>();
}

/// The cell size of `np`: `grid_spacing`, or the default relative to the mapped input.
template <class TriangleMesh, class NamedParameters>
double cell_size_of(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::grid_spacing_t>::value)
    return default_cell_size(tm, range_map_of(tm, np));
  else
    return double(get_parameter(np, CGAL::internal_np::grid_spacing));
}

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
  remove_all_elements(out);
  return emptied_on_cancel(out, [&] {
    const double h = cell_size_of(tm, np_in);
    if(target == 0)
      return primal_remesh_at(h, tm, out, np_in, np_out, inspect, progress, tag);
    Statistics stats;
    search_cell_size(h, target, [&](double h_try) {
      remove_all_elements(out);
      stats = primal_remesh_at(h_try, tm, out, np_in, np_out, inspect, progress, tag);
      return stats.output_vertices;
    }, CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_in, internal_np::preserve_topology), false));
    return stats;
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
\param out receives the remesh, in place of what it held (its property maps are kept).
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
      \cgalParamDefault{`default_relative_cell_size` (1%) of the diagonal of the bounding box of
                        f over the input's vertices (a pass over them, even in the seeded mode)}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_target_vertices}
      \cgalParamDescription{the number of vertices wanted in `out`: the cell size is searched (from
                            `grid_spacing` or its default) so that the output has this many within 10%,
                            in at most 12 runs}
      \cgalParamType{std::size_t}
      \cgalParamDefault{none: the cell size is used as given}
      \cgalParamExtra{`Remeshing_error` of kind `TARGET_NOT_REACHED` if no cell size tried gives the count}
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
  range coordinates exceed 2^29 cells, or when the output cap would be exceeded (also
  while `preserve_topology` refines the cell size), or with `preserve_topology` in the
  seeded mode; of kind `BAD_PARAMETER` if `out` is `tm`, or if `maximum_number` or
  `number_of_target_vertices` is negative or not whole, or the target is above the cap.

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
