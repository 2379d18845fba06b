// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_RUN_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_RUN_H

// One run of the primal remesh at a given cell size, in the order of the paper: the
// complete scan or the seeded traversal and the tracing of the arcs (section 4), the
// faces of the complex (section 5), the topology check (section 8; for
// `preserve_topology`, the cell size is refined until it passes), then the output.

#include <CGAL/Range_space_remeshing/Range_space_traits.h>
#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Topology_defect.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Cell_size.h>
#include <CGAL/Range_space_remeshing/internal/Grid_tracer.h>
#include <CGAL/Range_space_remeshing/internal/Local_magnification.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>
#include <CGAL/Range_space_remeshing/internal/Primal_output.h>
#include <CGAL/Range_space_remeshing/internal/Primal_parameters.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Topology_check.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The milliseconds since `start`, which moves to now: each stage is timed in turn.
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
  stats.parallel_edges = complex->number_of_parallel_edges();
  return complex;
}

// The error of a refined run (past the first), for which the refinement could not
// finish; an error of the first run, a cancel or check_refinement()'s refusal is rethrown as it is.
inline Remeshing_error refinement_failure(const Remeshing_error& error, std::size_t refinements, double h)
{
  return Remeshing_error("preserve_topology could not reach a cell size without topology defects (" +
                             std::to_string(refinements) + " refinements, to cell size " + std::to_string(h) +
                             "): " + error.what(),
                         Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED);
}

/// How far a checked run is from the input's topology, what the refinement around
/// defects must lower: first the differences in Euler characteristic and components,
/// then the defects the check counted and the pieces the complex dropped.
inline std::size_t topology_distance(const Statistics& stats)
{
  const std::size_t differences =
      std::size_t(std::abs(stats.output_euler_characteristic - stats.input_euler_characteristic)) +
      std::size_t(std::abs(long(stats.output_components) - long(stats.input_components)));
  const std::size_t defects = stats.closed_loops + stats.non_disk_cells + stats.lost_components +
                              stats.uncrossed_border_cycles + stats.dropped_pieces;
  return differences * (std::size_t(1) << 32) + (std::min)(defects, (std::size_t(1) << 32) - 1);
}

/// Ends a run that failed with `error`, the exception being handled: a cancel after
/// refinements says how far they got, an error of a refined run says it is one.
[[noreturn]] inline void rethrow_run_error(const Remeshing_error& error, std::size_t refinements,
                                           double finest_with_defects, double h)
{
  if(refinements > 0 && error.kind() == Remeshing_error::Kind::CANCELLED)
    throw Remeshing_cancelled(refinements, finest_with_defects); // what the refinement reached
  if(refinements == 0 || error.kind() == Remeshing_error::Kind::CANCELLED ||
     error.kind() == Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED)
    throw; // as it is: a Remeshing_cancelled stays one, check_refinement()'s says the refinements
  throw refinement_failure(error, refinements, h);
}

/// The extent in f (the longest side of the bounding box of their vertices' values)
/// of input faces; zero if there are none.
template <class TriangleMesh, class RangeMap, class FaceRange>
double extent_of_faces(const TriangleMesh& tm, const RangeMap& range_map, const FaceRange& faces)
{
  constexpr int D = range_dimension<RangeMap>();
  const auto box = mapped_box_of<D>(range_map, corners_of_faces(tm, faces));
  double extent = 0;
  for(int q = 0; q < D; ++q)
    extent = (std::max)(extent, box[1][q] - box[0][q]);
  return extent;
}

/// The extent in f of the smallest part of the input the run lost: a lost component,
/// or the pieces the complex dropped (their input faces together: an overestimate
/// where several pieces were dropped); infinity if it lost none.
template <class TriangleMesh, class RangeMap, class Tracer, class FaceDescriptor>
double smallest_lost_part(const TriangleMesh& tm, const RangeMap& range_map, Tracer& tracer,
                          const Primal_complex& complex, const std::vector<Topology_defect<FaceDescriptor>>& defects)
{
  double smallest = std::numeric_limits<double>::infinity();
  for(const auto& defect : defects)
    if(defect.kind == Topology_defect_kind::LOST_COMPONENT)
      smallest = (std::min)(smallest, extent_of_faces(tm, range_map, defect.input_faces));
  if(complex.number_of_dropped_pieces() > 0) {
    std::vector<FaceDescriptor> dropped;
    const auto& vertices = tracer.intersection_vertices();
    for(std::uint32_t v = 0; v < vertices.size(); ++v)
      if(!complex.is_kept(v))
        dropped.push_back(tracer.input().face_of_id(vertices[v].face_id));
    smallest = (std::min)(smallest, extent_of_faces(tm, range_map, dropped));
  }
  return smallest;
}

/// Whether the lost parts of a run can be kept by the local refinement: a part of
/// extent e in f needs cells of about e / 2, and the lenses reach h / 2^rounds at most.
template <class TriangleMesh, class RangeMap, class Tracer, class FaceDescriptor>
bool may_be_kept_locally(const TriangleMesh& tm, const RangeMap& range_map, Tracer& tracer,
                         const Primal_complex& complex, const std::vector<Topology_defect<FaceDescriptor>>& defects,
                         double h)
{
  const double needed = smallest_lost_part(tm, range_map, tracer, complex, defects) / 2;
  return !(needed * std::pow(2., maximum_local_refinements) < h);
}

/// With preserve_topology, before the run at a finer cell size than h: refuses at once
/// a refinement that cannot end below the output cap, rather than after the runs that
/// reach it (each about twice the last). A lost component of extent e in f is kept
/// only by cells smaller than about e / 2, and the output grows as h^-2: refused where
/// that predicts more than four times the cap. Also refuses the refinement past the last.
template <class TriangleMesh, class RangeMap, class Tracer, class FaceDescriptor>
void check_refinement(const TriangleMesh& tm, const RangeMap& range_map, Tracer& tracer, const Primal_complex& complex,
                      const std::vector<Topology_defect<FaceDescriptor>>& defects, const Statistics& stats,
                      double h, std::size_t refinements, std::size_t cap)
{
  std::ostringstream message;
  message << std::setprecision(3) << "preserve_topology: at cell size " << h << " (" << refinements
          << " refinements) ";
  if(refinements == maximum_topology_refinements) {
    message << "defects remain, and that was the last refinement";
    throw Remeshing_error(message.str(), Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED);
  }
  const double needed = smallest_lost_part(tm, range_map, tracer, complex, defects) / 2;
  if(!(needed < h))
    return;
  const double predicted = double((std::max)(stats.intersection_vertices, std::size_t(1))) * (h / needed) * (h / needed);
  if(predicted > 4 * double(cap)) {
    message << "a part of the input " << 2 * needed << " across (in units of f) is lost; keeping it needs cells of "
            << "about " << needed << ", about " << predicted << " output vertices, above the cap of " << cap;
    throw Remeshing_error(message.str(), Remeshing_error::Kind::TOPOLOGY_NOT_PRESERVED);
  }
}

/// Where to magnify the map after a run with defects: the centre of each defect's
/// cell in the range space (on the grid face of a closed loop) and its input faces,
/// and the input face of each intersection vertex of the pieces the complex dropped.
template <class Tracer, class FaceDescriptor, class Point_d>
std::vector<std::pair<std::vector<double>, std::vector<FaceDescriptor>>>
defect_regions(Tracer& tracer, const Primal_complex& complex,
               const std::vector<Topology_defect<FaceDescriptor>>& defects, const Point_d& origin, double h)
{
  std::vector<std::pair<std::vector<double>, std::vector<FaceDescriptor>>> regions;
  for(const auto& defect : defects) {
    std::vector<double> centre;
    for(std::size_t q = 0; q < defect.cell.size(); ++q)
      centre.push_back(origin[int(q)] + (double(defect.cell[q]) + (int(q) == defect.axis ? 0 : 0.5)) * h);
    regions.emplace_back(std::move(centre), defect.input_faces);
  }
  const auto& vertices = tracer.intersection_vertices();
  for(std::uint32_t v = 0; v < vertices.size(); ++v)
    if(!complex.is_kept(v))
      regions.emplace_back(std::vector<double>(),
                           std::vector<FaceDescriptor>{tracer.input().face_of_id(vertices[v].face_id)});
  return regions;
}

/// Whether `ConcurrencyTag` asks for the parallel scan (refused without TBB).
template <class ConcurrencyTag>
constexpr bool runs_in_parallel()
{
#if !defined(CGAL_LINKED_WITH_TBB)
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
  return false;
#else
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#endif
}

/// The topology check of a complete scan, timed: the defects it finds (none checked
/// in the seeded mode, which does not see every piece of the output).
template <class face_descriptor, class Tracer>
std::vector<Topology_defect<face_descriptor>> check_topology_of(Tracer& tracer, const Primal_complex& complex,
                                                                const Primal_run_options& options, Statistics& stats,
                                                                const Progress& progress,
                                                                std::chrono::steady_clock::time_point& start)
{
  std::vector<Topology_defect<face_descriptor>> defects;
  if(options.check && !options.seeded) {
    defects = Topology_check<Tracer, face_descriptor>(tracer, complex).run(stats, progress);
    stats.time_topology_ms = milliseconds_since(start);
  }
  return defects;
}

// The whole run at cell size `cell_size`, on a mesh with faces (the callers check);
// `inspect(tracer, complex)` sees the intermediate structures before the output is
// written (tests check the invariants there).
template <class TriangleMesh, class PolygonMesh, class NamedParametersIn, class NamedParametersOut,
          class Inspector, class ConcurrencyTag>
Statistics primal_remesh_at(double cell_size, const TriangleMesh& tm, PolygonMesh& out,
                            const NamedParametersIn& np_in, const NamedParametersOut& np_out,
                            const Inspector& inspect, const Progress& progress, ConcurrencyTag,
                            Parallel_edges parallel_edges = Parallel_edges::SPLIT, bool refine_around_defects = true)
{
  constexpr bool parallel = runs_in_parallel<ConcurrencyTag>();
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  auto start = std::chrono::steady_clock::now();
  const auto start_total = start;

  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParametersIn>::const_type;
  const VPM vpm = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  using Range_map = typename Range_map_of<TriangleMesh, NamedParametersIn>::type;
  const Range_map range_map = range_map_of(tm, np_in);
  using Traits = typename Primal_traits_of<TriangleMesh, NamedParametersIn>::type;
  const Traits traits = choose_parameter<Traits>(get_parameter(np_in, CGAL::internal_np::geom_traits));
  using Point_d = typename Traits::Point_d;

  Point_d origin = choose_parameter(get_parameter(np_in, internal_np::grid_origin), Point_d{});
  check_grid(cell_size, origin);
  bool may_move_origin = CGAL::parameters::is_default_parameter<NamedParametersIn, internal_np::grid_origin_t>::value;
  Primal_run_options options = primal_run_options(np_in);
  options.refine_locally = options.refine_locally && refine_around_defects; // off in a target search's trials
  const auto visitor =
      choose_parameter(get_parameter(np_in, internal_np::topology_visitor), No_topology_visitor());

  auto face_index = CGAL::get_initialized_face_index_map(tm, np_in);
  auto vertex_index = CGAL::get_initialized_vertex_index_map(tm, np_in);
  using Magnification = Local_magnification<TriangleMesh, Range_map, decltype(vertex_index), Traits::dimension>;
  Magnification magnification(tm, range_map, vertex_index);
  using Tracer = Grid_tracer<TriangleMesh, typename Magnification::Map, decltype(face_index),
                                       decltype(vertex_index), Traits>;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  double h = cell_size;
  double finest_with_defects = 0; // with preserve_topology: the last run refined
  for(std::size_t refinements = 0;;) {
    start = std::chrono::steady_clock::now();
    try {
      Tracer tracer(tm, magnification.map(), face_index, vertex_index, origin, h,
                    magnification.cap(options.maximum_vertices), traits);
      tracer.set_progress(progress);
      Statistics stats;
      stats.cell_size = h;
      stats.topology_refinements = refinements;
      const std::unique_ptr<Primal_complex> complex =
          trace_primal_complex(tm, tracer, np_in, options.seeded, options.check, std::integral_constant<bool, parallel>(),
                               stats, start);

      const std::vector<Topology_defect<face_descriptor>> defects =
          check_topology_of<face_descriptor>(tracer, *complex, options, stats, progress, start);
      if(magnification.undo_if_over_budget(stats.intersection_vertices, topology_distance(stats)))
        continue; // the run before the last round, kept
      magnification.report(stats);
      if(options.refine_locally && refinements == 0 && stats.topology_checked && !stats.topology_preserved() &&
         may_be_kept_locally(tm, range_map, tracer, *complex, defects, h) &&
         magnification.magnify_around(defect_regions(tracer, *complex, defects, origin, h), h))
        continue; // the same cell size, magnified where the defects are
      if(!options.preserve && magnification.restore_fewest_defects(topology_distance(stats)))
        continue; // the run of the rounds with the fewest defects, kept
      if(options.preserve && !stats.topology_preserved()) {
        magnification.clear(); // the whole grid is refined from here
        finest_with_defects = h;
        check_refinement(tm, range_map, tracer, *complex, defects, stats, h, refinements, options.maximum_vertices);
        h *= topology_refinement_factor;
        ++refinements;
        continue;
      }
      for(const auto& defect : defects)
        visitor(defect);
      inspect(tracer, *complex);

      progress.report(Remeshing_stage::PRIMAL_OUTPUT, 0);
      write_primal_complex(tm, vpm, vertex_index, tracer, *complex, out, np_in, np_out, stats, parallel_edges);
      progress.report(Remeshing_stage::PRIMAL_OUTPUT, 1);
      stats.time_output_ms = milliseconds_since(start);
      stats.time_total_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_total).count();
      return stats;
    } catch(const Remeshing_error& error) {
      if(may_move_origin && dynamic_cast<const Lattice_overflow*>(&error) != nullptr) {
        may_move_origin = false; // once, to the input: the same cells, fewer of them from it
        origin = lattice_point_below<Point_d>(tm, magnification.map(), h);
        continue;
      }
      if(magnification.undo_if_failed(error))
        continue;
      rethrow_run_error(error, refinements, finest_with_defects, h);
    }
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_RUN_H
