// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_PARAMETERS_H
#define CGAL_RANGE_SPACE_REMESHING_PARAMETERS_H

// Named parameters of the package.
//
// CGAL's list of named-parameter tags is closed, so a package outside CGAL cannot
// add a chainable `.range_map()` member. The package therefore
// * reuses CGAL's tags where the meaning fits: `grid_spacing` (the cell size),
//   `seeding_method`, `maximum_number` (cap on output vertices), `geom_traits`,
//   `vertex_point_map`, `vertex_normal_map`;
// * adds its own tags as free functions that start a pack, onto which CGAL's
//   tags chain as usual: `range_map(f).grid_spacing(h)`. Each of them optionally
//   takes an existing pack to extend: `grid_origin(o, range_map(f).grid_spacing(h))`.

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Range_space_remeshing {

/// How intersection vertices are found before tracing.
enum class Seeding_method
{
  /// Scan every input triangle for grid edges: finds every piece of the
  /// intersection, linear in the input size. The default.
  COMPLETE_SCAN,
  /// Start from one seed per input connected component (or from the faces given
  /// by `seed_faces()`) and trace from there: only the triangles the arcs cross are
  /// mapped, so the cost is sublinear in the input. May miss output pieces that are
  /// not connected to a seed.
  SEEDED
};

/// Where `dualize()` puts the dual vertex of a primal face.
enum class Dual_placement
{
  /// the average of the face's vertices, with the normalised average normal
  AVERAGE,
  /// the minimiser of the squared distances to the tangent planes of the face's
  /// vertices (dual contouring's quadric error, solved robustly). The default.
  QEM,
  /// the same minimiser, but keeping the corners and crease lines that the tangent
  /// planes pin even weakly (as those of a mesh prepared by `insert_crease_triangles()`
  /// do, where creases meet), and moved into the kernel of the face's polygon (where it
  /// sees every corner of the face): the dual quads then follow creases around corners
  /// instead of bridging the notches between them. A face whose polygon encloses nothing
  /// (inside an opened crease) gets the point of its sides nearest to the minimiser; a
  /// face whose polygon turns against its vertices' normals (around a concave corner,
  /// where that polygon is the notch) gets its corner nearest to it. On smooth inputs it
  /// scatters vertices more than `QEM` and leaves fewer quads for the collapse to
  /// regularise.
  SHARP_FEATURES
};

namespace internal_np {
enum range_map_t { range_map };
enum grid_origin_t { grid_origin };
enum seed_faces_t { seed_faces };
enum dual_placement_t { dual_placement };
enum vertex_tangent_planes_map_t { vertex_tangent_planes_map };
enum vertex_crease_normal_map_t { vertex_crease_normal_map };
enum quad_collapse_t { quad_collapse };
enum check_topology_t { check_topology };
enum preserve_topology_t { preserve_topology };
enum topology_visitor_t { topology_visitor };
} // namespace internal_np

namespace parameters {

#define CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(NAME)                              \
  template <class T>                                                               \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)     \
  {                                                                                \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(value);        \
  }                                                                                \
  template <class T, class NP_T, class NP_Tag, class NP_Base>                      \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t,                        \
                                  CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>> \
  NAME(const T& value, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& base) \
  {                                                                                \
    return {value, base};                                                          \
  }

/// The map f: a readable property map, vertex -> point of the range space
/// (`std::array<double, D>`). Default: the identity (vertex positions, D = 3).
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(range_map)
/// Origin of the grid in the range space (`std::array<double, D>`). Default: 0.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(grid_origin)
/// Faces to start from in `Seeding_method::SEEDED` (a range of face descriptors).
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(seed_faces)

/// `Dual_placement` of `dualize()`. Default: `Dual_placement::QEM`.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(dual_placement)
/// A read-write property map, dual vertex -> `Tangent_planes`: the tangent planes
/// of the primal face, written by `dualize()` and read by `relax_on_tangent_planes()`.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(vertex_tangent_planes_map)
/// A property map, primal vertex -> vector: at a vertex that `primal_remesh()` puts
/// inside an opened crease (a zero-area triangle of `insert_crease_triangles()`), the
/// unit normal of the crease's other side, the null vector elsewhere. Written by
/// `primal_remesh()` (`np_out`), read by `dualize()` (`np_in`), which gives such a
/// vertex the tangent planes of both sides: a crease, not a bend.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(vertex_crease_normal_map)
/// Whether `remesh()` runs `collapse_quads()` between the dual and the relaxation
/// (`bool`). Default: `true`.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(quad_collapse)

/// Whether `primal_remesh()` checks that its output has the topology of the input
/// (`bool`, complete scan only): fills the topology fields of `Statistics` and
/// reports each `Topology_defect` to the `topology_visitor`. Default: `false`.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(check_topology)
/// Whether `primal_remesh()` reduces the cell size until the topology check finds
/// no defect (`bool`, complete scan only; implies `check_topology`). Default: `false`.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(preserve_topology)
/// A callable taking a `const Topology_defect<face_descriptor>&`, called for each
/// defect the topology check finds in the output. Default: none.
CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER(topology_visitor)

#undef CGAL_RANGE_SPACE_REMESHING_NAMED_PARAMETER

} // namespace parameters
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_PARAMETERS_H
