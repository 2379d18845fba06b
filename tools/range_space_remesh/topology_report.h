// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: what the topology check found. The warning line on stderr and
// the input faces of the defects, as the mesh --topology-report writes.

#ifndef RANGE_SPACE_REMESHING_TOOLS_TOPOLOGY_REPORT_H
#define RANGE_SPACE_REMESHING_TOOLS_TOPOLOGY_REPORT_H

#include "mesh_types.h"
#include "options.h"

#include <CGAL/Range_space_remeshing/remesh.h>

#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace rsr_program {


/// The input faces where the topology check found defects, as a mesh.
inline Mesh flagged_faces(const Mesh& input, const std::vector<RSR::Topology_defect<Mesh::Face_index>>& defects)
{
  std::set<Mesh::Face_index> flagged;
  for(const auto& defect : defects)
    flagged.insert(defect.input_faces.begin(), defect.input_faces.end());
  Mesh report;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> copy;
  for(Mesh::Face_index f : flagged) {
    std::vector<Mesh::Vertex_index> corners;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(halfedge(f, input), input)) {
      auto found = copy.find(v);
      if(found == copy.end())
        found = copy.emplace(v, report.add_vertex(input.point(v))).first;
      corners.push_back(found->second);
    }
    if(report.add_face(corners) == Mesh::null_face()) // a face against the orientation of the others:
      report.add_face(std::vector<Mesh::Vertex_index>(corners.rbegin(), corners.rend())); // keep it anyway
  }
  return report;
}

/// One line on stderr when the output's topology may differ from the input's.
inline void warn_about_topology(const RSR::Remesh_statistics& all, const Options& options,
                         const std::vector<RSR::Topology_defect<Mesh::Face_index>>& defects)
{
  const RSR::Statistics& s = all.primal;
  const bool dual = options.output_kind != "primal";
  if(!s.topology_checked || (dual ? all.topology_preserved() : s.topology_preserved()))
    return;
  std::cerr << "range_space_remesh: warning: the remesh may not have the input's topology ("
            << s.closed_loops << " closed loops, " << s.non_disk_cells << " non-disk cells, " << s.lost_components
            << " lost components, " << s.uncrossed_border_cycles << " lost border cycles, "
            << s.dropped_pieces + (dual ? all.dual.dropped_pieces : 0) << " dropped pieces, "
            << (dual ? all.all_quads.pieces_not_all_quads : 0) << " pieces not all quads; Euler characteristic "
            << s.input_euler_characteristic << " -> " << s.output_euler_characteristic << ", "
            << defects.size() << " defects); use --preserve-topology or a smaller cell size" << std::endl;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_TOPOLOGY_REPORT_H
