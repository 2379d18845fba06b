// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_ARC_TRACER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_ARC_TRACER_H

// Section 4 of the paper: the arcs, the curves where the mapped surface meets a grid
// face, traced from an intersection vertex triangle by triangle. An arc lies in one
// hyperplane x_P = level and in the open box of the cell it leaves its vertex into;
// in each triangle it crosses, the exact predicates tell through which edge it
// leaves and whether it meets a wall of its box first: there it ends, at the
// intersection vertex of that wall's grid edge. An arc can also leave the surface
// through the border, at a boundary vertex.

#include <CGAL/Range_space_remeshing/internal/Border_crossings.h>
#include <CGAL/Range_space_remeshing/internal/Intersection_vertices.h>
#include <CGAL/Range_space_remeshing/internal/Lattice.h>
#include <CGAL/Range_space_remeshing/internal/Level_differences.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>
#include <CGAL/Range_space_remeshing/internal/Prefetch.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Untraced_pieces.h>

#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <algorithm>
#include <array>
#include <cstdint>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The ccw edge of `t` through which the curve of x_P = level leaves, with the side
/// u_P > level on its left if sigma = +1, on its right if sigma = -1.
template <class Triangle>
int exit_edge(const Triangle& t, int P, std::int32_t level, int sigma)
{
  int side[3]; // u_P > level iff ceil(u_P) > level: ties count as below
  for(int e = 0; e < 3; ++e)
    side[e] = (*t.c[e])[P] > level ? 1 : -1;
  for(int e = 0; e < 3; ++e)
    if(side[e] == -sigma && side[(e + 1) % 3] == sigma)
      return e;
  CGAL_error_msg("Range_space_remeshing: arc lost its plane");
}

template <class Input>
class Arc_tracer
{
  static constexpr int D = Input::D;
  using Point_d = typename Input::Point_d;
  using Levels = typename Input::Levels;
  using Triangle = typename Input::Triangle;
  using Vertex = Intersection_vertex<D>;
  using Predicates = Perturbed_predicates<typename Input::Traits>;

  /// An arc being traced: its plane x_P = level, the box it stays in, and the side
  /// of its travel direction the side u_P > level lies on.
  struct Arc
  {
    int P;
    std::int32_t level;
    int T = -1;   // the axis of the wall it starts on (none for an arc from the border)
    int dir = 0;  // the direction it leaves that wall in
    int sigma;    // +1: u_P > level lies left of the travel direction
    Levels lo, hi;
    std::array<double, D> lo_wall, hi_wall;
    Levels not_P; // all bits set but in axis P: masks P out
  };

  struct Wall
  {
    int axis = -1;
    std::int32_t level = 0;
    int up = 0; // +1: upper wall of the box in this axis, -1: lower wall
  };

public:
  Arc_tracer(Input& input, Intersection_vertices<D>& vertices, Border_crossings<Input>& border,
             Untraced_pieces& pieces, const Predicates& predicates)
    : input_(input), vertices_(vertices), border_(border), pieces_(pieces), predicates_(predicates)
  {}

  /// Traces every arc of every queued vertex; vertices met at arc ends are created
  /// when `create_at_arc_ends`, and must already exist otherwise (complete scan).
  void trace(bool create_at_arc_ends, const Progress& progress)
  {
    Work_meter meter(progress, Remeshing_stage::TRACE);
    std::size_t steps_before = tracing_steps_;
    for(std::size_t traced = 0; vertices_.has_queued(); ++traced) {
      // the work: the steps of the arcs (one face each); the queue holds every vertex
      // after a complete scan, the seeded tracing adds more
      meter.add(1 + tracing_steps_ - steps_before,
                [&] { return double(traced) / double(traced + vertices_.number_queued()); });
      steps_before = tracing_steps_;
      trace_arcs_of(vertices_.pop_queued(), create_at_arc_ends);
    }
    border_.add_corners_to_two_vertex_holes();
  }

  std::size_t number_of_tracing_steps() const { return tracing_steps_; }

  /// A point of the surface: a triangle and barycentric coordinates there.
  struct Surface_point
  {
    std::uint32_t face_id;
    std::array<double, 3> w;
  };

  /// A point of the arc leaving the (inner) vertex `v`, at barycentric coordinates
  /// `w_v` in its triangle, through `slot`: halfway along the first piece of the arc
  /// of non-zero length (its piece in v's triangle, unless v lies on the edge it leaves
  /// by), up to where it leaves that triangle or meets a wall of its box. The output
  /// splits a parallel edge there (see Primal_output.h): a point of the surface inside
  /// the cell of the faces on the arc's sides. Doubles only: it places a vertex, it
  /// decides nothing.
  Surface_point point_along_arc(const Vertex& v, int slot, const std::array<double, 3>& w_v)
  {
    const Arc arc = start_arc(v, slot);
    Surface_point from{v.face_id, w_v};
    for(std::size_t step = 0; step <= num_faces(input_.mesh()); ++step) {
      const Triangle t = input_.load(from.face_id);
      const int e = exit_edge(t, arc.P, arc.level, arc.sigma);
      const double s = (std::min)((std::max)(Predicates::crossing_parameter(*t.p[e], *t.p[(e + 1) % 3], arc.P,
                                                                            double(arc.level)), 0.), 1.);
      std::array<double, 3> exit = {{0, 0, 0}};
      exit[e] = 1 - s;
      exit[(e + 1) % 3] = s;
      const double reach = part_inside_box(t, arc, from.w, exit);
      double length = 0; // of the piece, in barycentric coordinates
      for(int c = 0; c < 3; ++c)
        length = (std::max)(length, reach * std::abs(exit[c] - from.w[c]));
      const std::uint32_t next = input_.record_of(from.face_id).neighbour[e];
      if(length > 1e-9 || reach < 1 || next == Input::border) {
        for(int c = 0; c < 3; ++c)
          from.w[c] += 0.5 * reach * (exit[c] - from.w[c]);
        return from;
      }
      input_.load(next); // recorded (the arc went through it), but say so
      from = {next, same_point_across(from.face_id, e, s, next)};
    }
    return from;
  }

private:
  /// The part of the way from `from` to `to` (barycentric coordinates in t) before the
  /// arc meets a wall of its box.
  double part_inside_box(const Triangle& t, const Arc& arc, const std::array<double, 3>& from,
                         const std::array<double, 3>& to) const
  {
    double reach = 1;
    for(int q = 0; q < D; ++q) {
      if(q == arc.P)
        continue;
      double a = 0, b = 0;
      for(int c = 0; c < 3; ++c) {
        a += from[c] * (*t.p[c])[q];
        b += to[c] * (*t.p[c])[q];
      }
      if(a == b)
        continue;
      const double r = ((b > a ? arc.hi_wall[q] : arc.lo_wall[q]) - a) / (b - a);
      if(r > 0 && r < reach)
        reach = r;
    }
    return reach;
  }

  /// The point at parameter s of edge e of face f (from corner e to corner e + 1), in
  /// barycentric coordinates of its neighbour g across that edge.
  std::array<double, 3> same_point_across(std::uint32_t f, int e, double s, std::uint32_t g) const
  {
    const auto& corners = input_.corners_of(f);
    const auto& other = input_.corners_of(g);
    std::array<double, 3> w = {{0, 0, 0}};
    for(int c = 0; c < 3; ++c) {
      if(other[c] == corners[e])
        w[c] = 1 - s;
      else if(other[c] == corners[(e + 1) % 3])
        w[c] = s;
    }
    return w;
  }

  void trace_arcs_of(std::uint32_t v, bool create_at_arc_ends)
  {
    if(!vertices_[v].has_cell)
      locate_vertex_in_cell(predicates_, input_.load(vertices_[v].face_id), vertices_[v]);
    if(vertices_[v].is_boundary()) {
      if(vertices_[v].link[boundary_arc_slot] == no_link)
        trace_and_link(v, boundary_arc_slot, create_at_arc_ends);
      border_.link_along_border(v);
      return;
    }
    for(int slot = 0; slot < 4; ++slot)
      if(vertices_[v].link[slot] == no_link)
        trace_and_link(v, slot, create_at_arc_ends);
  }

  void trace_and_link(std::uint32_t v, int slot, bool create_at_arc_ends)
  {
    std::uint32_t end;
    int end_slot;
    trace_arc(v, slot, create_at_arc_ends, end, end_slot);
    vertices_.link(v, slot, end, end_slot);
  }

  /// The arc leaving v through `slot`, in the box of v's cell on that side.
  Arc start_arc(const Vertex& v, int slot)
  {
    Arc arc;
    const bool from_border = v.is_boundary();
    const bool along_i = (slot % 2 == 0);
    arc.P = from_border ? v.i : (along_i ? v.j : v.i);
    arc.level = v.cell[arc.P];
    if(!from_border) {
      arc.T = along_i ? v.i : v.j;
      arc.dir = slot < 2 ? 1 : -1;
    }
    // An arc from the border enters its triangle through the border edge e, so that
    // edge goes from the side +sigma to -sigma.
    arc.sigma = from_border ? ((*input_.load(v.face_id).c[v.border_edge])[arc.P] > arc.level ? 1 : -1)
                            : ((slot == 0 || slot == 3) ? v.orientation : -v.orientation);
    for(int q = 0; q < D; ++q) {
      arc.lo[q] = v.cell[q];
      arc.hi[q] = v.cell[q] + 1;
    }
    if(arc.dir < 0) {
      arc.lo[arc.T] = v.cell[arc.T] - 1;
      arc.hi[arc.T] = v.cell[arc.T];
    }
    for(int q = 0; q < D; ++q) {
      arc.lo_wall[q] = double(arc.lo[q]);
      arc.hi_wall[q] = double(arc.hi[q]);
      arc.not_P[q] = q == arc.P ? 0 : -1;
    }
    return arc;
  }

  void trace_arc(std::uint32_t start, int slot, bool create_at_arc_ends, std::uint32_t& end, int& end_slot)
  {
    const Arc arc = start_arc(vertices_[start], slot); // a copy of what it needs: vertices_ may grow below
    std::uint32_t f = vertices_[start].face_id;
    const std::size_t maximum_steps = num_faces(input_.mesh()) + 1;
    for(std::size_t step = 0;; ++step) {
      if(step > maximum_steps)
        CGAL_error_msg("Range_space_remeshing: endless arc");
      ++tracing_steps_;
      pieces_.remove_arc_visit(f);
      const Triangle t = input_.load(f);
      // The arc's next face is one of these: its record (the step's first wait for
      // memory, as the faces around an arc lie anywhere in the input's order) is on
      // its way while this face's tests run.
      const auto& neighbours = input_.record_of(f).neighbour;
      for(std::uint32_t n : neighbours)
        if(n != Input::border)
          prefetch(&input_.record_of(n));
      const int e = exit_edge(t, arc.P, arc.level, arc.sigma);
      const Wall first = first_wall_met(t, e, arc, step);
      if(first.axis >= 0) {
        finish_arc(t, arc, first, create_at_arc_ends, end, end_slot);
        return;
      }
      if(neighbours[e] == Input::border) {
        finish_arc_at_border(t, e, arc, end, end_slot);
        return;
      }
      f = neighbours[e];
    }
  }

  /// The wall of the arc's box that the arc meets first in t before it leaves through
  /// edge e, if any.
  Wall first_wall_met(const Triangle& t, int e, const Arc& arc, std::size_t step) const
  {
    const Point_d& a = *t.p[e];
    const Point_d& b = *t.p[(e + 1) % 3];
    const double t_exit = Predicates::crossing_parameter(a, b, arc.P, double(arc.level));
    // An axis in which both ends of the exit edge lie strictly between the walls
    // (ceiling = hi: lo < u <= hi, strictly inside the perturbed walls) has the
    // crossing point, between them, inside too: crossing_slab_side() would return
    // 0. That leaves out most axes, in one pass over the integer levels (with the
    // walls of the first triangle kept: without one, an axis inside stays inside).
    std::uint32_t candidates = masked_level_differences(*t.c[e], *t.c[(e + 1) % 3], arc.hi, arc.not_P);
    Wall first;
    for(; candidates != 0; candidates &= candidates - 1) {
      const int l = lowest_set_bit(candidates);
      // In the first triangle the arc cannot cross back the wall it starts on.
      const bool skip_lo = (step == 0 && l == arc.T && arc.dir > 0);
      const bool skip_hi = (step == 0 && l == arc.T && arc.dir < 0);
      const int where = predicates_.crossing_slab_side(a, b, arc.P, arc.level, t_exit, l,
                                                       skip_lo ? -infinity : arc.lo_wall[l],
                                                       skip_hi ? infinity : arc.hi_wall[l]);
      if(where == 0)
        continue;
      const Wall crossed = where < 0 ? Wall{l, arc.lo[l], -1} : Wall{l, arc.hi[l], +1};
      if(first.axis < 0 || predicates_.is_met_first(*t.p[0], *t.p[1], *t.p[2], arc.P, arc.level, crossed.axis,
                                                     crossed.level, first.axis, first.level, first.up))
        first = crossed;
    }
    return first;
  }

  /// The arc leaves the surface through border edge e of t, inside its box.
  void finish_arc_at_border(const Triangle& t, int e, const Arc& arc, std::uint32_t& end, int& end_slot)
  {
    border_.crossings(t.face_id, e); // creates the edge's boundary vertices if need be
    end = vertices_.find_boundary(t.face_id, e, arc.P, arc.level);
    if(end == no_link)
      CGAL_error_msg("Range_space_remeshing: arc ends at no boundary vertex");
    end_slot = boundary_arc_slot;
    CGAL_USE(arc); // read by the assertion only
    CGAL_assertion_code(const Vertex& ev = vertices_[end];)
    CGAL_assertion_code(for(int q = 0; q < D; ++q))
    CGAL_assertion(q == arc.P || ev.cell[q] == arc.lo[q]);
  }

  /// The arc ends on `wall`, at the intersection vertex of the grid edge where the
  /// wall meets the arc's plane.
  void finish_arc(const Triangle& t, const Arc& arc, const Wall& wall, bool create_at_arc_ends, std::uint32_t& end,
                  int& end_slot)
  {
    const int P = arc.P, w = wall.axis;
    const int i = (std::min)(P, w), j = (std::max)(P, w);
    const std::int32_t k = (i == P) ? arc.level : wall.level;
    const std::int32_t m = (i == P) ? wall.level : arc.level;
    // The arc reaches the end vertex travelling along w towards the wall; leaving
    // the vertex along it goes the other way, -up.
    end_slot = (w == i ? 0 : 1) + (wall.up > 0 ? 2 : 0);

    if(create_at_arc_ends) {
      const int o = predicates_.projected_orientation(*t.p[0], *t.p[1], *t.p[2], i, j);
      end = vertices_.find_or_create(t.face_id, i, j, k, m, o, true);
    } else {
      end = vertices_.find(t.face_id, i, j, k, m);
      if(end == no_link)
        CGAL_error_msg("Range_space_remeshing: arc ends at an unscanned vertex");
    }
    CGAL_assertion(predicates_.grid_edge_orientation(*t.p[0], *t.p[1], *t.p[2], i, j, double(k), double(m)) != 0);
    // The end vertex lies in the arc's box, strictly inside in every other axis.
    Vertex& ev = vertices_[end];
    if(!ev.has_cell) {
      for(int q = 0; q < D; ++q)
        if(q != i && q != j)
          ev.cell[q] = arc.lo[q];
      ev.has_cell = true;
    } else {
      CGAL_assertion_code(for(int q = 0; q < D; ++q))
      CGAL_assertion(q == i || q == j || ev.cell[q] == arc.lo[q]);
    }
  }

  Input& input_;
  Intersection_vertices<D>& vertices_;
  Border_crossings<Input>& border_;
  Untraced_pieces& pieces_;
  const Predicates& predicates_;
  std::size_t tracing_steps_ = 0;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_ARC_TRACER_H
