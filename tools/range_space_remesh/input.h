// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: INPUT, from the file to the mesh the remesh reads. The reader
// (mesh_file_reader.h) gives a polygon soup, prepare_input() repairs and triangulates
// it (or refuses it with --strict), the vertex colours follow, and --sharp-angle
// opens the creases; one line on stderr says what the repair changed.

#ifndef RANGE_SPACE_REMESHING_TOOLS_INPUT_H
#define RANGE_SPACE_REMESHING_TOOLS_INPUT_H

#include "failure.h"
#include "mesh_file_reader.h"
#include "mesh_types.h"
#include "options.h"

#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/Range_space_remeshing/prepare_input.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rsr_program {


/// The input mesh and what it took to get it.
struct Input
{
  Mesh mesh;
  RSR::Input_repair_statistics repairs;
  double read_ms = 0, repair_ms = 0;
};

/// Gives the vertices of `mesh` the colours of the soup's points at their positions:
/// the repair only merges points that coincide and copies points, so each vertex
/// sits where some point of the file is (the first point there gives the colour).
inline void add_colors_by_position(const rsr_io::Polygon_soup& soup, Mesh& mesh)
{
  using Position = std::array<double, 3>;
  struct Hash
  {
    std::size_t operator()(const Position& p) const
    {
      std::size_t h = 0;
      for(double x : p)
        h = h * 1000003u ^ std::hash<double>()(x);
      return h;
    }
  };
  std::unordered_map<Position, std::size_t, Hash> point_at;
  point_at.reserve(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    point_at.emplace(soup.points[i], i);
  auto colors = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for(auto v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    const auto found = point_at.find({{p.x(), p.y(), p.z()}});
    if(found != point_at.end()) {
      const auto& c = soup.colors[found->second];
      colors[v] = CGAL::IO::Color(c[0], c[1], c[2]);
    }
  }
}

/// Reads INPUT into a triangle mesh (see rsr_io::read_mesh_file): repaired into an
/// oriented 2-manifold unless --strict, polygons triangulated, vertex colours kept.
inline Input read_input(const std::string& path, bool strict)
{
  Input input;
  const auto start = std::chrono::steady_clock::now();
  rsr_io::Polygon_soup soup;
  try {
    soup = rsr_io::read_mesh_file(path);
  } catch(const rsr_io::Read_error& e) {
    fail(e.what());
  }
  const auto read = std::chrono::steady_clock::now();
  std::vector<K::Point_3> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  try {
    input.repairs = RSR::prepare_input(points, soup.polygons, input.mesh,
                                       strict ? RSR::Input_repair::REFUSE : RSR::Input_repair::REPAIR);
  } catch(const RSR::Remeshing_error& e) {
    fail(quote(path) + ": " + e.what() + (strict ? " (drop --strict to repair it)" : ""));
  }
  if(!soup.colors.empty())
    add_colors_by_position(soup, input.mesh);
  const auto repaired = std::chrono::steady_clock::now();
  input.read_ms = std::chrono::duration<double, std::milli>(read - start).count();
  input.repair_ms = std::chrono::duration<double, std::milli>(repaired - read).count();
  return input;
}

/// One line on stderr when the input needed repairs.
inline void report_repairs(const std::string& path, const RSR::Input_repair_statistics& r)
{
  if(!r.repaired() && r.removed_isolated_points == 0)
    return;
  std::ostringstream line;
  line << "range_space_remesh: repaired '" << path << "':";
  const std::pair<std::size_t, const char*> counts[] = {
      {r.merged_points, "merged points"},
      {r.removed_isolated_points, "unused points removed"},
      {r.removed_repeated_corners, "repeated corners removed"},
      {r.removed_degenerate_polygons, "degenerate faces removed"},
      {r.removed_duplicate_polygons, "duplicate faces removed"},
      {r.reversed_polygons, "faces flipped"},
      {r.reversed_to_face_outward, "triangles flipped to face outward"},
      {r.non_manifold_edges, "non-manifold edges cut"},
      {r.split_non_manifold_points, "points copied to split non-manifold vertices"}};
  const char* separator = " ";
  for(const auto& [count, what] : counts)
    if(count > 0) {
      line << separator << count << " " << what;
      separator = ", ";
    }
  std::cerr << line.str() << (r.repaired() ? " (--strict refuses such input)" : "") << std::endl;
}

/// With --sharp-angle, the input with zero-area triangles along its creases, so that
/// the normal maps see each side's normal (vertex colours follow the copies).
inline Mesh with_creases_opened(Mesh input, const Options& options)
{
  if(!(options.sharp_angle >= 0))
    return input;
  Mesh creased;
  RSR::insert_crease_triangles(input, creased, options.sharp_angle);
  const auto colors = find_vertex_colors(input);
  if(colors) { // copies sit at their original's position: match them by position
    std::map<std::array<double, 3>, CGAL::IO::Color> by_position;
    for(auto v : vertices(input))
      by_position[{{input.point(v).x(), input.point(v).y(), input.point(v).z()}}] = (*colors)[v];
    auto copied = creased.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    for(auto v : vertices(creased))
      copied[v] = by_position[{{creased.point(v).x(), creased.point(v).y(), creased.point(v).z()}}];
  }
  return creased;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_INPUT_H
