// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_SAMPLER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_SAMPLER_H

// Where the output puts an intersection vertex on the input surface: its triangle's
// corners and its barycentric coordinates there, which the output interpolates (the
// position, and whatever else the input carries, e.g. colours). The output reads
// them for every vertex in order, and the triangles lie anywhere in the input: the
// prefetching hooks let it ask for them a few vertices ahead.

#include <CGAL/Range_space_remeshing/internal/Barycentric.h>
#include <CGAL/Range_space_remeshing/internal/Intersection_vertices.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>
#include <CGAL/Range_space_remeshing/internal/Prefetch.h>

#include <algorithm>
#include <array>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Input>
class Vertex_sampler
{
  using Vertex = Intersection_vertex<Input::D>;
  using Predicates = Perturbed_predicates<typename Input::Traits>;
  using vertex_descriptor = typename Input::vertex_descriptor;

public:
  explicit Vertex_sampler(Input& input) : input_(input) {}

  /// The input corners of the intersection vertex's triangle, in the order of
  /// `barycentric_coordinates()`: read from its record, which holds them already
  /// (where going through the mesh from the face would read four more places).
  std::array<vertex_descriptor, 3> corners_of(const Vertex& v) const { return corners_of_face(v.face_id); }
  /// The same for a recorded face.
  std::array<vertex_descriptor, 3> corners_of_face(std::uint32_t face_id) const
  {
    const auto& corners = input_.corners_of(face_id);
    return {{input_.vertex_of_id(corners[0]), input_.vertex_of_id(corners[1]), input_.vertex_of_id(corners[2])}};
  }

  /// Asks for the record of the vertex's triangle: the first of what
  /// `barycentric_coordinates()` and `corners_of()` read, and the one that says where
  /// the rest is (see `prefetch_corners_of()`, a few vertices later).
  void prefetch_record_of(const Vertex& v) const { prefetch(&input_.record_of(v.face_id)); }

  /// Asks for the rest, once the record is in the cache: the mapped corners and their
  /// descriptors.
  void prefetch_corners_of(const Vertex& v) const
  {
    input_.prefetch_corners(v.face_id);
    input_.prefetch_corner_handles(v.face_id);
  }

  /// Barycentric coordinates of the intersection vertex in its triangle, in the
  /// order source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))).
  std::array<double, 3> barycentric_coordinates(const Vertex& v) const
  {
    const auto t = input_.load(v.face_id);
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

private:
  Input& input_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_SAMPLER_H
