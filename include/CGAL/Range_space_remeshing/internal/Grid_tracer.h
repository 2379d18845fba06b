// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_TRACER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_TRACER_H

// Sections 3-4 of the paper: the intersection of the mapped surface u(M) with the
// integer lattice of R^D, as the primal complex's vertices and their links. This
// class holds the parts and their shared state, in the order of the data flow:
//
//   map    Mapped_input.h           u(v) = (f(v) - origin) / cell_size, lazily, and
//                                    the faces' records
//   scan   Grid_scanner.h           the intersection vertices: complete, parallel or
//                                    seeded; Output_size_cap.h refuses too many
//   trace  Arc_tracer.h             the arcs between them, face by face
//          Border_crossings.h       the boundary vertices and edges of an input border
//   faces  Primal_complex.h         (built by the caller from the links)
//   output Vertex_sampler.h         where each vertex lies on the input
//
// and what the topology check reads afterwards (Topology_check.h, Closed_loops.h).

#include <CGAL/Range_space_remeshing/internal/Arc_tracer.h>
#include <CGAL/Range_space_remeshing/internal/Border_crossings.h>
#include <CGAL/Range_space_remeshing/internal/Grid_scanner.h>
#include <CGAL/Range_space_remeshing/internal/Intersection_vertices.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>
#include <CGAL/Range_space_remeshing/internal/Output_size_cap.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Untraced_pieces.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_sampler.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class TriangleMesh, class RangeMap, class FaceIndexMap, class VertexIndexMap, class Traits>
class Grid_tracer
{
public:
  using Input = Mapped_input<TriangleMesh, RangeMap, FaceIndexMap, VertexIndexMap, Traits>;
  static constexpr int D = Input::D;
  using Point_d = typename Input::Point_d;
  using Levels = typename Input::Levels;
  using Vertex = Intersection_vertex<D>;
  using Predicates = Perturbed_predicates<Traits>;
  using face_descriptor = typename Input::face_descriptor;
  using vertex_descriptor = typename Input::vertex_descriptor;

  Grid_tracer(const TriangleMesh& tm, RangeMap range_map, FaceIndexMap face_index, VertexIndexMap vertex_index,
              const Point_d& origin, double cell_size, std::size_t maximum_vertices, const Traits& traits)
    : input_(tm, range_map, face_index, vertex_index, origin, cell_size), cap_(maximum_vertices),
      predicates_(traits),
      // typical outputs have a few times fewer vertices than the input has faces; the
      // bound keeps a seeded run on a huge input from clearing a huge table (it grows)
      vertices_((std::min)(std::size_t(num_faces(tm)) / 8, std::size_t(1) << 16), cap_, pieces_),
      border_(input_, vertices_, predicates_), scanner_(input_, vertices_, border_, pieces_, cap_, predicates_),
      tracer_(input_, vertices_, border_, pieces_, predicates_), sampler_(input_)
  {}

  // the parts refer to each other
  Grid_tracer(const Grid_tracer&) = delete;
  Grid_tracer& operator=(const Grid_tracer&) = delete;

  /// Where the scan and the tracing report how far they are (and may be cancelled).
  void set_progress(const Progress& progress) { progress_ = &progress; }

  // ---------------------------------------------------------------- map and scan
  /// Prepares the closed-loop check of the topology check: to be called before the
  /// scan; costs an increment per tracing step.
  void count_untraced_pieces() { pieces_.start_counting(num_faces(input_.mesh())); }

  /// The complete scan on this thread: every vertex mapped, then every face scanned.
  void map_all_vertices() { input_.map_all_vertices(*progress_); }
  void scan_all_faces() { scanner_.scan_all_faces(*progress_); }

#if defined(CGAL_LINKED_WITH_TBB)
  /// The complete scan on all threads: the input mapped and recorded, the output size
  /// estimated, then every face scanned.
  void map_and_record_in_parallel() { input_.map_and_record_in_parallel(*progress_); }
  void refuse_too_large_output() { cap_.refuse_too_large_output(input_); }
  void scan_in_parallel() { scanner_.scan_in_parallel(*progress_); }
#endif

  /// The seeded scan: see `Grid_scanner::seed_from()`.
  bool seed_from(face_descriptor seed) { return scanner_.seed_from(seed); }

  // ---------------------------------------------------------------- trace
  /// Traces every arc of every queued vertex; vertices met at arc ends are created
  /// when `create_at_arc_ends`, and must already exist otherwise (complete scan).
  void trace(bool create_at_arc_ends) { tracer_.trace(create_at_arc_ends, *progress_); }

  // ---------------------------------------------------------------- results
  const std::vector<Vertex>& intersection_vertices() const { return vertices_.all(); }
  std::size_t number_of_mapped_vertices() const { return input_.number_of_mapped_vertices(); }
  std::size_t number_of_visited_faces() const { return input_.number_of_visited_faces(); }
  /// whether an input border was met (every face is recorded in a complete scan)
  bool has_seen_border() const { return input_.has_seen_border(); }
  std::size_t number_of_tracing_steps() const { return tracer_.number_of_tracing_steps(); }
  FaceIndexMap face_index_map() const { return input_.face_index_map(); }
  std::size_t number_of_corners() const { return border_.number_of_corners(); }
  /// Border cycles that no grid hyperplane crosses, after a complete scan; after a
  /// seeded one, those of the components in which it found nothing.
  std::size_t number_of_uncrossed_border_cycles() { return border_.number_of_uncrossed_border_cycles(); }
  std::size_t number_of_border_cycles_of_empty_components() const
  {
    return border_.number_of_border_cycles_of_empty_components();
  }

  // ---------------------------------------------------------------- output
  std::array<vertex_descriptor, 3> corners_of(const Vertex& v) const { return sampler_.corners_of(v); }
  void prefetch_record_of(const Vertex& v) const { sampler_.prefetch_record_of(v); }
  void prefetch_corners_of(const Vertex& v) const { sampler_.prefetch_corners_of(v); }
  std::array<double, 3> barycentric_coordinates(const Vertex& v) const { return sampler_.barycentric_coordinates(v); }
  /// A point of the arc leaving the inner vertex `v` through `slot`, in barycentric
  /// coordinates of v's triangle (see `Arc_tracer::point_along_arc()`).
  auto point_along_arc(const Vertex& v, int slot)
  {
    return tracer_.point_along_arc(v, slot, sampler_.barycentric_coordinates(v));
  }
  /// The input corners of the triangle `face_id`, in the order of barycentric coordinates.
  std::array<vertex_descriptor, 3> corners_of_face(std::uint32_t face_id) const
  {
    return sampler_.corners_of_face(face_id);
  }

  // ---------------------------------------------------------------- topology check
  Input& input() { return input_; }
  Untraced_pieces& untraced_pieces() { return pieces_; }
  const Predicates& predicates() const { return predicates_; }

private:
  Input input_;
  Output_size_cap cap_;
  Predicates predicates_;
  Untraced_pieces pieces_;
  Intersection_vertices<D> vertices_;
  Border_crossings<Input> border_;
  Grid_scanner<Input> scanner_;
  Arc_tracer<Input> tracer_;
  Vertex_sampler<Input> sampler_;
  const Progress* progress_ = &Progress::none();
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_TRACER_H
