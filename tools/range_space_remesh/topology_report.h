// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: what the topology check found. The warning line on stderr and
// the input faces of the defects, as the mesh --topology-report writes.

#ifndef RANGE_SPACE_REMESHING_TOOLS_TOPOLOGY_REPORT_H
#define RANGE_SPACE_REMESHING_TOOLS_TOPOLOGY_REPORT_H

#include "mesh_types.h"
#include "options.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Range_space_remeshing/remesh.h>

#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace rsr_program {


/// The input faces where the topology check found defects, as a mesh. Some of the
/// faces around an input vertex can be flagged in separate fans: CGAL's
/// `orient_polygon_soup()` gives each fan its own copy of the vertex, so that the
/// report is a manifold mesh file, with every flagged face.
inline Mesh flagged_faces(const Mesh& input, const std::vector<RSR::Topology_defect<Mesh::Face_index>>& defects)
{
  std::set<Mesh::Face_index> flagged;
  for(const auto& defect : defects)
    flagged.insert(defect.input_faces.begin(), defect.input_faces.end());
  std::vector<Mesh::Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::map<Mesh::Vertex_index, std::size_t> index_of;
  for(Mesh::Face_index f : flagged) {
    polygons.emplace_back();
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(halfedge(f, input), input)) {
      const auto inserted = index_of.emplace(v, points.size());
      if(inserted.second)
        points.push_back(input.point(v));
      polygons.back().push_back(inserted.first->second);
    }
  }
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
  Mesh report;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, report);
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
