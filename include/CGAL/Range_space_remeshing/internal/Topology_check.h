// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_TOPOLOGY_CHECK_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_TOPOLOGY_CHECK_H

// Whether the primal remesh has the topology of its input, decided after a complete
// scan from the tracer's records and the traced complex.
//
// The grid cuts the surface M into vertices, open arcs, closed loops and open
// regions (the components of M inside the open cells). Counting Euler
// characteristics with compact support, chi(M) = V - E + sum over regions of
// chi_c(R) (a loop counts 0), while the traced complex has V - E + F with F the
// number of traced faces, one per boundary cycle. So
//     chi(M) - chi(traced) = sum over regions of (chi_c(R) - cycles(R)),
// and for a region with at least one boundary cycle chi_c(R) - cycles(R) =
// 2 - 2 genus - ends - cycles <= 0, zero exactly for a disk bounded by one cycle.
// Regions without a traced cycle are bounded by closed loops or are whole
// components, and are found directly. Hence the cheap test: no loop, no lost
// component, no hole inside a cell and chi(M) = chi(traced) mean every region is a
// disk, and then the output is a cell decomposition of M: the same topology.
//
// Only when it fails are the defects located, cell by cell: chi_c of M inside an
// open cell c is #triangles - #edges + #vertices meeting it (a triangle or an edge
// meets a convex cell in one convex piece), and the triangles meeting c are found
// from the points where the cells around a triangle meet it: its corners, both sides
// of its edges' crossings, the four quadrants of its intersection vertices.

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Topology_defect.h>
#include <CGAL/Range_space_remeshing/internal/Cell_index.h>
#include <CGAL/Range_space_remeshing/internal/Closed_loops.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Union_find.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Tracer, class FaceDescriptor>
class Topology_check
{
  using Input = typename Tracer::Input;
  static constexpr int D = Tracer::D;
  using Levels = typename Tracer::Levels;
  using Defect = Topology_defect<FaceDescriptor>;
  static constexpr std::uint32_t none = std::uint32_t(-1);
  static constexpr std::size_t unlimited = std::size_t(-1);
  using Cell_map = std::unordered_map<Levels, long, Levels_hash<Levels>>;
  using Seeds = std::unordered_map<Levels, std::vector<std::uint32_t>, Levels_hash<Levels>>;
  struct Loop
  {
    int axis;
    Levels cell; // above the loop in `axis`
    std::vector<std::uint32_t> faces;
    bool harmless = false;
  };

public:
  Topology_check(Tracer& tracer, const Primal_complex& complex)
    : tracer_(tracer), input_(tracer.input()),
      closed_loops_(tracer.input(), tracer.untraced_pieces(), tracer.predicates()), complex_(complex),
      number_of_faces_(std::uint32_t(input_.number_of_input_faces()))
  {}

  /// Fills the topology fields of `stats` and returns the defects found.
  std::vector<Defect> run(Statistics& stats, const Progress& progress)
  {
    progress_ = &progress;
    progress.report(Remeshing_stage::TOPOLOGY_CHECK, 0);
    stats.topology_checked = true;
    closed_loops_.find(
        [&](int axis, std::int32_t level, const Levels& cell, const std::vector<std::uint32_t>& faces) {
          loops_.push_back(Loop{axis, cell, faces});
          loops_.back().cell[axis] = level;
        });
    progress.report(Remeshing_stage::TOPOLOGY_CHECK, 0.1);
    const long chi_of_kept_components = find_components(stats);
    progress.report(Remeshing_stage::TOPOLOGY_CHECK, 0.2);
    if(stats.uncrossed_border_cycles > 0) // the scan counted them: walk them for their faces
      find_lost_border_cycles();
    stats.input_euler_characteristic = input_euler_characteristic_;
    stats.output_euler_characteristic = complex_.euler_characteristic();
    stats.output_components = complex_.number_of_components();
    const bool chi_matches = chi_of_kept_components == complex_.traced_euler_characteristic();
    if(defects_.empty() && chi_matches && !loops_.empty()) {
      // Loops only: if they all just cut caps off, counting their cells is enough
      // (the other cells then have excess 0, the total being 0): no full count.
      Cell_map excess = count_in_cells_of_loops();
      stats.harmless_loops = absorb_caps(excess);
      if(stats.harmless_loops == loops_.size())
        return std::move(defects_);
      stats.harmless_loops = 0;
      for(Loop& loop : loops_)
        loop.harmless = false;
    }
    if(!defects_.empty() || !loops_.empty() || !chi_matches) {
      // Without lost pieces, counting the suspect cells is enough if they make up
      // the whole difference; else every cell is counted.
      Cell_map excess;
      const bool suspects_only = defects_.empty() &&
          count_in_suspect_cells(chi_of_kept_components - complex_.traced_euler_characteristic(), excess);
      if(!suspects_only)
        excess = count_per_cell();
      stats.harmless_loops = absorb_caps(excess);
      for(const Loop& loop : loops_)
        if(!loop.harmless) {
          add_defect(Topology_defect_kind::CLOSED_LOOP, loop.cell, loop.faces).axis = loop.axis;
          ++stats.closed_loops;
        }
      stats.non_disk_cells = suspects_only ? locate_non_disk_suspect_cells(excess) : locate_non_disk_cells(excess);
    }
    return std::move(defects_);
  }

private:
  template <class Faces>
  Defect& add_defect(Topology_defect_kind kind, const Levels& cell, const Faces& face_ids)
  {
    defects_.emplace_back();
    Defect& d = defects_.back();
    d.kind = kind;
    d.cell.assign(cell.begin(), cell.end());
    for(std::uint32_t f : face_ids)
      d.input_faces.push_back(input_.face_of_id(f));
    return d;
  }

  bool same_ceiling(std::uint32_t v, std::uint32_t w) const
  {
    return same_levels(input_.ceiling_of(v), input_.ceiling_of(w));
  }

  Levels cell_of_vertex(std::uint32_t v) const
  {
    Levels c = input_.ceiling_of(v);
    for(std::int32_t& x : c)
      --x; // a coordinate on a level counts as below it
    return c;
  }

  // ---------------------------------------------------------- components
  /// Labels the input components, finds those without output, and returns the
  /// Euler characteristic of the others (the input's is stored). Union-find over
  /// the faces in index order, not a traversal: neighbouring faces have close
  /// indices in most meshes, so the passes stay in cache.
  long find_components(Statistics& stats)
  {
    std::vector<std::uint32_t> parent(number_of_faces_);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      parent[f] = f;
      for(std::uint32_t n : input_.neighbours_of(f))
        if(n != Input::border && n < f)
          unite(parent, f, n);
    }
    struct Counts
    {
      long vertices = 0, half_edges = 0, border_edges = 0, faces = 0;
      bool output = false;
    };
    std::vector<Counts> counts;
    component_.assign(number_of_faces_, none);
    std::vector<std::uint32_t> vertex_owner(input_.number_of_input_vertices(), 0); // 1 + component
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      std::uint32_t& c = component_[union_find_root(parent, f)];
      if(c == none) {
        c = std::uint32_t(counts.size());
        counts.emplace_back();
      }
      component_[f] = c;
      Counts& k = counts[c];
      ++k.faces;
      k.half_edges += 3;
      for(int e = 0; e < 3; ++e) {
        const std::uint32_t v = input_.corners_of(f)[e];
        if(vertex_owner[v] != c + 1) {
          vertex_owner[v] = c + 1;
          ++k.vertices;
        }
        k.border_edges += input_.neighbours_of(f)[e] == Input::border ? 1 : 0;
      }
    }
    for(const auto& v : tracer_.intersection_vertices())
      counts[component_[v.face_id]].output = true;

    stats.input_components = counts.size();
    long chi_kept = 0;
    lost_component_.assign(counts.size(), 0);
    for(std::uint32_t c = 0; c < counts.size(); ++c) {
      const Counts& k = counts[c];
      const long chi = k.vertices - (k.half_edges + k.border_edges) / 2 + k.faces;
      input_euler_characteristic_ += chi;
      if(k.output)
        chi_kept += chi;
      else
        lost_component_[c] = 1;
    }
    report_lost_components(stats);
    return chi_kept;
  }

  static void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b)
  {
    a = union_find_root(parent, a);
    b = union_find_root(parent, b);
    if(a != b)
      parent[(std::max)(a, b)] = (std::min)(a, b);
  }

  void report_lost_components(Statistics& stats)
  {
    std::vector<std::size_t> defect_of(lost_component_.size(), std::size_t(-1));
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      const std::uint32_t c = component_[f];
      if(!lost_component_[c])
        continue;
      if(defect_of[c] == std::size_t(-1)) {
        defect_of[c] = defects_.size();
        add_defect(Topology_defect_kind::LOST_COMPONENT, cell_of_vertex(input_.corners_of(f)[0]),
                   std::vector<std::uint32_t>());
        ++stats.lost_components;
      }
      defects_[defect_of[c]].input_faces.push_back(input_.face_of_id(f));
    }
  }

  bool is_lost(std::uint32_t f) const { return lost_component_[component_[f]]; }

  // ---------------------------------------------------------- border cycles
  /// Border cycles whose vertices all lie in one cell (no hyperplane crosses them),
  /// in components that have an output.
  void find_lost_border_cycles()
  {
    std::vector<std::uint8_t> walked(3 * std::size_t(number_of_faces_), 0);
    std::vector<std::uint32_t> faces;
    for(std::uint32_t f = 0; f < number_of_faces_; ++f)
      for(int e = 0; e < 3; ++e) {
        if(input_.neighbours_of(f)[e] != Input::border || walked[3 * f + e] || is_lost(f))
          continue;
        const Levels& ceiling = input_.ceiling_of(input_.corners_of(f)[e]);
        bool one_cell = true;
        faces.clear();
        std::uint32_t g = f;
        int edge = e;
        do {
          walked[3 * g + edge] = 1;
          faces.push_back(g);
          one_cell = one_cell && same_levels(input_.ceiling_of(input_.corners_of(g)[edge]), ceiling);
          next_border_edge(g, edge);
        } while(g != f || edge != e);
        if(one_cell)
          add_defect(Topology_defect_kind::LOST_BORDER_CYCLE, cell_of_vertex(input_.corners_of(f)[e]), faces);
      }
  }

  /// The border edge that follows edge `e` of face `f` along the border, turning
  /// around the vertex that ends it.
  void next_border_edge(std::uint32_t& f, int& e) const
  {
    const std::uint32_t pivot = input_.corners_of(f)[(e + 1) % 3];
    for(std::uint32_t steps = 0; steps <= number_of_faces_; ++steps) {
      e = (e + 1) % 3; // the face's edge leaving the pivot
      const std::uint32_t n = input_.neighbours_of(f)[e];
      if(n == Input::border)
        return;
      f = n;
      const auto& corners = input_.corners_of(f);
      e = int(std::find(corners.begin(), corners.end(), pivot) - corners.begin());
      e = (e + 2) % 3; // the edge entering the pivot, shared with the previous face
    }
    CGAL_error_msg("Range_space_remeshing: endless border");
  }

  // ---------------------------------------------------------- cells

  /// A list of cells keeps each once by a search per insertion up to this size; past
  /// it, repeats are let in and removed once, by `remove_repeats()`. A face of a fine
  /// grid (the Gauss map at a crease) meets tens of thousands of cells: a search per
  /// insertion made that quadratic (minutes for one face), a sort of every list cost
  /// the common case, a face in a cell or two, 40 % more.
  static constexpr std::size_t searched_cells = 16;

  /// Appends x to the part of `list` from `from` on, where not there yet (for cells,
  /// their levels or their ids); a long part may hold repeats until `remove_repeats()`.
  template <class T>
  static void add_once(std::vector<T>& list, const T& x, std::size_t from = 0)
  {
    if(list.size() - from > searched_cells ||
       std::find_if(list.begin() + from, list.end(), [&](const T& y) { return same(y, x); }) == list.end())
      list.push_back(x);
  }

  static bool same(std::uint32_t a, std::uint32_t b) { return a == b; }
  static bool same(const Levels& a, const Levels& b) { return same_levels(a, b); }

  template <class T>
  static void add_each_once(const T* begin, const T* end, std::vector<T>& list, std::size_t from)
  {
    for(; begin != end; ++begin)
      add_once(list, *begin, from);
  }

  template <class T>
  static void remove_repeats(std::vector<T>& list, std::size_t from = 0)
  {
    if(list.size() - from <= searched_cells)
      return;
    std::sort(list.begin() + from, list.end());
    list.erase(std::unique(list.begin() + from, list.end()), list.end());
  }

  /// Adds the cells the open edge from vertex a to vertex b meets, but for its ends';
  /// long lists may hold repeats until the caller runs `remove_repeats()`.
  void add_crossing_cells(std::uint32_t a, std::uint32_t b, std::vector<Levels>& cells) const
  {
    const Levels &ca = input_.ceiling_of(a), &cb = input_.ceiling_of(b);
    for(int P = 0; P < D; ++P)
      for(std::int32_t level = (std::min)(ca[P], cb[P]); level < (std::max)(ca[P], cb[P]); ++level) {
        Levels c = closed_loops_.cell_of_edge_crossing(a, b, P, level);
        add_once(cells, c);
        --c[P];
        add_once(cells, c);
      }
  }

  /// Whether vertex v lies in cell c.
  bool vertex_in(std::uint32_t v, const Levels& c) const
  {
    const Levels& ceiling = input_.ceiling_of(v);
    for(int P = 0; P < D; ++P)
      if(ceiling[P] != c[P] + 1) // a coordinate on a level counts as below it
        return false;
    return true;
  }

  /// Whether the closed edge from vertex a to vertex b meets cell c: at an end, or
  /// where it crosses one of the two hyperplanes bounding c in some axis (the cells
  /// of its other crossings differ from c in that axis).
  bool edge_meets(std::uint32_t a, std::uint32_t b, const Levels& c) const
  {
    if(vertex_in(a, c) || vertex_in(b, c))
      return true;
    const Levels &ca = input_.ceiling_of(a), &cb = input_.ceiling_of(b);
    for(int P = 0; P < D; ++P)
      for(std::int32_t level = c[P]; level <= c[P] + 1; ++level) {
        if(level < (std::min)(ca[P], cb[P]) || level >= (std::max)(ca[P], cb[P]))
          continue;
        Levels x = closed_loops_.cell_of_edge_crossing(a, b, P, level);
        x[P] = c[P]; // the cell above the crossing, or below it
        if(same_levels(x, c))
          return true;
      }
    return false;
  }

  /// Whether face f meets cell c: along an edge, or around one of its intersection
  /// vertices.
  bool face_meets(std::uint32_t f, const Levels& c) const
  {
    const auto& corners = input_.corners_of(f);
    for(int e = 0; e < 3; ++e)
      if(edge_meets(corners[e], corners[(e + 1) % 3], c))
        return true;
    bool around_vertex = false;
    for_each_cell_around_vertices_of(f, [&](const Levels& x) { around_vertex = around_vertex || same_levels(x, c); });
    return around_vertex;
  }

  /// Calls `add(cell)` for the four cells around each intersection vertex of face f.
  template <class Add>
  void for_each_cell_around_vertices_of(std::uint32_t f, const Add& add) const
  {
    const auto& vertices = tracer_.intersection_vertices();
    for(std::uint32_t x = vertex_start_[f]; x < vertex_start_[f + 1]; ++x) {
      const auto& v = vertices[vertices_by_face_[x]];
      for(int quadrant = 0; quadrant < 4; ++quadrant) {
        Levels c = v.cell;
        c[v.i] -= quadrant & 1;
        c[v.j] -= quadrant >> 1;
        add(c);
      }
    }
  }

  /// The cell of the border piece that starts at boundary vertex v going forward:
  /// on the side of its hyperplane where the border edge ends.
  template <class Vertex>
  Levels cell_ahead(const Vertex& v) const
  {
    Levels c = v.cell;
    const std::uint32_t end = input_.corners_of(v.face_id)[(v.border_edge + 1) % 3];
    c[v.i] = v.k() - (input_.ceiling_of(end)[v.i] > v.k() ? 0 : 1);
    return c;
  }

  /// The counts above take M inside a cell with its border: a region that reaches
  /// the border has, for each open border piece between two boundary vertices in
  /// it, -1 in chi_c (a half-open disk has chi_c = 0). Calls `add(cell)` for each
  /// piece, so that such a disk has excess 0 too.
  template <class Add>
  void add_border_pieces(const Add& add) const
  {
    for(const auto& v : tracer_.intersection_vertices())
      if(v.is_boundary() && !v.is_corner() && !is_lost(v.face_id))
        add(cell_ahead(v));
  }

  /// The cell of a traced face, from the sector it fills at one of its vertices.
  Levels cell_of_traced_face(const Primal_complex::Traced_face_corner& corner) const
  {
    const auto& v = tracer_.intersection_vertices()[corner.halfedge / 4];
    const std::uint32_t s = corner.halfedge % 4, t = corner.next_slot;
    Levels c = v.cell;
    if(v.is_corner())
      return c;
    if(v.is_boundary()) {
      // between the forward boundary edge and the arc (slots 0 -> 1): the forward
      // side; between the arc and the backward edge: the other
      c = cell_ahead(v);
      if(s != 0)
        c[v.i] += c[v.i] == v.k() ? -1 : 1;
      return c;
    }
    const std::uint32_t along_i = (s % 2 == 0) ? s : t, along_j = (s % 2 == 0) ? t : s;
    c[v.i] = v.k() - (along_i == 0 ? 0 : 1); // slot 0 is +i, 2 is -i
    c[v.j] = v.m() - (along_j == 1 ? 0 : 1); // slot 1 is +j, 3 is -j
    return c;
  }

  void index_vertices_by_face()
  {
    if(!vertex_start_.empty())
      return; // indexed already (the loops' cells were counted first)
    const auto& vertices = tracer_.intersection_vertices();
    vertex_start_.assign(std::size_t(number_of_faces_) + 1, 0);
    for(const auto& v : vertices)
      if(!v.is_boundary())
        ++vertex_start_[v.face_id + 1];
    for(std::uint32_t f = 0; f < number_of_faces_; ++f)
      vertex_start_[f + 1] += vertex_start_[f];
    vertices_by_face_.resize(vertex_start_.back());
    std::vector<std::uint32_t> next(vertex_start_.begin(), vertex_start_.end() - 1);
    for(std::uint32_t x = 0; x < vertices.size(); ++x)
      if(!vertices[x].is_boundary())
        vertices_by_face_[next[vertices[x].face_id]++] = x;
  }

  // ---------------------------------------------------------- cells, by id
  /// Gives the cells that faces of kept components meet dense ids, and lists by id
  /// the cells of every such face; the cells where an edge crosses the grid are
  /// found once (an exact search each), at the face that owns the edge.
  void index_cells()
  {
    index_vertices_by_face();
    index_vertex_cells();
    index_edge_crossings();
    index_face_cells();
  }

  /// A vertex takes the id of a corner of the same face in the same cell where one
  /// has an id already (most do): a comparison instead of a hash.
  void index_vertex_cells()
  {
    vertex_cell_.assign(input_.number_of_input_vertices(), none);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      if(is_lost(f))
        continue;
      const auto& corners = input_.corners_of(f);
      for(int k = 0; k < 3; ++k) {
        const std::uint32_t v = corners[k];
        if(vertex_cell_[v] != none)
          continue;
        for(int other = 1; other < 3 && vertex_cell_[v] == none; ++other) {
          const std::uint32_t w = corners[(k + other) % 3];
          if(vertex_cell_[w] != none && same_ceiling(w, v))
            vertex_cell_[v] = vertex_cell_[w];
        }
        if(vertex_cell_[v] == none)
          vertex_cell_[v] = cell_index_.id_of(cell_of_vertex(v));
      }
    }
  }

  /// Whether edge e of face f is counted at f (each edge is, at one face).
  bool owns_edge(std::uint32_t f, int e) const
  {
    const std::uint32_t n = input_.neighbours_of(f)[e];
    return n == Input::border || n > f;
  }

  void index_edge_crossings()
  {
    crossing_start_.assign(3 * std::size_t(number_of_faces_) + 1, 0);
    crossing_cells_.clear();
    std::vector<Levels> cells;
    for(std::uint32_t f = 0; f < number_of_faces_; ++f)
      for(int e = 0; e < 3; ++e) {
        crossing_start_[3 * f + e] = std::uint32_t(crossing_cells_.size());
        if(is_lost(f) || !owns_edge(f, e))
          continue;
        const std::uint32_t a = input_.corners_of(f)[e], b = input_.corners_of(f)[(e + 1) % 3];
        if(same_ceiling(a, b))
          continue; // no crossing
        cells.clear();
        add_crossing_cells(a, b, cells);
        remove_repeats(cells);
        const Levels cell_a = cell_of_vertex(a), cell_b = cell_of_vertex(b);
        for(const Levels& c : cells) // the ends' cells are listed with the ends
          if(!same_levels(c, cell_a) && !same_levels(c, cell_b))
            crossing_cells_.push_back(cell_index_.id_of(c));
      }
    crossing_start_.back() = std::uint32_t(crossing_cells_.size());
  }

  /// Where the crossings of edge e of face f are listed: at the face owning the edge.
  std::size_t crossing_slot(std::uint32_t f, int e) const
  {
    if(owns_edge(f, e))
      return 3 * std::size_t(f) + e;
    const std::uint32_t n = input_.neighbours_of(f)[e];
    const std::uint32_t a = input_.corners_of(f)[e], b = input_.corners_of(f)[(e + 1) % 3];
    const auto& corners = input_.corners_of(n);
    for(int k = 0; k < 3; ++k) {
      const std::uint32_t p = corners[k], q = corners[(k + 1) % 3];
      if(input_.neighbours_of(n)[k] == f && ((p == a && q == b) || (p == b && q == a)))
        return 3 * std::size_t(n) + k;
    }
    CGAL_error_msg("Range_space_remeshing: an edge without its twin");
    return 0;
  }

  const std::uint32_t* crossings_begin(std::size_t slot) const { return crossing_cells_.data() + crossing_start_[slot]; }
  const std::uint32_t* crossings_end(std::size_t slot) const { return crossing_cells_.data() + crossing_start_[slot + 1]; }

  /// Whether face f lies in one cell: its corners do and no hyperplane crosses it.
  bool is_in_one_cell(std::uint32_t f) const
  {
    const auto& corners = input_.corners_of(f);
    return vertex_start_[f] == vertex_start_[f + 1] && same_ceiling(corners[0], corners[1]) &&
           same_ceiling(corners[0], corners[2]);
  }

  /// The cells a face meets: its corners', its edges' crossings', and the four
  /// around each of its intersection vertices.
  void index_face_cells()
  {
    face_start_.assign(std::size_t(number_of_faces_) + 1, 0);
    face_cells_.clear();
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      const std::size_t from = face_cells_.size();
      face_start_[f] = std::uint32_t(from);
      if(is_lost(f))
        continue;
      const auto& corners = input_.corners_of(f);
      if(is_in_one_cell(f)) {
        face_cells_.push_back(vertex_cell_[corners[0]]);
        continue;
      }
      for(std::uint32_t v : corners)
        add_once(face_cells_, vertex_cell_[v], from);
      for(int e = 0; e < 3; ++e) {
        if(same_ceiling(corners[e], corners[(e + 1) % 3]))
          continue; // no crossing: no need to find the twin that lists them
        const std::size_t slot = crossing_slot(f, e);
        add_each_once(crossings_begin(slot), crossings_end(slot), face_cells_, from);
      }
      for_each_cell_around_vertices_of(f, [&](const Levels& c) {
        const std::uint32_t id = cell_index_.id_of(c);
        add_once(face_cells_, id, from);
      });
      remove_repeats(face_cells_, from);
    }
    face_start_.back() = std::uint32_t(face_cells_.size());
  }

  /// chi_c(M inside c) - (traced faces in c) for every cell, as a map of the cells
  /// where it is not zero: zero where the surface is a set of disks each bounded by
  /// one traced cycle.
  Cell_map count_per_cell()
  {
    index_cells();
    std::vector<long> excess(cell_index_.size(), 0);
    auto excess_of = [&](const Levels& c) -> long& {
      const std::uint32_t id = cell_index_.id_of(c);
      if(id >= excess.size())
        excess.resize(id + 1, 0);
      return excess[id];
    };
    std::vector<std::uint32_t> edge_cells;
    Work_meter meter(*progress_, Remeshing_stage::TOPOLOGY_CHECK);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      meter.add(1 + face_start_[f + 1] - face_start_[f], [&] { return 0.2 + 0.5 * f / number_of_faces_; });
      for(std::uint32_t x = face_start_[f]; x < face_start_[f + 1]; ++x)
        ++excess[face_cells_[x]];
      if(is_lost(f))
        continue;
      const auto& corners = input_.corners_of(f);
      for(int e = 0; e < 3; ++e)
        if(owns_edge(f, e)) {
          edge_cells.clear();
          const std::uint32_t a = vertex_cell_[corners[e]], b = vertex_cell_[corners[(e + 1) % 3]];
          add_once(edge_cells, a);
          add_once(edge_cells, b);
          add_each_once(crossings_begin(3 * std::size_t(f) + e), crossings_end(3 * std::size_t(f) + e), edge_cells, 0);
          remove_repeats(edge_cells);
          for(std::uint32_t id : edge_cells)
            --excess[id];
        }
    }
    for(std::uint32_t id : vertex_cell_)
      if(id != none)
        ++excess[id];
    for(const auto& corner : complex_.traced_face_corners()) {
      meter.add(1, 0.7);
      --excess_of(cell_of_traced_face(corner));
    }
    add_border_pieces([&](const Levels& c) { ++excess_of(c); });
    Cell_map nonzero;
    for(std::uint32_t id = 0; id < excess.size(); ++id)
      if(excess[id] != 0)
        nonzero.emplace(cell_index_.cell(id), excess[id]);
    return nonzero;
  }

  /// The loops' faces, as seeds of both their cells.
  Seeds seeds_of_loops() const
  {
    Seeds seeds;
    for(const Loop& loop : loops_) {
      auto& above = seeds[loop.cell];
      auto& below = seeds[cell_below(loop)];
      above.insert(above.end(), loop.faces.begin(), loop.faces.end());
      below.insert(below.end(), loop.faces.begin(), loop.faces.end());
    }
    return seeds;
  }

  /// The excesses of the two cells of every loop, counted in those cells only.
  Cell_map count_in_cells_of_loops()
  {
    Seeds seeds = seeds_of_loops();
    Cell_map excess;
    count_in_cells(seeds, unlimited, excess, nullptr);
    return excess;
  }

  /// The cells where a region may have excess above zero (those of loops) or may be
  /// bounded by several traced cycles (those of two traced faces or more): with no
  /// lost piece, every other cell holds regions bounded by one traced cycle each,
  /// of excess 0 (a disk) or below (a handle inside the cell).
  Seeds seeds_of_suspect_cells(std::size_t& traced_in_suspects) const
  {
    Seeds seeds = seeds_of_loops();
    Cell_index<Levels> traced_cells;
    std::vector<std::uint32_t> traced_faces;
    for(const auto& corner : complex_.traced_face_corners()) {
      const Levels c = cell_of_traced_face(corner);
      const std::uint32_t id = traced_cells.id_of(c);
      if(id == traced_faces.size())
        traced_faces.push_back(0);
      if(++traced_faces[id] == 2)
        seeds[c];
    }
    traced_in_suspects = 0;
    for(std::uint32_t n : traced_faces)
      traced_in_suspects += n >= 2 ? n : 0;
    return seeds;
  }

  /// The excesses of the suspect cells, in `excess`, and the faces meeting each, in
  /// `faces_in_suspect_cells_`; whether they add up to the total over all cells,
  /// chi(M) - chi(traced). Then the other cells, of excess 0 or below, are all 0.
  /// False too, without counting, when the suspect cells hold more than a third of
  /// the traced faces, or after visiting as many faces as the input has: a face
  /// meets many cells of a fine grid, and counting cell by cell would then cost
  /// more than the count of all cells, which takes each face once.
  bool count_in_suspect_cells(long total, Cell_map& excess)
  {
    std::size_t traced_in_suspects = 0;
    Seeds seeds = seeds_of_suspect_cells(traced_in_suspects);
    if(3 * traced_in_suspects > complex_.traced_face_corners().size() ||
       !count_in_cells(seeds, number_of_faces_, excess, &faces_in_suspect_cells_))
      return false;
    long sum = 0;
    for(const auto& entry : excess)
      sum += entry.second;
    return sum == total;
  }

  /// The excesses of the seeded cells, from the input faces meeting them only: those
  /// reached from the seeds and the traced faces' vertices in them, across edges
  /// meeting the cell (a region is connected through them). Each region must hold a
  /// seed or bound a traced face of the cell. Lists the faces meeting each cell in
  /// `faces_meeting` if given. False if it stopped after visiting `budget` faces.
  bool count_in_cells(Seeds& seeds, std::size_t budget, Cell_map& excess, Seeds* faces_meeting)
  {
    index_vertices_by_face();
    const auto& vertices = tracer_.intersection_vertices();
    for(const auto& corner : complex_.traced_face_corners()) {
      const auto found = seeds.find(cell_of_traced_face(corner));
      if(found != seeds.end()) {
        found->second.push_back(vertices[corner.halfedge / 4].face_id);
        --excess[found->first];
      }
    }
    Flood flood(number_of_faces_, input_.number_of_input_vertices(), budget);
    for(auto& entry : seeds) {
      excess[entry.first] += count_in_cell(entry.first, entry.second, flood);
      if(flood.budget == 0)
        return false;
      if(faces_meeting)
        (*faces_meeting)[entry.first] = flood.region;
    }
    const Cell_map seeded = excess;
    add_border_pieces([&](const Levels& c) {
      if(seeded.count(c))
        ++excess[c];
    });
    return true;
  }

  /// Scratch of count_in_cell(): marks by face and by vertex, cleared after each cell.
  struct Flood
  {
    Flood(std::size_t faces, std::size_t vertices, std::size_t limit)
      : in_region(faces, 0), vertex_counted(vertices, 0), budget(limit)
    {}
    std::vector<std::uint8_t> in_region, vertex_counted;
    std::size_t budget; // faces left to visit
    std::vector<std::uint32_t> region, stack, counted_vertices;
  };

  /// #faces - #edges + #vertices meeting cell c, over the faces reached from
  /// `seeds` (those meeting c) across edges meeting c; the faces in `flood.region`.
  long count_in_cell(const Levels& c, const std::vector<std::uint32_t>& seeds, Flood& flood) const
  {
    flood.region.clear();
    flood.counted_vertices.clear();
    for(std::uint32_t f : seeds)
      if(!flood.in_region[f] && face_meets(f, c)) {
        flood.in_region[f] = 1;
        flood.stack.push_back(f);
      }
    long excess = 0;
    while(!flood.stack.empty()) {
      if(flood.budget == 0) { // give up; unmark the faces met
        flood.region.insert(flood.region.end(), flood.stack.begin(), flood.stack.end());
        flood.stack.clear();
        break;
      }
      --flood.budget;
      const std::uint32_t f = flood.stack.back();
      flood.stack.pop_back();
      flood.region.push_back(f);
      ++excess;
      const auto& corners = input_.corners_of(f);
      for(int e = 0; e < 3; ++e) {
        if(!edge_meets(corners[e], corners[(e + 1) % 3], c))
          continue;
        const std::uint32_t n = input_.neighbours_of(f)[e];
        if(n == Input::border || n > f) // each edge once (both its faces meet c)
          --excess;
        if(n != Input::border && !flood.in_region[n]) {
          flood.in_region[n] = 1;
          flood.stack.push_back(n);
        }
      }
      for(std::uint32_t v : corners)
        if(!flood.vertex_counted[v] && vertex_in(v, c)) {
          flood.vertex_counted[v] = 1;
          flood.counted_vertices.push_back(v);
          ++excess;
        }
    }
    for(std::uint32_t f : flood.region)
      flood.in_region[f] = 0;
    for(std::uint32_t v : flood.counted_vertices)
      flood.vertex_counted[v] = 0;
    return excess;
  }

  /// A closed loop whose two cells hold no other loop and have excesses +1 and -1
  /// only cuts a cap off: the +1 is a disk bounded by the loop alone (any other
  /// region bounded by it, or one with a traced cycle too, has an excess below 1,
  /// and the other regions of the cell at most 0), and gluing it across the loop
  /// makes the other cell's regions disks (their excesses, at most 0 each, then sum
  /// to 0). The output, which covers the loop by the face of the other cell, then
  /// has the input's topology. Marks those loops harmless, and their cells zero.
  std::size_t absorb_caps(Cell_map& excess)
  {
    std::unordered_map<Levels, int, Levels_hash<Levels>> loops_per_cell;
    for(const Loop& loop : loops_) {
      ++loops_per_cell[loop.cell];
      ++loops_per_cell[cell_below(loop)];
    }
    std::size_t harmless = 0;
    for(Loop& loop : loops_) {
      long& above = excess[loop.cell];
      long& below = excess[cell_below(loop)];
      if(loops_per_cell[loop.cell] == 1 && loops_per_cell[cell_below(loop)] == 1 && above + below == 0 &&
         (above == 1 || below == 1)) {
        above = below = 0;
        loop.harmless = true;
        ++harmless;
      }
    }
    return harmless;
  }

  static Levels cell_below(const Loop& loop)
  {
    Levels c = loop.cell;
    --c[loop.axis];
    return c;
  }

  /// Reports the cells of nonzero excess (in the order of their levels), with the
  /// faces meeting them; their number. Those cells have ids: count_per_cell() met them.
  std::size_t locate_non_disk_cells(const Cell_map& excess)
  {
    const std::vector<Levels> cells = add_non_disk_cells(excess);
    if(cells.empty())
      return 0;
    std::vector<std::size_t> defect_of_id(cell_index_.size(), std::size_t(-1));
    for(std::size_t k = 0; k < cells.size(); ++k)
      defect_of_id[cell_index_.id_of(cells[k])] = defects_.size() - cells.size() + k;
    Work_meter meter(*progress_, Remeshing_stage::TOPOLOGY_CHECK);
    for(std::uint32_t f = 0; f < number_of_faces_; ++f) {
      meter.add(1 + face_start_[f + 1] - face_start_[f], [&] { return 0.7 + 0.3 * f / number_of_faces_; });
      for(std::uint32_t x = face_start_[f]; x < face_start_[f + 1]; ++x) {
        const std::size_t d = defect_of_id[face_cells_[x]];
        if(d != std::size_t(-1))
          defects_[d].input_faces.push_back(input_.face_of_id(f));
      }
    }
    return cells.size();
  }

  /// The same from the faces count_in_suspect_cells() found in each suspect cell:
  /// the cells of nonzero excess are among them.
  std::size_t locate_non_disk_suspect_cells(const Cell_map& excess)
  {
    const std::vector<Levels> cells = add_non_disk_cells(excess);
    for(std::size_t k = 0; k < cells.size(); ++k) {
      std::vector<std::uint32_t>& faces = faces_in_suspect_cells_[cells[k]];
      std::sort(faces.begin(), faces.end()); // in face order, as a scan would list them
      Defect& d = defects_[defects_.size() - cells.size() + k];
      for(std::uint32_t f : faces)
        d.input_faces.push_back(input_.face_of_id(f));
    }
    return cells.size();
  }

  /// Adds a defect without faces for each cell of nonzero excess, in the order of
  /// their levels, and returns those cells in that order.
  std::vector<Levels> add_non_disk_cells(const Cell_map& excess)
  {
    std::vector<Levels> cells;
    for(const auto& entry : excess)
      if(entry.second != 0)
        cells.push_back(entry.first);
    std::sort(cells.begin(), cells.end());
    for(const Levels& c : cells)
      add_defect(Topology_defect_kind::NON_DISK_CELL, c, std::vector<std::uint32_t>());
    return cells;
  }

  const Progress* progress_ = &Progress::none();
  Tracer& tracer_;
  Input& input_;
  Closed_loops<Input> closed_loops_;
  const Primal_complex& complex_;
  std::uint32_t number_of_faces_;
  std::vector<std::uint32_t> component_;     // by face id
  std::vector<std::uint8_t> lost_component_; // by component
  long input_euler_characteristic_ = 0;
  std::vector<std::uint32_t> vertex_start_, vertices_by_face_; // intersection vertices by face
  Cell_index<Levels> cell_index_;
  std::vector<std::uint32_t> vertex_cell_;                     // cell id by input vertex
  std::vector<std::uint32_t> crossing_start_, crossing_cells_; // by slot 3 face + edge, at the owning face
  std::vector<std::uint32_t> face_start_, face_cells_;         // cell ids by face
  Seeds faces_in_suspect_cells_;                                // by cell, when only those were counted
  std::vector<Loop> loops_;
  std::vector<Defect> defects_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_TOPOLOGY_CHECK_H
