// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_REMESHING_STAGE_H
#define CGAL_RANGE_SPACE_REMESHING_REMESHING_STAGE_H

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

The stages that a `progress_visitor` is told about, in the order in which a run of
`remesh()` goes through them. A stage may be reported again when the run repeats
(`preserve_topology` shrinks the cell size, `number_of_target_vertices` searches it).
*/
enum class Remeshing_stage
{
  /// Mapping the input by f and finding where it crosses the grid's edges.
  SCAN,
  /// Tracing the arcs between crossings, across the input's triangles.
  TRACE,
  /// Checking that the primal remesh has the input's topology.
  TOPOLOGY_CHECK,
  /// Writing the primal remesh into its mesh.
  PRIMAL_OUTPUT,
  /// `dualize()`.
  DUAL,
  /// `collapse_quads()`.
  COLLAPSE,
  /// `relax_on_tangent_planes()`.
  RELAXATION
};

/// The stage's name, in lower case (`"scan"`, `"trace"`, ...), for messages.
inline const char* stage_name(Remeshing_stage stage)
{
  switch(stage) {
  case Remeshing_stage::SCAN: return "scan";
  case Remeshing_stage::TRACE: return "trace";
  case Remeshing_stage::TOPOLOGY_CHECK: return "topology check";
  case Remeshing_stage::PRIMAL_OUTPUT: return "primal output";
  case Remeshing_stage::DUAL: return "dual";
  case Remeshing_stage::COLLAPSE: return "collapse";
  case Remeshing_stage::RELAXATION: return "relaxation";
  }
  return "unknown";
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_REMESHING_STAGE_H
