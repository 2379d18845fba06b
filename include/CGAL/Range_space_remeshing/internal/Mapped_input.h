// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_MAPPED_INPUT_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_MAPPED_INPUT_H

// The first step of the paper (section 3): the input surface M mapped into the range
// space, u(v) = (f(v) - origin) / cell_size, in cell units, with the first lattice
// level above each coordinate (its ceiling). Everything after it reads the input
// through this class only: the mapped corners of a face and its neighbours, copied
// once per visited face into a compact record, since arcs cross each triangle
// several times and chasing the FaceGraph's halfedges each time is what costs (cache
// misses), not the predicates. Both are made on first use, so that a seeded run
// touches only the faces its arcs cross.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Lattice.h>
#include <CGAL/Range_space_remeshing/internal/Lazily_zeroed_array.h>
#include <CGAL/Range_space_remeshing/internal/Prefetch.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#if defined(CGAL_LINKED_WITH_TBB)
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <atomic>
#endif
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Range values are refused from 2^42 cells on: the unit in their last place would be
/// more than 2^-10 of a cell.
constexpr int resolution_exponent = 42;

/// The refusal of a range coordinate beyond the lattice's 32-bit levels, of its own
/// type so that `primal_remesh_at()` can move a default grid origin next to the input
/// and try again (a scan in georeferenced coordinates lies 1e6 or more from the origin).
struct Lattice_overflow : Remeshing_error
{
  Lattice_overflow()
    : Remeshing_error("the cell size is too small for the range of the map: more than 2^29 cells along one axis "
                      "from the grid origin",
                      Kind::OUTPUT_TOO_LARGE)
  {}
};

/// Throws `Error(message(), more...)`, with the message built here, out of line: built
/// where the input is checked, once per face, it made the checking functions too big to
/// inline.
template <class Error, class Message, class... More>
[[noreturn]]
#if defined(__GNUC__)
__attribute__((noinline, cold))
#endif
void throw_error(const Message& message, const More&... more)
{
  throw Error(message(), more...);
}

#if defined(CGAL_LINKED_WITH_TBB)
/// Runs `work(first, last)` on consecutive blocks of [0, n), reporting the scan's
/// progress between them on this thread: the visitor is never called from two
/// threads, and a cancellation waits for one block at most. `start`: the fraction of
/// the scan done before.
template <class Work>
void in_reported_blocks(const Progress& progress, std::size_t n, double start, const Work& work)
{
  constexpr std::size_t block = 16 * Progress::interval;
  for(std::size_t first = 0; first < n; first += block) {
    progress.report(Remeshing_stage::SCAN, start + 0.25 * double(first) / double(n));
    work(first, (std::min)(n, first + block));
  }
}
#endif

template <class TriangleMesh, class RangeMap, class FaceIndexMap, class VertexIndexMap, class Traits_>
class Mapped_input
{
  using GT = boost::graph_traits<TriangleMesh>;

public:
  using Traits = Traits_;
  using Mesh = TriangleMesh;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  static constexpr int D = Traits::dimension;
  using Point_d = typename Traits::Point_d;
  using Levels = std::array<std::int32_t, D>;

  /// The neighbour of a face across a border edge.
  static constexpr std::uint32_t border = std::uint32_t(-1);

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

  Mapped_input(const TriangleMesh& tm, RangeMap range_map, FaceIndexMap face_index, VertexIndexMap vertex_index,
               const Point_d& origin, double cell_size)
    : tm_(tm), range_map_(range_map), face_index_(face_index), vertex_index_(vertex_index), origin_(origin),
      cell_size_(cell_size), resolved_value_(std::ldexp(cell_size, resolution_exponent)),
      mapped_(num_vertices(tm)), mapped_vertices_(num_vertices(tm)), vertex_of_id_(num_vertices(tm)),
      records_(num_faces(tm)), recorded_(num_faces(tm)), face_of_id_(num_faces(tm))
  {
    for(int q = 0; q < D; ++q)
      if(!(std::abs(origin_[q]) < resolved_value_))
        throw Remeshing_error(unresolved(origin_[q], "the grid origin's coordinate"), Remeshing_error::Kind::BAD_PARAMETER);
  }

  const TriangleMesh& mesh() const { return tm_; }
  FaceIndexMap face_index_map() const { return face_index_; }

  // ---------------------------------------------------------------- loading
  /// The index of `f`, remembering `f` as the face of that index.
  std::uint32_t id_of(face_descriptor f)
  {
    const std::uint32_t face_id = std::uint32_t(get(face_index_, f));
    face_of_id_[face_id] = f;
    return face_id;
  }

  Triangle load_face(face_descriptor f) { return load(id_of(f)); }

  /// The face's mapped corners, recording the face and mapping its corners if need be.
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

  // As `u()`: the check is on every loaded face, kept small and inlined, with the
  // recording (once per face) out of line.
  const Face_record& record(std::uint32_t face_id)
  {
    CGAL_assertion(face_id < recorded_.size());
    if(!recorded_[face_id])
      record_first_time(face_id);
    return records_[face_id];
  }

  /// The record of a face already recorded (a loaded face, or a neighbour's address to
  /// prefetch).
  const Face_record& record_of(std::uint32_t face_id) const { return records_[face_id]; }

  // ---------------------------------------------------------------- complete scans
  /// The order of a complete scan, sequential or parallel: the faces' indices in the
  /// order of `faces(tm)`.
  const std::vector<std::uint32_t>& faces_in_scan_order() const { return all_face_ids_; }

  /// Before a complete scan, which maps every vertex anyway: maps them in the order of
  /// `vertices(tm)`. The map then reads its property maps in their storage order; the
  /// scan over the faces would read them at random (at n = 9, three arrays per vertex).
  void map_all_vertices(const Progress& progress)
  {
    std::size_t done = 0;
    const std::size_t total = 2 * num_vertices(tm_); // the mapping is the scan's first half
    for(vertex_descriptor v : vertices(tm_)) {
      progress.report_every(Remeshing_stage::SCAN, done++, total);
      map_in_place(v);
    }
    number_of_mapped_ = mapped_.size();
  }

  /// Records every face, in the order of `faces(tm)`. The sequential scan then knows
  /// a face's corners long before it reads them: it asks for them a few faces ahead
  /// (`prefetch_corners()`), so that reading the three corners of a face (anywhere in
  /// the vertex array, and two cache lines each at D = 9) does not wait for memory.
  void record_all_faces()
  {
    list_faces_in_scan_order();
    for(std::uint32_t face_id : all_face_ids_)
      record(face_id);
  }

  void prefetch_corners(std::uint32_t face_id) const
  {
    for(std::uint32_t corner : records_[face_id].vertex)
      prefetch(&mapped_vertices_[corner]);
  }

  /// ... and their descriptors, read with them by the output.
  void prefetch_corner_handles(std::uint32_t face_id) const
  {
    for(std::uint32_t corner : records_[face_id].vertex)
      prefetch(&vertex_of_id_[corner]);
  }

#if defined(CGAL_LINKED_WITH_TBB)
  /// The first half of the complete scan on all threads: maps every vertex and
  /// records every face, each task writing only the entries of its own elements.
  void map_and_record_in_parallel(const Progress& progress)
  {
    const std::vector<vertex_descriptor> all_vertices(vertices(tm_).begin(), vertices(tm_).end());
    in_reported_blocks(progress, all_vertices.size(), 0.0, [&](std::size_t first, std::size_t last) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 2048),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for(std::size_t i = range.begin(); i != range.end(); ++i)
                            map_in_place(all_vertices[i]);
                        });
    });
    number_of_mapped_ = all_vertices.size();

    list_faces_in_scan_order();
    std::atomic<bool> border_seen(false);
    in_reported_blocks(progress, all_face_ids_.size(), 0.25, [&](std::size_t first, std::size_t last) {
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
#endif

  // ---------------------------------------------------------------- queries
  std::size_t number_of_mapped_vertices() const { return number_of_mapped_; }
  std::size_t number_of_visited_faces() const { return number_of_visited_faces_; }
  /// whether an input border was met (every face is recorded in a complete scan)
  bool has_seen_border() const { return seen_border_; }
  std::size_t number_of_input_faces() const { return face_of_id_.size(); }
  std::size_t number_of_input_vertices() const { return mapped_.size(); }
  face_descriptor face_of_id(std::uint32_t face_id) const { return face_of_id_[face_id]; }
  vertex_descriptor vertex_of_id(std::uint32_t vertex_id) const { return vertex_of_id_[vertex_id]; }
  /// the face's corners (vertex ids, counter-clockwise) and its neighbours across
  /// the edges corner e -> corner e+1 (`border` on the border)
  const std::array<std::uint32_t, 3>& corners_of(std::uint32_t face_id) const { return records_[face_id].vertex; }
  const std::array<std::uint32_t, 3>& neighbours_of(std::uint32_t face_id) const { return records_[face_id].neighbour; }
  /// the range coordinates of a mapped vertex, and the first lattice level above each
  const Point_d& point_of(std::uint32_t vertex_id) const { return mapped_vertices_[vertex_id].u; }
  const Levels& ceiling_of(std::uint32_t vertex_id) const { return mapped_vertices_[vertex_id].ceiling; }

  /// The halfedge of edge e (vertex e -> vertex e+1) of a recorded face.
  halfedge_descriptor halfedge_of(std::uint32_t face_id, int e) const
  {
    halfedge_descriptor h = halfedge(face_of_id_[face_id], tm_);
    for(int n = 0; n < e; ++n)
      h = next(h, tm_);
    return h;
  }

private:
  /// The corners and the neighbours (where not border) of a face.
  struct Face_handles
  {
    std::array<vertex_descriptor, 3> corners;
    std::array<face_descriptor, 3> neighbours;
  };

  void list_faces_in_scan_order()
  {
    all_face_ids_.clear();
    all_face_ids_.reserve(num_faces(tm_));
    for(face_descriptor f : faces(tm_))
      all_face_ids_.push_back(id_of(f));
  }

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

#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  void record_first_time(std::uint32_t face_id)
  {
    const Face_record& r = records_[face_id];
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
      if(!(std::abs(x[q]) < maximum_lattice_coordinate) || !(std::abs(f[q]) < resolved_value_)) // NaN too
        refuse_coordinate(f[q], x[q], id);
      c[q] = ceil_to_int(x[q]);
    }
  }

  [[noreturn]] void refuse_coordinate(double value, double in_cells, std::uint32_t id) const
  {
    if(!std::isfinite(value))
      throw Remeshing_error("the range map gives a NaN or infinite value at input vertex " + std::to_string(id));
    if(!(std::abs(value) < resolved_value_)) // first: no grid origin helps
      throw Remeshing_error(unresolved(value, "the range map's value at input vertex " + std::to_string(id)),
                            Remeshing_error::Kind::BAD_INPUT);
    CGAL_assertion(!(std::abs(in_cells) < maximum_lattice_coordinate));
    throw Lattice_overflow();
  }

  /// The refusal of a value so large beside the cell size that doubles place it only
  /// to within a thousandth of a cell: the cells would no longer bound the faces.
  std::string unresolved(double value, const std::string& what) const
  {
    std::ostringstream message;
    message << std::setprecision(3) << "the cell size (" << cell_size_ << ") is below 2^-" << resolution_exponent
            << " of " << what << " (" << value << "): doubles place it only to within a thousandth of a cell; "
            << "move the input nearer the origin of the range space, or use a larger cell size";
    return message.str();
  }

  /// Fills the record of a face: the only entry it writes (any thread).
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

  const TriangleMesh& tm_;
  RangeMap range_map_;
  FaceIndexMap face_index_;
  VertexIndexMap vertex_index_;
  Point_d origin_;
  double cell_size_;
  double resolved_value_; // range values at least this large are refused (see unresolved())

  // The arrays by input vertex or face are zeroed lazily, or not at all where each
  // entry is written before it is read: a seeded run touches only a fraction of them
  // (see Lazily_zeroed_array.h).
  Zeroed_array<std::uint8_t> mapped_;
  // u and its ceilings side by side: every step reads both for every corner
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
  Uninitialised_array<face_descriptor> face_of_id_; // an entry is written before it is read
  std::vector<std::uint32_t> all_face_ids_; // a complete scan's order: faces(tm), by index
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_MAPPED_INPUT_H
