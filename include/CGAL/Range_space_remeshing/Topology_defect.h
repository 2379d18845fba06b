// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_TOPOLOGY_DEFECT_H
#define CGAL_RANGE_SPACE_REMESHING_TOPOLOGY_DEFECT_H

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef
The ways in which the primal remesh can differ topologically from its input at a
given cell size (see `Topology_defect`).
*/
enum class Topology_defect_kind
{
  /// the surface meets a grid hyperplane in a closed curve that reaches no grid
  /// edge: no arc traces it, so the output does not separate the two sides
  CLOSED_LOOP,
  /// the surface inside a cell is not a set of disks each bounded by one traced
  /// cycle: a tube through the cell (a thin part, a handle), a handle inside it, a
  /// hole inside it, or a closed loop on its side. The output has one face per
  /// traced cycle, so its topology differs there
  NON_DISK_CELL,
  /// an input component that gives no output: it lies in one cell, or only closed
  /// loops cross it
  LOST_COMPONENT,
  /// a border cycle of the input inside one cell: the output covers the hole
  LOST_BORDER_CYCLE
};

/*!
\ingroup PkgRangeSpaceRemeshingRef
Where the primal remesh is not topologically faithful to the input, as reported to
the `topology_visitor` by `primal_remesh()` (named parameter `check_topology`).

The cell with lattice coordinates `cell` holds the points x of the range space with
`cell[q] < (x[q] - origin[q]) / h <= cell[q] + 1` in every axis q, up to the
symbolic perturbation of the grid (h the cell size).
*/
template <class FaceDescriptor>
struct Topology_defect
{
  Topology_defect_kind kind = Topology_defect_kind::NON_DISK_CELL;
  /// the cell concerned: for `CLOSED_LOOP`, the cell just above the grid face that
  /// holds the loop, in `axis`; for `LOST_COMPONENT` and `LOST_BORDER_CYCLE`, the
  /// cell of one of their vertices
  std::vector<std::int32_t> cell;
  /// `CLOSED_LOOP`: the loop lies in the hyperplane of axis `axis` between `cell`
  /// and the cell below it; -1 for the other kinds
  int axis = -1;
  /// the input faces concerned: those the loop crosses, those meeting the cell,
  /// those of the component, those along the border cycle
  std::vector<FaceDescriptor> input_faces;
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_TOPOLOGY_DEFECT_H
