// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_TRACER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_TRACER_H

// Section 3-4 of the paper: the intersection of the mapped surface u(M) with the
// integer lattice of R^D, traced arc by arc across the input triangles.
//
// u(v) = (f(v) - origin) / cell_size, evaluated lazily and cached.
// An intersection vertex is a (triangle, grid edge {x_i = k, x_j = m}, i < j) pair;
// it has four arcs, stored in slots 0: +i, 1: +j, 2: -i, 3: -j, which is their
// counter-clockwise order on the surface when the triangle's orientation projected
// on (i, j) is positive, clockwise otherwise.
//
// On a surface with boundary (section 7 of the paper), an arc can also end where
// the input border crosses its hyperplane: a boundary vertex, keyed by (triangle,
// border edge of that triangle, hyperplane x_P = k). Its slots, in counter-clockwise
// order: 0 the boundary edge forward along the border (the interior on its left),
// 1 its one arc, 2 the boundary edge backward; slot 3 is unused. Where a border cycle
// has only two crossings, an input vertex between them becomes a boundary vertex too
// (a corner: no arc), since a polygon mesh cannot have a hole of two edges.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Lazily_zeroed_array.h>
#include <CGAL/Range_space_remeshing/internal/Level_differences.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>
#include <CGAL/Range_space_remeshing/internal/Prefetch.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_table.h>

#include <CGAL/Exact_rational.h>
#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <atomic>
#endif
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/use.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

constexpr std::uint32_t no_link = std::uint32_t(-1);
constexpr double infinity = std::numeric_limits<double>::infinity();

// Lattice levels are kept in 32-bit integers; range coordinates beyond this bound
// mean an absurd cell size and are rejected before they could overflow.
constexpr double maximum_lattice_coordinate = 1 << 29;

// The sequential complete scan estimates the output size (a pass over all faces)
// only once a bound of the vertices it builds reaches this many: below, building them
// costs less than the estimate would on every run.
constexpr double vertices_built_before_estimate = 1 << 20;

template <int D>
struct Intersection_vertex
{
  std::uint32_t face_id;
  std::int8_t i, j;        // axes of the grid edge, i < j
  std::int8_t orientation; // sign of the triangle's orientation projected on (i, j)
  bool has_cell = false;
  std::int8_t border_edge = -1; // boundary vertex: its edge in the triangle (i = j = P)
  std::array<std::int32_t, D> cell; // lattice cell; cell[i] = k, cell[j] = m always
  std::array<std::uint32_t, 4> link = {{no_link, no_link, no_link, no_link}}; // 4*vertex+slot

  std::int32_t k() const { return cell[i]; }
  std::int32_t m() const { return cell[j]; }
  bool is_boundary() const { return border_edge >= 0; }
  /// a boundary vertex at an input vertex, added where a border cycle has only two
  /// crossings (a polygon mesh has no hole of two edges); i = j = -1, no arc
  bool is_corner() const { return border_edge >= 0 && i < 0; }
};

// slots of a boundary vertex
constexpr int forward_slot = 0, boundary_arc_slot = 1, backward_slot = 2;

/// Index of the lowest set bit of x != 0.
inline int lowest_set_bit(std::uint32_t x)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(x);
#else
  int i = 0;
  for(; !(x & 1); x >>= 1)
    ++i;
  return i;
#endif
}

/// std::ceil for |x| < 2^31, without a library call.
inline std::int32_t ceil_to_int(double x)
{
  const std::int32_t i = std::int32_t(x);
  return i + (double(i) < x);
}

/// Throws `Error(message())`, with the message built here, out of line: built where the
/// input is checked, once per face, it made the checking functions too big to inline.
template <class Error, class Message>
[[noreturn]]
#if defined(__GNUC__)
__attribute__((noinline, cold))
#endif
void throw_error(const Message& message)
{
  throw Error(message());
}

template <class TriangleMesh, class RangeMap, class FaceIndexMap, class VertexIndexMap,
          class Traits>
class Grid_tracer
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

public:
  static constexpr int D = Traits::dimension;
  using Point_d = typename Traits::Point_d;
  using Vertex = Intersection_vertex<D>;
  using Levels = std::array<std::int32_t, D>;

  Grid_tracer(const TriangleMesh& tm, RangeMap range_map, FaceIndexMap face_index,
              VertexIndexMap vertex_index, const Point_d& origin, double cell_size,
              std::size_t maximum_vertices, const Traits& traits)
    : tm_(tm), range_map_(range_map), face_index_(face_index), vertex_index_(vertex_index),
      origin_(origin), cell_size_(cell_size), maximum_vertices_(maximum_vertices),
      predicates_(traits), mapped_(num_vertices(tm)),
      mapped_vertices_(num_vertices(tm)),
      vertex_of_id_(num_vertices(tm)), records_(num_faces(tm)),
      recorded_(num_faces(tm)), face_of_id_(num_faces(tm)),
      // typical outputs have a few times fewer vertices than the input has faces; the
      // bound keeps a seeded run on a huge input from clearing a huge table (it grows)
      table_((std::min)(std::size_t(num_faces(tm)) / 8, std::size_t(1) << 16))
  {}

  /// Where the scan and the tracing report how far they are (and may be cancelled).
  void set_progress(const Progress& progress) { progress_ = &progress; }

  // ---------------------------------------------------------------- results
  const std::vector<Vertex>& intersection_vertices() const { return vertices_; }
  face_descriptor face_of(const Vertex& v) const { return face_of_id_[v.face_id]; }
  std::size_t number_of_mapped_vertices() const { return number_of_mapped_; }
  std::size_t number_of_visited_faces() const { return number_of_visited_faces_; }
  /// whether an input border was met (every face is recorded in a complete scan)
  bool has_seen_border() const { return seen_border_; }
  std::size_t number_of_tracing_steps() const { return tracing_steps_; }
  FaceIndexMap face_index_map() const { return face_index_; }

  // ---------------------------------------------------------------- seeding
  /// Finds every intersection vertex of the triangle `f` and queues it.
  void scan_face(face_descriptor f)
  {
    scan_triangle(load_face(f), [](const Crossed_levels&) {});
  }

  /// The complete scan on this thread: `scan_face()` over `faces(tm)`, after
  /// `map_all_vertices()`. Refuses an output whose expected size
  /// (`expected_number_of_vertices()`) exceeds the cap before it is built, without
  /// the pass over all faces that this estimate takes on most runs: a bound of the
  /// vertices built, summed before each face is scanned, has to reach
  /// `vertices_built_before_estimate` (or the cap, if lower) first. Only then is the
  /// estimate made, once; if it is above the cap, at most about that many vertices
  /// were built for nothing, however large one face is.
  void scan_all_faces()
  {
    const double cap = double(maximum_vertices_);
    const double check_at = (std::min)(cap, vertices_built_before_estimate);
    double bound = 0;
    bool checked = false;
    auto bound_before_scan = [&](const Crossed_levels& levels) {
      if(checked)
        return;
      bound += vertices_bound(levels);
      if(bound_may_reach(bound, check_at)) {
        checked = true;
        refuse_if_expected_above(cap);
      }
    };
    record_all_faces();
    const std::size_t n = all_face_ids_.size();
    Work_meter meter(*progress_, Remeshing_stage::SCAN);
    std::size_t vertices_before = vertices_.size();
    for(std::size_t position = 0; position < n; ++position) {
      // the work: a face, and the vertices it holds; the second half of the scan
      meter.add(1 + vertices_.size() - vertices_before, [&] { return 0.5 + 0.5 * double(position) / double(n); });
      vertices_before = vertices_.size();
      if(position + scan_lookahead < n)
        prefetch_corners(all_face_ids_[position + scan_lookahead]);
      scan_triangle(load(all_face_ids_[position]), bound_before_scan);
    }
  }

  /// Faces ahead in the scan whose corners are asked for: the work of a face covers
  /// about a memory access's wait at this distance.
  static constexpr std::size_t scan_lookahead = 8;

  /// The first pass of the sequential complete scan: records every face, in the order
  /// of `faces(tm)`, which is kept in `all_face_ids_`. The scan then knows a face's
  /// corners long before it reads them: it asks for them `scan_lookahead` faces ahead,
  /// so that reading the three corners of a face (anywhere in the vertex array, and two
  /// cache lines each at D = 9) does not wait for memory.
  void record_all_faces()
  {
    list_faces_in_scan_order();
    for(std::uint32_t face_id : all_face_ids_)
      record(face_id);
  }

  /// The order of a complete scan, sequential or parallel: the faces' indices in the
  /// order of `faces(tm)`, in `all_face_ids_`, and their descriptors in `face_of_id_`.
  void list_faces_in_scan_order()
  {
    all_face_ids_.clear();
    all_face_ids_.reserve(num_faces(tm_));
    for(face_descriptor f : faces(tm_)) {
      const std::uint32_t face_id = std::uint32_t(get(face_index_, f));
      face_of_id_[face_id] = f;
      all_face_ids_.push_back(face_id);
    }
  }

  void prefetch_corners(std::uint32_t face_id) const
  {
    for(std::uint32_t corner : records_[face_id].vertex)
      prefetch(&mapped_vertices_[corner]);
  }

  /// Throws the error that says the output would exceed `cap` if
  /// `expected_number_of_vertices()` does.
  void refuse_if_expected_above(double cap)
  {
    const double expected = expected_number_of_vertices();
    if(expected > cap)
      throw Remeshing_error("the output would have about " + std::to_string(std::llround(expected)) +
                            " vertices, more than the cap of " + std::to_string(std::llround(cap)) +
                            ": the cell size is too small for this input",
                            Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  }

  /// Creates the boundary vertices on the border edges of a face, if it has any.
  void create_border_crossings_of(std::uint32_t face_id)
  {
    for(int e = 0; e < 3; ++e)
      if(records_[face_id].neighbour[e] == border)
        border_crossings(face_id, e);
  }

  /// Before a complete scan, which maps every vertex anyway: maps them in the order of
  /// `vertices(tm)`. The map then reads its property maps in their storage order; the
  /// scan over the faces would read them at random (at n = 9, three arrays per vertex).
  void map_all_vertices()
  {
    std::size_t done = 0;
    const std::size_t total = 2 * num_vertices(tm_); // the mapping is the scan's first half
    for(vertex_descriptor v : vertices(tm_)) {
      progress_->report_every(Remeshing_stage::SCAN, done++, total);
      map_in_place(v);
    }
    number_of_mapped_ = mapped_.size();
  }

#if defined(CGAL_LINKED_WITH_TBB)
  /// The first half of the complete scan on all threads: maps every vertex and
  /// records every face, each task writing only the entries of its own elements.
  /// Afterwards `refuse_too_large_output()` maps nothing.
  void map_and_record_in_parallel()
  {
    const std::vector<vertex_descriptor> all_vertices(vertices(tm_).begin(), vertices(tm_).end());
    in_reported_blocks(all_vertices.size(), 0.0, [&](std::size_t first, std::size_t last) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 2048),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for(std::size_t i = range.begin(); i != range.end(); ++i)
                            map_in_place(all_vertices[i]);
                        });
    });
    number_of_mapped_ = all_vertices.size();

    list_faces_in_scan_order();
    std::atomic<bool> border_seen(false);
    in_reported_blocks(all_face_ids_.size(), 0.25, [&](std::size_t first, std::size_t last) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 2048),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          bool border_here = false;
                          for(std::size_t i = range.begin(); i != range.end(); ++i) {
                            const std::uint32_t id = all_face_ids_[i];
                            fill_record(id);
                            recorded_[id] = 1;
                            for(std::uint32_t n : records_[id].neighbour)
                              border_here = border_here || n == border;
                          }
                          if(border_here)
                            border_seen = true;
                        });
    });
    seen_border_ = seen_border_ || border_seen;
    number_of_visited_faces_ = all_face_ids_.size();
  }

  /// The second half: the exact tests of every face on all threads, then, on this
  /// thread, the vertices created and queued in the order in which `scan_face()`
  /// over `faces(tm)` creates them, so that the result is the sequential one,
  /// vertex numbering included.
  void scan_in_parallel()
  {
    struct Found
    {
      std::uint32_t position; // in faces(tm)
      std::int8_t i, j, orientation;
      std::int32_t k, m;
    };
    constexpr std::size_t chunk = 1024; // faces per task: the merge below needs the order
    const std::size_t n = all_face_ids_.size(), chunks = (n + chunk - 1) / chunk;
    std::vector<std::vector<Found>> found(chunks);
    in_reported_blocks(chunks, 0.5, [&](std::size_t first, std::size_t last) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last), [&](const tbb::blocked_range<std::size_t>& range) {
        for(std::size_t c = range.begin(); c != range.end(); ++c)
          for(std::size_t position = c * chunk; position < (std::min)(n, (c + 1) * chunk); ++position) {
            const Triangle t = load(all_face_ids_[position]); // reads only: all mapped and recorded
            const Crossed_levels levels = crossed_levels(t);
            if(levels.number_of_axes == 0)
              continue;
            account_for_crossings(levels, t.face_id);
            scan_crossed_levels(t, levels, [&](int i, int j, std::int32_t k, std::int32_t m, int o) {
              found[c].push_back(
                  {std::uint32_t(position), std::int8_t(i), std::int8_t(j), std::int8_t(o), k, m});
            });
          }
      });
    });
    for(std::size_t c = 0; c < chunks; ++c) {
      auto next = found[c].begin();
      for(std::size_t position = c * chunk; position < (std::min)(n, (c + 1) * chunk); ++position) {
        const std::uint32_t face_id = all_face_ids_[position];
        for(; next != found[c].end() && next->position == position; ++next)
          find_or_create(face_id, next->i, next->j, next->k, next->m, next->orientation, /*queue*/ true);
        create_border_crossings_of(face_id);
      }
    }
  }

  /// Runs `work(first, last)` on consecutive blocks of [0, n), reporting the scan's
  /// progress between them on this thread: the visitor is never called from two
  /// threads, and a cancellation waits for one block at most. `start`: the fraction of
  /// the scan done before.
  template <class Work>
  void in_reported_blocks(std::size_t n, double start, const Work& work)
  {
    constexpr std::size_t block = 16 * Progress::interval;
    for(std::size_t first = 0; first < n; first += block) {
      progress_->report(Remeshing_stage::SCAN, start + 0.25 * double(first) / double(n));
      work(first, (std::min)(n, first + block));
    }
  }
#endif

  /// Expected number of intersection vertices: the number of lattice points in a
  /// projected triangle is about its area, so the sum of the projected areas over all
  /// faces and axis pairs predicts the output size before anything is built.
  double expected_number_of_vertices()
  {
    double expected = 0;
    for(face_descriptor f : faces(tm_)) {
      const Triangle t = load_face(f);
      const Point_d &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
      for(int i = 0; i < D; ++i)
        for(int j = i + 1; j < D; ++j)
          expected += 0.5 * std::abs((b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]));
    }
    return expected;
  }

  /// Refuses an output whose `expected_number_of_vertices()` exceeds the cap, before
  /// it is built. The estimate is made only when the sum of
  /// `expected_vertices_bound()` may reach the cap.
  void refuse_too_large_output()
  {
    double bound = 0;
    for(face_descriptor f : faces(tm_))
      bound += expected_vertices_bound(load_face(f));
    if(bound_may_reach(bound, double(maximum_vertices_)))
      refuse_if_expected_above(double(maximum_vertices_));
  }

  /// Whether a sum of bounds (`expected_vertices_bound()`, `vertices_bound()`) may
  /// reach `level`, with a wide margin for the rounding of the sum and of the estimate.
  static bool bound_may_reach(double bound, double level) { return 1.01 * bound >= level; }

  /// Scans the faces reachable from `seed` across edges, nearest first, until one
  /// holding an intersection vertex is found. Returns false if there is none.
  bool seed_from(face_descriptor seed)
  {
    if(seed_marks_.empty())
      seed_marks_ = Zeroed_array<std::uint8_t>(num_faces(tm_));
    const std::uint32_t seed_id = std::uint32_t(get(face_index_, seed));
    face_of_id_[seed_id] = seed;
    std::deque<std::uint32_t> faces_to_scan(1, seed_id);
    std::vector<std::uint32_t> marked(1, seed_id);
    seed_marks_[seed_id] = 1;
    bool found = false;
    while(!faces_to_scan.empty() && !found) {
      const std::uint32_t f = faces_to_scan.front();
      faces_to_scan.pop_front();
      const std::size_t before = queue_.size();
      scan_face(face_of_id_[f]);
      found = queue_.size() > before;
      for(std::uint32_t n : records_[f].neighbour)
        if(n != border && !seed_marks_[n]) {
          seed_marks_[n] = 1;
          marked.push_back(n);
          faces_to_scan.push_back(n);
        }
    }
    if(!found) // the whole component was scanned: its border cycles are all uncrossed
      count_border_cycles_of(marked);
    for(std::uint32_t f : marked)
      seed_marks_[f] = 0;
    return found;
  }

  /// Border cycles of the components in which `seed_from()` found nothing: all
  /// uncrossed (the seeded mode cannot tell for the others).
  std::size_t number_of_border_cycles_of_empty_components() const { return border_cycles_of_empty_components_; }

  // ---------------------------------------------------------------- tracing
  /// Traces every arc of every queued vertex; vertices met at arc ends are created
  /// when `create_at_arc_ends`, and must already exist otherwise (complete scan).
  void trace(bool create_at_arc_ends)
  {
    Work_meter meter(*progress_, Remeshing_stage::TRACE);
    std::size_t steps_before = tracing_steps_;
    for(std::size_t traced = 0; !queue_.empty(); ++traced) {
      // the work: the steps of the arcs (one face each); the queue holds every vertex
      // after a complete scan, the seeded tracing adds more
      meter.add(1 + tracing_steps_ - steps_before, [&] { return double(traced) / double(traced + queue_.size()); });
      steps_before = tracing_steps_;
      const std::uint32_t v = queue_.front();
      queue_.pop_front();
      if(!vertices_[v].has_cell)
        compute_cell(v);
      if(vertices_[v].is_boundary()) {
        if(vertices_[v].link[boundary_arc_slot] == no_link)
          trace_and_link(v, boundary_arc_slot, create_at_arc_ends);
        if(vertices_[v].link[forward_slot] == no_link)
          link(v, forward_slot, neighbour_along_border(v, +1), backward_slot);
        if(vertices_[v].link[backward_slot] == no_link)
          link(v, backward_slot, neighbour_along_border(v, -1), forward_slot);
        continue;
      }
      for(int slot = 0; slot < 4; ++slot)
        if(vertices_[v].link[slot] == no_link)
          trace_and_link(v, slot, create_at_arc_ends);
    }
    add_corners_to_two_vertex_holes();
  }

  /// Number of corners added (see `Intersection_vertex::is_corner()`).
  std::size_t number_of_corners() const { return number_of_corners_; }

  /// Number of boundary vertices found.
  std::size_t number_of_boundary_vertices() const { return number_of_boundary_vertices_; }

  /// Number of border cycles of the input that no grid hyperplane crosses: they have
  /// no boundary vertex, so the output does not have them (a hole inside one cell
  /// is covered by the face of that cell). Meaningful after a complete scan only.
  std::size_t number_of_uncrossed_border_cycles()
  {
    std::vector<std::uint8_t> walked(3 * num_faces(tm_), 0); // by border_key()
    std::size_t uncrossed = 0;
    for(halfedge_descriptor b : halfedges(tm_)) {
      if(!is_border(b, tm_) || walked[border_key(border_edge_of(opposite(b, tm_)))])
        continue;
      bool crossed = false;
      for(halfedge_descriptor c : CGAL::halfedges_around_face(b, tm_)) {
        const std::uint64_t key = border_key(border_edge_of(opposite(c, tm_)));
        walked[key] = 1;
        const auto found = border_crossings_.find(key);
        crossed = crossed || (found != border_crossings_.end() && !found->second.empty());
      }
      uncrossed += crossed ? 0 : 1;
    }
    return uncrossed;
  }

private:
  static constexpr std::uint32_t border = std::uint32_t(-1);

  void count_border_cycles_of(const std::vector<std::uint32_t>& faces_of_component)
  {
    if(walked_border_.empty())
      walked_border_ = Zeroed_array<std::uint8_t>(3 * num_faces(tm_)); // once: by border_key()
    for(std::uint32_t f : faces_of_component)
      for(int e = 0; e < 3; ++e) {
        if(records_[f].neighbour[e] != border || walked_border_[border_key({f, e})])
          continue;
        ++border_cycles_of_empty_components_;
        const halfedge_descriptor start = opposite(halfedge_of({f, e}), tm_);
        for(halfedge_descriptor c : CGAL::halfedges_around_face(start, tm_))
          walked_border_[border_key(border_edge_of(opposite(c, tm_)))] = 1;
      }
  }

  // The part of the input the tracer reads, copied once per visited face into a
  // compact array: arcs cross each triangle several times, and chasing the
  // FaceGraph's halfedges each time is what costs (cache misses), not the predicates.
  struct Face_record
  {
    std::array<std::uint32_t, 3> vertex;    // counter-clockwise, vertex 0 = source(halfedge(f))
    std::array<std::uint32_t, 3> neighbour; // face across edge vertex e -> vertex e+1, or border
  };

  struct Triangle
  {
    std::uint32_t face_id;
    std::array<const Point_d*, 3> p; // range coordinates of the corners
    std::array<const Levels*, 3> c;  // their ceilings
  };

  /// The lattice levels a triangle strictly crosses, per axis.
  struct Crossed_levels
  {
    // level k + eps lies strictly between lo and hi iff ceil(lo) <= k <= ceil(hi) - 1;
    // set in the listed axes only
    Levels first, last;
    std::array<int, D> axes;      // the axes with a crossed level, increasing
    int number_of_axes = 0;
    // crossed levels over all axes: the hyperplane segments in the triangle (up to
    // D * 2^30 for an absurd cell size, hence 64 bits)
    std::int64_t hyperplanes = 0;
  };

  struct Wall
  {
    int axis = -1;
    std::int32_t level = 0;
    int up = 0; // +1: upper wall of the box in this axis, -1: lower wall
  };

  // -------------------------------------------------------------- the lazy map
  // The check is on every corner of every loaded triangle: kept small and inlined,
  // with the evaluation of the map (once per vertex, and as large as the map's
  // code, lazy normals included) out of line.
  std::size_t u(std::uint32_t id)
  {
    CGAL_assertion(id < mapped_.size());
    if(!mapped_[id])
      map_vertex(id);
    return id;
  }

#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  void map_vertex(std::uint32_t id)
  {
    compute_range_coordinates(id);
    mapped_[id] = 1;
    ++number_of_mapped_;
  }

  /// Maps v, writing only its own entries (any thread).
  void map_in_place(vertex_descriptor v)
  {
    const std::uint32_t id = std::uint32_t(get(vertex_index_, v));
    vertex_of_id_[id] = v;
    compute_range_coordinates(id);
    mapped_[id] = 1;
  }

  /// f of the vertex, in cell units, and its ceilings: writes only its own entry.
  void compute_range_coordinates(std::uint32_t id)
  {
    const Point_d f = get(range_map_, vertex_of_id_[id]);
    Point_d& x = mapped_vertices_[id].u;
    Levels& c = mapped_vertices_[id].ceiling;
    for(int q = 0; q < D; ++q) {
      x[q] = (f[q] - origin_[q]) / cell_size_;
      if(!(std::abs(x[q]) < maximum_lattice_coordinate)) // NaN too: one test on the common path
        refuse_coordinate(f[q], id);
      c[q] = ceil_to_int(x[q]);
    }
  }

  [[noreturn]] static void refuse_coordinate(double value, std::uint32_t id)
  {
    if(!std::isfinite(value))
      throw Remeshing_error("the range map gives a NaN or infinite value at input vertex " + std::to_string(id));
    throw Remeshing_error("the cell size is too small for the range of the map: "
                          "more than 2^29 cells along one axis",
                          Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  }

  const Face_record& record(std::uint32_t face_id)
  {
    CGAL_assertion(face_id < recorded_.size());
    Face_record& r = records_[face_id];
    if(recorded_[face_id])
      return r;
    const Face_handles handles = fill_record(face_id);
    for(int e = 0; e < 3; ++e) {
      vertex_of_id_[r.vertex[e]] = handles.corners[e];
      if(r.neighbour[e] == border)
        seen_border_ = true;
      else
        face_of_id_[r.neighbour[e]] = handles.neighbours[e];
    }
    recorded_[face_id] = 1;
    ++number_of_visited_faces_;
    return r;
  }

  /// The corners and the neighbours (where not border) of a face.
  struct Face_handles
  {
    std::array<vertex_descriptor, 3> corners;
    std::array<face_descriptor, 3> neighbours;
  };

  /// Fills the record of a face: the only entry it writes.
  Face_handles fill_record(std::uint32_t face_id)
  {
    Face_record& r = records_[face_id];
    Face_handles handles;
    const face_descriptor f = face_of_id_[face_id];
    const halfedge_descriptor h0 = halfedge(f, tm_);
    const std::array<halfedge_descriptor, 3> h = {{h0, next(h0, tm_), next(next(h0, tm_), tm_)}};
    if(next(h[2], tm_) != h0)
      throw_error<Remeshing_error>(
          [&] { return "the input has a face that is not a triangle (face " + std::to_string(face_id) + ")"; });
    for(int e = 0; e < 3; ++e)
      handles.corners[e] = source(h[e], tm_);
    check_face_structure(f, face_id, h, handles.corners);
    for(int e = 0; e < 3; ++e) {
      r.vertex[e] = std::uint32_t(get(vertex_index_, handles.corners[e]));
      const halfedge_descriptor o = opposite(h[e], tm_);
      if(is_border(o, tm_)) {
        r.neighbour[e] = border;
      } else {
        handles.neighbours[e] = face(o, tm_);
        r.neighbour[e] = std::uint32_t(get(face_index_, handles.neighbours[e]));
      }
    }
    return handles;
  }

  /// What the walk relies on, checked once per visited face (so also lazily in the
  /// seeded mode): the face's halfedges point back to it, their opposites to them, and
  /// its three corners (`corners[e]`, the source of `h[e]`) are distinct vertices.
  void check_face_structure(face_descriptor f, std::uint32_t face_id, const std::array<halfedge_descriptor, 3>& h,
                            const std::array<vertex_descriptor, 3>& corners) const
  {
    for(int e = 0; e < 3; ++e)
      if(face(h[e], tm_) != f || opposite(opposite(h[e], tm_), tm_) != h[e] ||
         target(h[e], tm_) != corners[(e + 1) % 3])
        throw_error<Remeshing_error>(
            [&] { return "the input is not a valid halfedge structure around face " + std::to_string(face_id); });
    if(corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0])
      throw_error<Remeshing_error>(
          [&] { return "the input has a face with a repeated vertex (face " + std::to_string(face_id) + ")"; });
  }

  /// An upper bound of the face's term of `expected_number_of_vertices()`, in O(D)
  /// instead of O(D^2): with B = b - a, C = c - a, each term |B_i C_j - B_j C_i| <=
  /// |B_i| |C_j| + |B_j| |C_i|, so the sum over i < j is at most (sum |B_i|) (sum |C_j|).
  static double expected_vertices_bound(const Triangle& t)
  {
    const Point_d &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
    double sum_b = 0, sum_c = 0;
    for(int q = 0; q < D; ++q) {
      sum_b += std::abs(b[q] - a[q]);
      sum_c += std::abs(c[q] - a[q]);
    }
    return 0.5 * sum_b * sum_c;
  }

  Triangle load_face(face_descriptor f)
  {
    const std::uint32_t face_id = std::uint32_t(get(face_index_, f));
    face_of_id_[face_id] = f;
    return load(face_id);
  }

  /// Finds every intersection vertex of the triangle and queues it. If it crosses a
  /// level, `before_scan(levels)` is told which before anything is built.
  template <class BeforeScan>
  void scan_triangle(const Triangle& t, const BeforeScan& before_scan)
  {
    const Crossed_levels levels = crossed_levels(t);
    if(levels.number_of_axes > 0) {
      before_scan(levels);
      scan_crossed_levels_of(t, levels);
    }
    create_border_crossings_of(t.face_id);
  }

  void scan_crossed_levels_of(const Triangle& t, const Crossed_levels& levels)
  {
    account_for_crossings(levels, t.face_id);
    scan_crossed_levels(t, levels, [&](int i, int j, std::int32_t k, std::int32_t m, int o) {
      find_or_create(t.face_id, i, j, k, m, o, /*queue*/ true);
    });
  }

  /// What every scan does with the levels a face crosses before its exact tests:
  /// refuses too many, and counts the pieces of arc the topology check expects.
  /// Writes only the face's own entry, so tasks of the parallel scan may call it.
  void account_for_crossings(const Crossed_levels& levels, std::uint32_t face_id)
  {
    refuse_if_too_many_crossings(levels, face_id);
    if(untraced_pieces_)
      untraced_pieces_[face_id] += std::int32_t(levels.hyperplanes);
  }

  /// A face crossing more levels than the output may have vertices: its scan alone would
  /// take a loop per crossed level, and a needle of a face across the whole lattice
  /// (2^30 levels per axis, nearly no area, so no large estimate) ran for minutes.
  void refuse_if_too_many_crossings(const Crossed_levels& levels, std::uint32_t face_id) const
  {
    if(levels.hyperplanes > std::int64_t(maximum_vertices_))
      throw_error<Remeshing_error>([&] {
        return "face " + std::to_string(face_id) + " crosses " + std::to_string(levels.hyperplanes) +
               " grid hyperplanes, more than the cap of " + std::to_string(maximum_vertices_) +
               " vertices: the cell size is too small for this input";
      });
  }

  /// Asked of every face. Only the axes in which the corners' ceilings differ have a
  /// crossed level; a face with none lies in one cell and holds no intersection vertex
  /// (many faces, and the more so the higher D). One comparison of the three arrays
  /// finds those axes (see Level_differences.h).
  static Crossed_levels crossed_levels(const Triangle& t)
  {
    Crossed_levels levels;
    for(std::uint32_t axes = level_differences(*t.c[0], *t.c[2], *t.c[1]); axes != 0; axes &= axes - 1) {
      const int q = lowest_set_bit(axes);
      levels.first[q] = lowest_ceiling(t, q);
      levels.last[q] = highest_ceiling(t, q) - 1;
      levels.hyperplanes += std::int64_t(levels.last[q]) + 1 - levels.first[q];
      levels.axes[levels.number_of_axes++] = q;
    }
    return levels;
  }

  /// An upper bound of the vertices the scan of a triangle creates: one per grid edge
  /// {x_i = k, x_j = m} of crossed levels, at most (sum of the crossed levels)^2 / 2.
  static double vertices_bound(const Crossed_levels& levels)
  {
    return 0.5 * double(levels.hyperplanes) * double(levels.hyperplanes);
  }

  Triangle load(std::uint32_t face_id)
  {
    const Face_record& r = record(face_id);
    Triangle t;
    t.face_id = face_id;
    for(int e = 0; e < 3; ++e) {
      const std::size_t id = u(r.vertex[e]);
      t.p[e] = &mapped_vertices_[id].u;
      t.c[e] = &mapped_vertices_[id].ceiling;
    }
    return t;
  }

  /// The intersection vertices of the triangle: the grid edges {x_i = k, x_j = m}
  /// of the levels it strictly crosses, tested exactly (see `scan_face()`).
  /// Calls `found(i, j, k, m, orientation)` for each, in a fixed order.
  template <class Found>
  void scan_crossed_levels(const Triangle& t, const Crossed_levels& levels, const Found& found) const
  {
    const Levels &first = levels.first, &last = levels.last;
    for(int a = 0; a < levels.number_of_axes; ++a)
      for(int b = a + 1; b < levels.number_of_axes; ++b) {
        const int i = levels.axes[a], j = levels.axes[b];
        for(std::int32_t k = first[i]; k <= last[i]; ++k) {
          // Only the lattice points near the column x_i = k of the projected triangle
          // are candidates: the work is proportional to its area, not its bounding box.
          std::int32_t m_first = first[j], m_last = last[j];
          column_range(t, i, j, k, m_first, m_last);
          for(std::int32_t m = m_first; m <= m_last; ++m) {
            const int o = predicates_.grid_edge_orientation(*t.p[0], *t.p[1], *t.p[2], i, j,
                                                            double(k), double(m));
            if(o != 0)
              found(i, j, k, m, o);
          }
        }
      }
  }

  /// Narrows [m_first, m_last] to the levels of axis j near the segment where the
  /// line x_i = k meets the triangle projected on (i, j). Estimated in doubles and
  /// widened by one level: the exact test of each candidate decides.
  void column_range(const Triangle& t, int i, int j, std::int32_t k, std::int32_t& m_first,
                    std::int32_t& m_last) const
  {
    double low = infinity, high = -infinity;
    for(int e = 0; e < 3; ++e) {
      const Point_d& p = *t.p[e];
      const Point_d& q = *t.p[(e + 1) % 3];
      if((std::min)(p[i], q[i]) > k || (std::max)(p[i], q[i]) < k)
        continue;
      double y;
      if(p[i] == q[i]) {
        low = (std::min)({low, p[j], q[j]});
        high = (std::max)({high, p[j], q[j]});
        continue;
      }
      y = p[j] + (double(k) - p[i]) / (q[i] - p[i]) * (q[j] - p[j]);
      low = (std::min)(low, y);
      high = (std::max)(high, y);
    }
    if(!(low <= high))
      return; // keep the bounding-box range
    const double margin = 1. + 1e-9 * (std::abs(low) + std::abs(high));
    m_first = (std::max)(m_first, std::int32_t(std::floor(low - margin)));
    m_last = (std::min)(m_last, std::int32_t(std::ceil(high + margin)));
  }

  // -------------------------------------------------------------- vertices
  std::uint32_t find_or_create(std::uint32_t face_id, int i, int j,
                               std::int32_t k, std::int32_t m, int o, bool queue)
  {
    const Vertex_key key{face_id, i, j, k, m};
    bool inserted = false;
    const std::uint32_t id = table_.find_or_insert(
        key, std::uint32_t(vertices_.size()),
        [this](std::uint32_t stored) { return key_of(vertices_[stored]); }, inserted);
    if(!inserted)
      return id;
    check_cap();
    if(untraced_pieces_)
      untraced_pieces_[face_id] += 2; // the vertex splits the segments of both its hyperplanes
    Vertex v;
    v.face_id = face_id;
    v.i = std::int8_t(i);
    v.j = std::int8_t(j);
    v.orientation = std::int8_t(o);
    v.cell[i] = k;
    v.cell[j] = m;
    vertices_.push_back(v);
    if(queue)
      queue_.push_back(id);
    return id;
  }

  static Vertex_key key_of(const Vertex& v)
  {
    if(v.is_boundary())
      return boundary_key(v.face_id, v.border_edge, v.i, v.k());
    return {v.face_id, v.i, v.j, v.k(), v.m()};
  }

  static Vertex_key boundary_key(std::uint32_t face_id, int e, int P, std::int32_t level)
  {
    return {face_id, P, -1 - e, level, 0}; // j < 0: no grid-edge vertex has it
  }

  // -------------------------------------------------------------- boundary
  struct Border_edge
  {
    std::uint32_t face_id;
    int e; // edge vertex e -> vertex e+1 of the face record, its opposite a border
  };

  static std::uint64_t border_key(const Border_edge& b) { return 3 * std::uint64_t(b.face_id) + b.e; }

  halfedge_descriptor halfedge_of(const Border_edge& b) const
  {
    halfedge_descriptor h = halfedge(face_of_id_[b.face_id], tm_);
    for(int e = 0; e < b.e; ++e)
      h = next(h, tm_);
    return h;
  }

  Border_edge border_edge_of(halfedge_descriptor h)
  {
    const face_descriptor f = face(h, tm_);
    const std::uint32_t face_id = std::uint32_t(get(face_index_, f));
    face_of_id_[face_id] = f;
    int e = 0;
    for(halfedge_descriptor g = halfedge(f, tm_); g != h; g = next(g, tm_))
      ++e;
    return {face_id, e};
  }

  /// The next border edge along the border, forward (direction > 0: the direction
  /// of the face's edge) or backward, turning around the shared input vertex.
  Border_edge next_border_edge(const Border_edge& b, int direction)
  {
    halfedge_descriptor g = halfedge_of(b);
    if(direction > 0) {
      g = next(g, tm_);
      while(!is_border(opposite(g, tm_), tm_))
        g = next(opposite(g, tm_), tm_);
    } else {
      g = prev(g, tm_);
      while(!is_border(opposite(g, tm_), tm_))
        g = prev(opposite(g, tm_), tm_);
    }
    return border_edge_of(g);
  }

  /// The boundary vertices of border edge e of a face, in order along the edge
  /// (the face's counter-clockwise direction); created, and queued, on first request.
  const std::vector<std::uint32_t>& border_crossings(std::uint32_t face_id, int e)
  {
    const std::uint64_t key = border_key({face_id, e});
    const auto found = border_crossings_.find(key);
    if(found != border_crossings_.end())
      return found->second;
    const Triangle t = load(face_id);
    const Point_d &a = *t.p[e], &b = *t.p[(e + 1) % 3];
    const Levels &ca = *t.c[e], &cb = *t.c[(e + 1) % 3];
    std::vector<std::uint32_t> ids;
    for(int P = 0; P < D; ++P) // levels strictly crossed, as in scan_face()
      for(std::int32_t level = (std::min)(ca[P], cb[P]); level < (std::max)(ca[P], cb[P]); ++level)
        ids.push_back(create_boundary_vertex(face_id, e, P, level, a, b));
    std::sort(ids.begin(), ids.end(), [&](std::uint32_t x, std::uint32_t y) {
      return comes_first_along_edge(a, b, vertices_[x], vertices_[y]);
    });
    return border_crossings_.emplace(key, std::move(ids)).first->second;
  }

  /// Of two crossings of edge ab with hyperplanes, is x met first going from a to b?
  bool comes_first_along_edge(const Point_d& a, const Point_d& b, const Vertex& x, const Vertex& y) const
  {
    if(x.i == y.i)
      return (x.k() < y.k()) == (a[x.i] < b[x.i]);
    // side of x's crossing point relative to y's hyperplane, against the direction
    // in which the edge crosses that hyperplane
    const int side_of_x = predicates_.crossing_side(a, b, x.i, double(x.k()), y.i, double(y.k()));
    return side_of_x != (a[y.i] < b[y.i] ? 1 : -1);
  }

  std::uint32_t create_boundary_vertex(std::uint32_t face_id, int e, int P, std::int32_t level,
                                       const Point_d& a, const Point_d& b)
  {
    bool inserted = false;
    const std::uint32_t id = table_.find_or_insert(
        boundary_key(face_id, e, P, level), std::uint32_t(vertices_.size()),
        [this](std::uint32_t stored) { return key_of(vertices_[stored]); }, inserted);
    CGAL_assertion(inserted);
    check_cap();
    Vertex v;
    v.face_id = face_id;
    v.i = v.j = std::int8_t(P);
    v.border_edge = std::int8_t(e);
    v.orientation = 1; // slots 0, 1, 2 counter-clockwise
    v.cell = cell_of_crossing(a, b, P, level);
    v.has_cell = true;
    vertices_.push_back(v);
    queue_.push_back(id);
    ++number_of_boundary_vertices_;
    return id;
  }

  /// The lattice cell of the point where segment ab crosses x_P = level, exactly:
  /// the floor of its coordinates in the other axes, and level in axis P.
  Levels cell_of_crossing(const Point_d& a, const Point_d& b, int P, std::int32_t level) const
  {
    Levels cell;
    cell[P] = level;
    const double t = Predicates::crossing_parameter(a, b, P, double(level));
    for(int q = 0; q < D; ++q) {
      if(q == P)
        continue;
      const double guess = a[q] + t * (b[q] - a[q]);
      std::int32_t n = std::int32_t(std::floor((std::min)((std::max)(guess, (std::min)(a[q], b[q])),
                                                           (std::max)(a[q], b[q]))));
      while(predicates_.crossing_side(a, b, P, double(level), q, double(n)) < 0) --n;
      while(predicates_.crossing_side(a, b, P, double(level), q, double(n + 1)) > 0) ++n;
      cell[q] = n;
    }
    return cell;
  }

  /// The boundary vertex next to v along the input border (direction +1: forward).
  std::uint32_t neighbour_along_border(std::uint32_t v, int direction)
  {
    Border_edge b{vertices_[v].face_id, vertices_[v].border_edge};
    const std::vector<std::uint32_t>& here = border_crossings(b.face_id, b.e);
    const std::size_t at = std::size_t(std::find(here.begin(), here.end(), v) - here.begin());
    CGAL_assertion(at < here.size());
    if(direction > 0 && at + 1 < here.size())
      return here[at + 1];
    if(direction < 0 && at > 0)
      return here[at - 1];
    // the border cycle holds v, so the walk ends at the latest back on v's edge
    for(std::size_t step = 0; step <= 3 * num_faces(tm_); ++step) {
      b = next_border_edge(b, direction);
      const std::vector<std::uint32_t>& crossings = border_crossings(b.face_id, b.e);
      if(!crossings.empty())
        return direction > 0 ? crossings.front() : crossings.back();
    }
    throw std::logic_error("Range_space_remeshing: endless border (internal error)");
  }

  /// Where a border cycle has two boundary vertices a, b only, inserts after a the
  /// input vertex that ends a's border edge, taking a whose forward neighbour b is
  /// not further along the same edge: that vertex is then between a and b.
  void add_corners_to_two_vertex_holes()
  {
    const std::size_t n = vertices_.size();
    for(std::uint32_t a = 0; a < n; ++a) {
      if(!vertices_[a].is_boundary())
        continue;
      const std::uint32_t b = vertices_[a].link[forward_slot] / 4;
      if(b < a || vertices_[b].link[forward_slot] / 4 != a)
        continue; // not a cycle of two, or seen from b already
      const auto& crossings = border_crossings(vertices_[a].face_id, vertices_[a].border_edge);
      const bool b_after_a_on_its_edge =
          std::find(std::find(crossings.begin(), crossings.end(), a), crossings.end(), b) != crossings.end();
      insert_corner_after(b_after_a_on_its_edge ? b : a);
    }
  }

  void insert_corner_after(std::uint32_t a)
  {
    const std::uint32_t b = vertices_[a].link[forward_slot] / 4;
    Vertex c;
    c.face_id = vertices_[a].face_id;
    c.border_edge = vertices_[a].border_edge;
    c.i = c.j = -1;
    c.orientation = 1;
    const std::size_t input_vertex = u(record(c.face_id).vertex[(c.border_edge + 1) % 3]);
    const Levels& ceiling = mapped_vertices_[input_vertex].ceiling;
    for(int q = 0; q < D; ++q)
      c.cell[q] = ceiling[q] - 1; // a coordinate on a level counts as below it
    c.has_cell = true;
    const std::uint32_t id = std::uint32_t(vertices_.size());
    vertices_.push_back(c);
    vertices_[a].link[forward_slot] = vertices_[b].link[backward_slot] = no_link;
    link(a, forward_slot, id, backward_slot);
    link(id, forward_slot, b, backward_slot);
    ++number_of_corners_;
  }

  void link(std::uint32_t v, int slot, std::uint32_t w, int w_slot)
  {
    if(vertices_[w].link[w_slot] != no_link)
      throw std::logic_error("Range_space_remeshing: inconsistent boundary (internal error)");
    vertices_[v].link[slot] = 4 * w + std::uint32_t(w_slot);
    vertices_[w].link[w_slot] = 4 * v + std::uint32_t(slot);
  }

  void check_cap() const
  {
    if(vertices_.size() >= maximum_vertices_)
      throw Remeshing_error("the output would exceed the cap of " +
                            std::to_string(maximum_vertices_) +
                            " vertices: the cell size is too small for this input",
                            Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  }

  /// The lattice cell of the vertex in the axes other than its grid edge's:
  /// floor of its coordinates, decided by exact perturbed predicates.
  void compute_cell(std::uint32_t id)
  {
    Vertex& v = vertices_[id];
    const Triangle t = load(v.face_id);
    const Point_d &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
    const Levels &ca = *t.c[0], &cb = *t.c[1], &cc = *t.c[2];
    // barycentric estimate, only to guess the level; the exact test decides
    std::array<double, 3> w{};
    bool estimated = false;
    for(int q = 0; q < D; ++q) {
      if(q == v.i || q == v.j)
        continue;
      // Corners with one ceiling C lie strictly between the perturbed levels C - 1
      // and C, and so does every point of the triangle: the cell is C - 1 without a
      // test. True of most axes when D is large, as the cells are then wide.
      if(ca[q] == cb[q] && cb[q] == cc[q]) {
        v.cell[q] = ca[q] - 1;
        continue;
      }
      if(!estimated) {
        w = barycentric(t, v.i, v.j, v.k(), v.m());
        estimated = true;
      }
      const double lo = (std::min)({a[q], b[q], c[q]});
      const double hi = (std::max)({a[q], b[q], c[q]});
      double guess = w[0] * a[q] + w[1] * b[q] + w[2] * c[q];
      guess = (std::min)((std::max)(guess, lo), hi);
      std::int32_t n = std::int32_t(std::floor(guess));
      auto above = [&](std::int32_t level) {
        return predicates_.vertex_coordinate_side(a, b, c, v.orientation, v.i, v.j,
                                                  double(v.k()), double(v.m()), q,
                                                  double(level)) > 0;
      };
      while(!above(n)) --n;
      while(above(n + 1)) ++n;
      v.cell[q] = n;
    }
    v.has_cell = true;
  }

  // -------------------------------------------------------------- arcs
  void trace_and_link(std::uint32_t v, int slot, bool create_at_arc_ends)
  {
    std::uint32_t end;
    int end_slot;
    trace_arc(v, slot, create_at_arc_ends, end, end_slot);
    link(v, slot, end, end_slot);
  }

  void trace_arc(std::uint32_t start, int slot, bool create_at_arc_ends,
                 std::uint32_t& end, int& end_slot)
  {
    const Vertex v = vertices_[start]; // copy: vertices_ may grow below
    // Plane of the arc x_P = level; travel axis T and direction dir (none for an arc
    // leaving the border: it starts strictly inside its box).
    const bool from_border = v.is_boundary();
    const bool along_i = (slot % 2 == 0);
    const int P = from_border ? v.i : (along_i ? v.j : v.i);
    const int T = from_border ? -1 : (along_i ? v.i : v.j);
    const int dir = slot < 2 ? 1 : -1;
    const std::int32_t level = v.cell[P];
    // sigma: +1 when the side u_P > level lies left of the travel direction. An arc
    // from the border enters its triangle through the border edge e, so that edge
    // goes from the side +sigma to -sigma.
    const int sigma = from_border ? ((*load(v.face_id).c[v.border_edge])[P] > level ? 1 : -1)
                                  : ((slot == 0 || slot == 3) ? v.orientation : -v.orientation);

    std::array<std::int32_t, D> lo, hi;
    for(int q = 0; q < D; ++q) {
      lo[q] = v.cell[q];
      hi[q] = v.cell[q] + 1;
    }
    if(!from_border && dir < 0) {
      lo[T] = v.cell[T] - 1;
      hi[T] = v.cell[T];
    }
    std::array<double, D> lo_wall, hi_wall;
    std::array<std::int32_t, D> not_P; // all bits set but in axis P: masks P out
    for(int q = 0; q < D; ++q) {
      lo_wall[q] = double(lo[q]);
      hi_wall[q] = double(hi[q]);
      not_P[q] = q == P ? 0 : -1;
    }

    std::uint32_t f = v.face_id;
    const std::size_t maximum_steps = num_faces(tm_) + 1;
    for(std::size_t step = 0;; ++step) {
      if(step > maximum_steps)
        throw std::logic_error("Range_space_remeshing: endless arc (internal error)");
      ++tracing_steps_;
      if(untraced_pieces_)
        --untraced_pieces_[f];
      const Triangle t = load(f);
      // The arc's next face is one of these: its record (the step's first wait for
      // memory, as the faces around an arc lie anywhere in the input's order) is on
      // its way while this face's tests run.
      for(std::uint32_t n : records_[f].neighbour)
        if(n != border)
          prefetch(&records_[n]);
      const int e = exit_edge(t, P, level, sigma);
      const Point_d& a = *t.p[e];
      const Point_d& b = *t.p[(e + 1) % 3];

      const double t_exit = Predicates::crossing_parameter(a, b, P, double(level));
      // An axis in which both ends of the exit edge lie strictly between the walls
      // (ceiling = hi: lo < u <= hi, strictly inside the perturbed walls) has the
      // crossing point, between them, inside too: crossing_slab_side() would return
      // 0. That leaves out most axes, in one pass over the integer levels (with the
      // walls of the first triangle kept: without one, an axis inside stays inside).
      const Levels& ca = *t.c[e];
      const Levels& cb = *t.c[(e + 1) % 3];
      std::uint32_t candidates = masked_level_differences(ca, cb, hi, not_P);
      Wall first;
      for(; candidates != 0; candidates &= candidates - 1) {
        const int l = lowest_set_bit(candidates);
        // In the first triangle the arc cannot cross back the wall it starts on.
        const bool skip_lo = (step == 0 && l == T && dir > 0);
        const bool skip_hi = (step == 0 && l == T && dir < 0);
        const int where = predicates_.crossing_slab_side(
            a, b, P, level, t_exit, l, skip_lo ? -infinity : lo_wall[l],
            skip_hi ? infinity : hi_wall[l]);
        if(where == 0)
          continue;
        const Wall crossed = where < 0 ? Wall{l, lo[l], -1} : Wall{l, hi[l], +1};
        if(first.axis < 0 ||
           predicates_.is_met_first(*t.p[0], *t.p[1], *t.p[2], P, level, crossed.axis,
                                    crossed.level, first.axis, first.level, first.up))
          first = crossed;
      }

      if(first.axis >= 0) {
        finish_arc(t, P, level, first, lo, create_at_arc_ends, end, end_slot);
        return;
      }
      if(records_[f].neighbour[e] == border) {
        finish_arc_at_border(t, e, P, level, lo, end, end_slot);
        return;
      }
      f = records_[f].neighbour[e];
    }
  }

  /// The arc leaves the surface through border edge e of t, inside its box.
  void finish_arc_at_border(const Triangle& t, int e, int P, std::int32_t level,
                            const std::array<std::int32_t, D>& lo, std::uint32_t& end, int& end_slot)
  {
    border_crossings(t.face_id, e); // creates the edge's boundary vertices if need be
    end = table_.find(boundary_key(t.face_id, e, P, level),
                      [this](std::uint32_t id) { return key_of(vertices_[id]); });
    if(end == no_link)
      throw std::logic_error("Range_space_remeshing: arc ends at no boundary vertex (internal error)");
    end_slot = boundary_arc_slot;
    CGAL_USE(lo); // read by the assertion only
    CGAL_assertion_code(const Vertex& ev = vertices_[end];)
    CGAL_assertion_code(for(int q = 0; q < D; ++q))
    CGAL_assertion(q == P || ev.cell[q] == lo[q]);
  }

  /// The ccw edge of `t` through which an arc in x_P = level leaves, given sigma.
  int exit_edge(const Triangle& t, int P, std::int32_t level, int sigma) const
  {
    int side[3]; // u_P > level iff ceil(u_P) > level: ties count as below
    for(int e = 0; e < 3; ++e)
      side[e] = (*t.c[e])[P] > level ? 1 : -1;
    for(int e = 0; e < 3; ++e)
      if(side[e] == -sigma && side[(e + 1) % 3] == sigma)
        return e;
    throw std::logic_error("Range_space_remeshing: arc lost its plane (internal error)");
  }

  void finish_arc(const Triangle& t, int P, std::int32_t level, const Wall& wall,
                  const std::array<std::int32_t, D>& lo, bool create_at_arc_ends,
                  std::uint32_t& end, int& end_slot)
  {
    const int w = wall.axis;
    const int i = (std::min)(P, w), j = (std::max)(P, w);
    const std::int32_t k = (i == P) ? level : wall.level;
    const std::int32_t m = (i == P) ? wall.level : level;
    // The arc reaches the end vertex travelling along w towards the wall; leaving
    // the vertex along it goes the other way, -up.
    end_slot = (w == i ? 0 : 1) + (wall.up > 0 ? 2 : 0);

    if(create_at_arc_ends) {
      const int o = predicates_.projected_orientation(*t.p[0], *t.p[1], *t.p[2], i, j);
      end = find_or_create(t.face_id, i, j, k, m, o, true);
    } else {
      end = table_.find(Vertex_key{t.face_id, std::int8_t(i), std::int8_t(j), k, m},
                        [this](std::uint32_t id) { return key_of(vertices_[id]); });
      if(end == no_link)
        throw std::logic_error("Range_space_remeshing: arc ends at an unscanned vertex "
                               "(internal error)");
    }
    CGAL_assertion(predicates_.grid_edge_orientation(*t.p[0], *t.p[1], *t.p[2], i, j,
                                                     double(k), double(m)) != 0);
    // The end vertex lies in the arc's box, strictly inside in every other axis.
    Vertex& ev = vertices_[end];
    if(!ev.has_cell) {
      for(int q = 0; q < D; ++q)
        if(q != i && q != j)
          ev.cell[q] = lo[q];
      ev.has_cell = true;
    } else {
      CGAL_assertion_code(for(int q = 0; q < D; ++q))
      CGAL_assertion(q == i || q == j || ev.cell[q] == lo[q]);
    }
  }

  /// Barycentric coordinates of the point of the triangle whose (i, j) coordinates
  /// are (k, m). Only constructions: the exact predicates have decided that the
  /// point exists. Where the triangle's projection on (i, j) is degenerate, the
  /// centre of the points over (k, m); `barycentric_in_cell` does better there.
  std::array<double, 3> barycentric(const Triangle& t, int i, int j, double k, double m) const
  {
    std::array<double, 3> w;
    if(solve_barycentric(t, i, j, k, m, w))
      return w;
    const auto ends = points_over(t, i, j, k, m);
    return {{(ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2, (ends[0][2] + ends[1][2]) / 2}};
  }

  /// The 2x2 solve; false where the projection is degenerate. Where it is nearly
  /// so (the projected triangle's angles below 1e-8), rounding would throw the point
  /// far off, possibly out of the cell the exact predicates gave it: solve in exact
  /// rationals there (rare, and the inputs are doubles and integers, so exact).
  bool solve_barycentric(const Triangle& t, int i, int j, double k, double m, std::array<double, 3>& w) const
  {
    const Point_d &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
    const double bi = b[i] - a[i], bj = b[j] - a[j], ci = c[i] - a[i], cj = c[j] - a[j];
    const double det = bi * cj - bj * ci;
    double s, r;
    if(std::abs(det) > 1e-8 * std::sqrt((bi * bi + bj * bj) * (ci * ci + cj * cj))) {
      s = ((k - a[i]) * cj - (m - a[j]) * ci) / det;
      r = (bi * (m - a[j]) - bj * (k - a[i])) / det;
    } else {
      using Q = CGAL::Exact_rational;
      const Q qbi = Q(b[i]) - Q(a[i]), qbj = Q(b[j]) - Q(a[j]), qci = Q(c[i]) - Q(a[i]),
              qcj = Q(c[j]) - Q(a[j]), qk = Q(k) - Q(a[i]), qm = Q(m) - Q(a[j]);
      const Q qdet = qbi * qcj - qbj * qci;
      if(CGAL::is_zero(qdet))
        return false;
      s = CGAL::to_double((qk * qcj - qm * qci) / qdet);
      r = CGAL::to_double((qbi * qm - qbj * qk) / qdet);
    }
    const double s0 = (std::min)((std::max)(s, 0.), 1.);
    const double r0 = (std::min)((std::max)(r, 0.), 1. - s0);
    w = {{1. - s0 - r0, s0, r0}};
    return true;
  }

  /// Where the triangle projects on (i, j) to a segment (two coordinates of the map
  /// that vary together, a symmetric input) the points of the triangle over (k, m)
  /// form a segment: its two ends, in barycentric coordinates. Where it projects to
  /// a point, the whole triangle is over it: the centroid, twice.
  std::array<std::array<double, 3>, 2> points_over(const Triangle& t, int i, int j, double k, double m) const
  {
    const std::array<double, 3> centroid = {{1. / 3, 1. / 3, 1. / 3}};
    std::array<std::array<double, 2>, 3> q;
    for(int v = 0; v < 3; ++v)
      q[v] = {{(*t.p[v])[i], (*t.p[v])[j]}};
    std::array<double, 2> d = {{0, 0}}; // direction of the segment: the longest edge
    for(int v = 0; v < 3; ++v) {
      const std::array<double, 2> e = {{q[(v + 1) % 3][0] - q[v][0], q[(v + 1) % 3][1] - q[v][1]}};
      if(e[0] * e[0] + e[1] * e[1] > d[0] * d[0] + d[1] * d[1])
        d = e;
    }
    if(d[0] == 0 && d[1] == 0)
      return {{centroid, centroid}};
    std::array<double, 3> param;
    for(int v = 0; v < 3; ++v)
      param[v] = (q[v][0] - q[0][0]) * d[0] + (q[v][1] - q[0][1]) * d[1];
    const double lowest = (std::min)({param[0], param[1], param[2]});
    const double highest = (std::max)({param[0], param[1], param[2]});
    const double wanted =
        (std::min)((std::max)((k - q[0][0]) * d[0] + (m - q[0][1]) * d[1], lowest), highest);
    // the points where the triangle's edges reach the wanted parameter, on one line
    // of the barycentric triangle: keep the two farthest apart
    std::array<std::array<double, 3>, 4> found;
    int count = 0;
    for(int v = 0; v < 3; ++v) {
      const int w = (v + 1) % 3;
      std::array<double, 3> x = {{0, 0, 0}};
      if(param[v] == param[w]) {
        if(param[v] != wanted)
          continue;
        x[v] = 1; // the whole edge is over the point: both ends
        found[count++] = x;
        x[v] = 0;
        x[w] = 1;
        found[count++] = x;
      } else if((std::min)(param[v], param[w]) <= wanted && wanted <= (std::max)(param[v], param[w])) {
        const double lambda = (wanted - param[v]) / (param[w] - param[v]);
        x[v] = 1 - lambda;
        x[w] = lambda;
        if(count < 4)
          found[count++] = x;
      }
    }
    if(count == 0)
      return {{centroid, centroid}};
    std::array<std::array<double, 3>, 2> ends = {{found[0], found[0]}};
    double farthest = -1;
    for(int x = 0; x < count; ++x)
      for(int y = x; y < count; ++y) {
        double distance = 0;
        for(int c = 0; c < 3; ++c)
          distance += (found[x][c] - found[y][c]) * (found[x][c] - found[y][c]);
        if(distance > farthest) {
          farthest = distance;
          ends = {{found[x], found[y]}};
        }
      }
    return ends;
  }

  /// On the segment of the triangle over (k, m) (see `points_over`), the middle of the
  /// part whose coordinates lie in the vertex's cell: so that the sampled point agrees
  /// with the cell the exact predicates gave the vertex (or the nearest point of the
  /// segment to it).
  std::array<double, 3> barycentric_in_cell(const Triangle& t, const Vertex& v) const
  {
    const auto ends = points_over(t, v.i, v.j, double(v.k()), double(v.m()));
    auto coordinate = [&](const std::array<double, 3>& w, int q) {
      return w[0] * (*t.p[0])[q] + w[1] * (*t.p[1])[q] + w[2] * (*t.p[2])[q];
    };
    double from = 0, to = 1; // part of the segment inside the cell, as a parameter
    for(int q = 0; q < D; ++q) {
      if(q == v.i || q == v.j)
        continue;
      const double x0 = coordinate(ends[0], q), x1 = coordinate(ends[1], q);
      const double low = double(v.cell[q]), high = low + 1;
      if(x0 == x1)
        continue; // constant along the segment: nothing to choose
      const double t_low = (low - x0) / (x1 - x0), t_high = (high - x0) / (x1 - x0);
      from = (std::max)(from, (std::min)(t_low, t_high));
      to = (std::min)(to, (std::max)(t_low, t_high));
    }
    const double middle = (std::min)((std::max)((from + to) / 2, 0.), 1.);
    std::array<double, 3> w;
    for(int c = 0; c < 3; ++c)
      w[c] = (1 - middle) * ends[0][c] + middle * ends[1][c];
    return w;
  }

public:
  /// The input corners of the intersection vertex's triangle, in the order of
  /// `barycentric_coordinates()`: read from its record, which holds them already
  /// (where going through the mesh from `face_of()` would read four more places).
  std::array<vertex_descriptor, 3> corners_of(const Vertex& v) const
  {
    const Face_record& r = records_[v.face_id]; // recorded: v was created in it
    return {{vertex_of_id_[r.vertex[0]], vertex_of_id_[r.vertex[1]], vertex_of_id_[r.vertex[2]]}};
  }

  /// Asks for the record of the vertex's triangle: the first of what
  /// `barycentric_coordinates()` and `corners_of()` read, and the one that says where
  /// the rest is (see `prefetch_corners_of()`, a few vertices later).
  void prefetch_record_of(const Vertex& v) const { prefetch(&records_[v.face_id]); }

  /// Asks for the rest, once the record is in the cache: the mapped corners and their
  /// descriptors.
  void prefetch_corners_of(const Vertex& v) const
  {
    prefetch_corners(v.face_id);
    for(std::uint32_t corner : records_[v.face_id].vertex)
      prefetch(&vertex_of_id_[corner]);
  }

  /// Barycentric coordinates of the intersection vertex in its triangle, in the
  /// order source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))).
  std::array<double, 3> barycentric_coordinates(const Vertex& v)
  {
    const Triangle t = load(v.face_id);
    std::array<double, 3> w;
    if(v.is_corner()) {
      w = {{0, 0, 0}};
      w[(v.border_edge + 1) % 3] = 1;
      return w;
    }
    if(v.is_boundary()) { // on the border edge e, where it crosses x_P = k
      const int e = v.border_edge;
      const double s = Predicates::crossing_parameter(*t.p[e], *t.p[(e + 1) % 3], v.i, double(v.k()));
      w = {{0, 0, 0}};
      w[e] = 1 - (std::min)((std::max)(s, 0.), 1.);
      w[(e + 1) % 3] = 1 - w[e];
      return w;
    }
    if(solve_barycentric(t, v.i, v.j, double(v.k()), double(v.m()), w))
      return w;
    return v.has_cell ? barycentric_in_cell(t, v) : barycentric(t, v.i, v.j, double(v.k()), double(v.m()));
  }

  // ---------------------------------------------------------------- topology
  // What the topology check (Topology_check.h) reads, after a complete scan: every
  // face is recorded and every vertex it uses is mapped.

  /// Keeps, per input face, the number of pieces of hyperplane segments that no arc
  /// has passed through: + the hyperplanes crossing the face, + 2 per intersection
  /// vertex in it (it splits a segment of each of its two hyperplanes), - 1 per arc
  /// visit. After a complete scan and the tracing, what remains are the pieces of
  /// closed loops. To be called before the scan; costs an increment per tracing step.
  void count_untraced_pieces()
  {
    untraced_piece_counts_.assign(num_faces(tm_), 0);
    untraced_pieces_ = untraced_piece_counts_.data();
  }

  /// Calls `report(P, level, cell, faces)` for each closed loop of the surface in a
  /// hyperplane x_P = level that meets no grid edge (so no arc traced it): `cell` is
  /// the lattice cell above the grid face holding it (cell[P] = level), `faces` the
  /// ids of the input faces it crosses. Needs `count_untraced_pieces()`, a complete
  /// scan and `trace()`; walks only from the faces with untraced pieces.
  template <class Report>
  std::size_t find_closed_loops(const Report& report)
  {
    std::size_t loops = 0;
    std::vector<std::uint32_t> loop;
    auto key = [](int P, std::int32_t level) { return (std::uint64_t(std::uint32_t(level)) << 8) | std::uint64_t(P); };
    // the segments of the loops found: a face several loops cross is met again. The
    // keys keep all their 64 bits (in 32, a negative level lost its high bits, and a
    // loop was found once more from each of its faces another loop crosses).
    std::unordered_map<std::uint32_t, std::vector<decltype(key(0, 0))>> found; // face -> keys
    auto is_found = [&](std::uint32_t f, int P, std::int32_t level) {
      const auto it = found.find(f);
      return it != found.end() && std::find(it->second.begin(), it->second.end(), key(P, level)) != it->second.end();
    };
    for(std::uint32_t f = 0; f < untraced_piece_counts_.size(); ++f) {
      if(untraced_piece_counts_[f] < 0)
        throw std::logic_error("Range_space_remeshing: an arc crossed a face more often than "
                               "hyperplanes do (internal error)");
      if(untraced_piece_counts_[f] == 0)
        continue;
      const Triangle t = load(f);
      for(int P = 0; P < D && untraced_piece_counts_[f] > 0; ++P)
        for(std::int32_t level = lowest_ceiling(t, P); level < highest_ceiling(t, P) &&
                                                       untraced_piece_counts_[f] > 0; ++level) {
          if(is_found(f, P, level) || segment_has_vertex(t, P, level) || !walk_loop(f, P, level, loop))
            continue;
          for(std::uint32_t g : loop) {
            --untraced_piece_counts_[g];
            found[g].push_back(key(P, level));
          }
          const int e = exit_edge(t, P, level, 1);
          report(P, level, cell_of_crossing(*t.p[e], *t.p[(e + 1) % 3], P, level), loop);
          ++loops;
        }
    }
    return loops;
  }

  static constexpr std::uint32_t no_neighbour = border;
  std::size_t number_of_input_faces() const { return face_of_id_.size(); }
  std::size_t number_of_input_vertices() const { return mapped_.size(); }
  face_descriptor face_of_id(std::uint32_t face_id) const { return face_of_id_[face_id]; }
  /// the face's corners (vertex ids, counter-clockwise) and its neighbours across
  /// the edges corner e -> corner e+1 (`no_neighbour` on the border)
  const std::array<std::uint32_t, 3>& corners_of(std::uint32_t face_id) const { return records_[face_id].vertex; }
  const std::array<std::uint32_t, 3>& neighbours_of(std::uint32_t face_id) const { return records_[face_id].neighbour; }
  /// the first lattice level above each range coordinate of a mapped vertex
  const Levels& ceiling_of(std::uint32_t vertex_id) const { return mapped_vertices_[vertex_id].ceiling; }

  /// The cell of the point where the input edge between the two mapped vertices
  /// crosses x_P = level (cell[P] = level): the same whichever face asks, since the
  /// edge is taken from its lower vertex id.
  Levels cell_of_edge_crossing(std::uint32_t a, std::uint32_t b, int P, std::int32_t level) const
  {
    if(b < a)
      std::swap(a, b);
    return cell_of_crossing(mapped_vertices_[a].u, mapped_vertices_[b].u, P, level);
  }

private:
  using Predicates = Perturbed_predicates<Traits>;

  static std::int32_t lowest_ceiling(const Triangle& t, int P)
  {
    return (std::min)({(*t.c[0])[P], (*t.c[1])[P], (*t.c[2])[P]});
  }
  static std::int32_t highest_ceiling(const Triangle& t, int P)
  {
    return (std::max)({(*t.c[0])[P], (*t.c[1])[P], (*t.c[2])[P]});
  }

  /// Whether the segment of x_P = level across the triangle holds an intersection
  /// vertex, by the exact tests of the scan.
  bool segment_has_vertex(const Triangle& t, int P, std::int32_t level) const
  {
    for(int l = 0; l < D; ++l) {
      if(l == P)
        continue;
      const int i = (std::min)(P, l), j = (std::max)(P, l);
      for(std::int32_t n = lowest_ceiling(t, l); n < highest_ceiling(t, l); ++n) {
        const double k = double(i == P ? level : n), m = double(i == P ? n : level);
        if(predicates_.grid_edge_orientation(*t.p[0], *t.p[1], *t.p[2], i, j, k, m) != 0)
          return true;
      }
    }
    return false;
  }

  /// Follows the curve of x_P = level from face f0 as the tracer would; true, with
  /// the faces in `loop`, when it comes back to f0 without meeting a face where it
  /// holds a vertex, or the border (then it is a piece of some traced arc).
  bool walk_loop(std::uint32_t f0, int P, std::int32_t level, std::vector<std::uint32_t>& loop)
  {
    loop.assign(1, f0);
    for(std::uint32_t f = f0; loop.size() <= num_faces(tm_);) {
      const std::uint32_t n = records_[f].neighbour[exit_edge(load(f), P, level, 1)];
      if(n == f0)
        return true;
      if(n == border || segment_has_vertex(load(n), P, level))
        return false;
      loop.push_back(f = n);
    }
    throw std::logic_error("Range_space_remeshing: endless level curve (internal error)");
  }

  const TriangleMesh& tm_;
  RangeMap range_map_;
  FaceIndexMap face_index_;
  VertexIndexMap vertex_index_;
  Point_d origin_;
  double cell_size_;
  std::size_t maximum_vertices_;
  Predicates predicates_;
  const Progress* progress_ = &Progress::none();

  // The arrays by input vertex or face are zeroed lazily, or not at all where each
  // entry is written before it is read: a seeded run touches only a fraction of them
  // (see Lazily_zeroed_array.h).
  Zeroed_array<std::uint8_t> mapped_;
  // u and its ceilings side by side: the tracer reads both for every corner
  struct Mapped_vertex
  {
    Point_d u;
    Levels ceiling; // the first lattice level above each coordinate (ties: equal)
  };
  Uninitialised_array<Mapped_vertex> mapped_vertices_; // filled on first use
  std::size_t number_of_mapped_ = 0;
  Uninitialised_array<vertex_descriptor> vertex_of_id_; // an entry is written before it is read
  Uninitialised_array<Face_record> records_; // filled on first use only
  Zeroed_array<std::uint8_t> recorded_;
  std::size_t number_of_visited_faces_ = 0;
  bool seen_border_ = false;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> border_crossings_; // by border_key()
  std::size_t number_of_boundary_vertices_ = 0;
  std::size_t number_of_corners_ = 0;
  Zeroed_array<std::uint8_t> seed_marks_;
  Zeroed_array<std::uint8_t> walked_border_; // by border_key(), for empty components
  std::size_t border_cycles_of_empty_components_ = 0;
  std::size_t tracing_steps_ = 0;
  std::vector<std::int32_t> untraced_piece_counts_; // see count_untraced_pieces()
  std::int32_t* untraced_pieces_ = nullptr;         // its data, or null: not counting

  std::vector<Vertex> vertices_;
  Uninitialised_array<face_descriptor> face_of_id_; // an entry is written before it is read
  std::vector<std::uint32_t> all_face_ids_; // a complete scan's order: faces(tm), by index
  Vertex_table table_;
  std::deque<std::uint32_t> queue_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_GRID_TRACER_H
