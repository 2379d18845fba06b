// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: INPUT, from the file to the mesh the remesh reads. The reader
// (mesh_file_reader.h) gives a polygon soup, prepare_input() repairs and triangulates
// it (or refuses it with --strict), the vertex colours and UVs follow, and --sharp-angle
// opens the creases; one line on stderr says what the repair changed.

#ifndef RANGE_SPACE_REMESHING_TOOLS_INPUT_H
#define RANGE_SPACE_REMESHING_TOOLS_INPUT_H

#include "attribute_seams.h"
#include "failure.h"
#include "mesh_file_reader.h"
#include "mesh_types.h"
#include "options.h"

#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/Range_space_remeshing/prepare_input.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <functional>
#include <iostream>
#include <optional>
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
  // why the texture coordinates were dropped (see report_dropped_uvs())
  std::size_t uv_seam_vertices = 0;   // vertices with several UVs
  std::size_t uv_missing_corners = 0; // face corners without a UV where others have one
  // edges where the file's colours or UVs change (see attribute_seams.h)
  std::size_t opened_seam_edges = 0, blended_seam_edges = 0;
  bool creases_opened = false; // with the seams, for --sharp-angle
  std::vector<std::string> reader_notes; // where the file was taken otherwise than it says
};

using rsr_io::Position;
using rsr_io::Position_hash;
using Point_at = std::unordered_map<Position, std::size_t, Position_hash>;

/// The points of the soup's polygons, in their order: the repair removes the others,
/// whose values (a colour, a UV) are no vertex's.
inline std::vector<std::size_t> used_points(const rsr_io::Polygon_soup& soup)
{
  std::vector<std::uint8_t> used(soup.points.size(), 0);
  for(const auto& polygon : soup.polygons)
    for(std::size_t i : polygon)
      if(i < used.size())
        used[i] = 1;
  std::vector<std::size_t> found;
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    if(used[i])
      found.push_back(i);
  return found;
}

/// The first of the used points at each position.
inline Point_at first_point_at_each_position(const rsr_io::Polygon_soup& soup, const std::vector<std::size_t>& used)
{
  Point_at point_at;
  point_at.reserve(used.size());
  for(std::size_t i : used)
    point_at.emplace(soup.points[i], i);
  return point_at;
}

/// Gives each vertex v of `mesh` the value `value_of(i)` of the soup's point
/// i = point_of(v), if any.
template <class T, class PointOf, class ValueOf>
void add_values(const PointOf& point_of, const ValueOf& value_of, const std::string& name, Mesh& mesh)
{
  auto values = mesh.add_property_map<Mesh::Vertex_index, T>(name).first;
  for(auto v : vertices(mesh))
    if(const std::optional<std::size_t> i = point_of(v))
      values[v] = value_of(*i);
}

/// The positions whose points (of polygons) have different UVs: a texture seam given
/// as copies of its points, which the repair merges into one vertex.
inline std::size_t positions_with_several_uvs(const rsr_io::Polygon_soup& soup, const Point_at& point_at)
{
  std::vector<std::uint8_t> on_seam(soup.points.size(), 0);
  for(const auto& polygon : soup.polygons)
    for(std::size_t i : polygon) {
      const auto first = point_at.find(soup.points[i]);
      if(first != point_at.end() && !rsr_io::same_uv(soup.uvs[i], soup.uvs[first->second])) // not found: a NaN
        on_seam[first->second] = 1;
    }
  return std::size_t(std::count(on_seam.begin(), on_seam.end(), 1));
}

/// Where the soup's vertex values come from, found before the repair renumbers its
/// polygons: the used points in order (the vertices of a mesh the repair did not
/// change), the point that gives each position its values (where the repair merged
/// points, or copied them: each vertex sits where some point of the file is), and
/// the positions with several UVs (a seam once merged).
struct Soup_values
{
  std::vector<std::size_t> used;  // empty if the soup has no colours and no UVs
  Point_at point_at;               // likewise
  std::size_t position_seams = 0;
};

inline Soup_values soup_values(const rsr_io::Polygon_soup& soup)
{
  Soup_values values;
  if(soup.colors.empty() && soup.uvs.empty())
    return values;
  values.used = used_points(soup);
  values.point_at = first_point_at_each_position(soup, values.used);
  values.position_seams = soup.uvs.empty() ? 0 : positions_with_several_uvs(soup, values.point_at);
  return values;
}

/// Whether the vertices of `input.mesh` are the soup's used points, in order: the
/// repair did not change the mesh.
inline bool vertices_as_in_file(const Soup_values& values, const Input& input)
{
  return !input.repairs.repaired() && num_vertices(input.mesh) == values.used.size();
}

/// The soup's vertex colours and texture coordinates on `input.mesh`; UVs that are
/// not one per vertex are dropped (counted in `input`, reported once the output is
/// written by report_dropped_uvs(): a run that fails says only why). A mesh the
/// repair did not change has the used points as vertices, in order, even where two
/// are at one position (--strict keeps them apart): vertex k takes the k-th's values.
inline void add_vertex_values(const rsr_io::Polygon_soup& soup, const Soup_values& values, Input& input)
{
  const bool as_in_file = vertices_as_in_file(values, input);
  input.uv_missing_corners = soup.uv_missing_corners;
  input.uv_seam_vertices = soup.uv_seam_points + (as_in_file ? 0 : values.position_seams);
  const Mesh& mesh = input.mesh;
  auto point_of = [&](Mesh::Vertex_index v) -> std::optional<std::size_t> {
    if(as_in_file)
      return values.used[v.idx()];
    const auto& p = mesh.point(v);
    const auto found = values.point_at.find({{p.x(), p.y(), p.z()}});
    return found == values.point_at.end() ? std::nullopt : std::optional<std::size_t>(found->second);
  };
  if(!soup.colors.empty())
    add_values<CGAL::IO::Color>(point_of, [&](std::size_t i) {
      const auto& c = soup.colors[i];
      return CGAL::IO::Color(c[0], c[1], c[2]);
    }, "v:color", input.mesh);
  if(input.uv_seam_vertices == 0 && !soup.uvs.empty())
    add_values<K::Point_2>(point_of, [&](std::size_t i) {
      return K::Point_2(soup.uvs[i][0], soup.uvs[i][1]);
    }, "v:uv", input.mesh);
}

/// The polygons at each of the soup's positions, if the file has points at one position
/// with different colours or UVs (a seam the repair's merge would blur): taken before
/// the repair, which renumbers the polygons.
inline std::optional<Corner_points> seam_corners(const rsr_io::Polygon_soup& soup, const Soup_values& values)
{
  const Seam_values seam_values(soup);
  if(!seam_values.any() || values.used.empty() || !has_points_with_different_values(seam_values, values.used, values.point_at))
    return std::nullopt;
  return Corner_points(soup);
}

/// Where the repair merged points with different colours or UVs: the seams opened on a
/// closed surface, with creases sharper than `sharp_angle` degrees (if not negative),
/// or counted on a surface with a border (see attribute_seams.h).
inline void open_seams(const rsr_io::Polygon_soup& soup, const Soup_values& values,
                       const std::optional<Corner_points>& corners, double sharp_angle, Input& input)
{
  if(!corners || vertices_as_in_file(values, input))
    return;
  const bool closed = CGAL::is_closed(input.mesh);
  Seam_values seam_values(soup);
  seam_values.uvs = seam_values.uvs && closed; // with a border, add_vertex_values() dropped them
  const Attribute_seams seams = find_attribute_seams(seam_values, *corners, input.mesh);
  if(seams.edges == 0)
    return;
  if(!closed) { // the colours are blended across
    input.blended_seam_edges = seams.edges;
    return;
  }
  input.mesh = open_attribute_seams(input.mesh, seams, seam_values, values.point_at, sharp_angle);
  input.opened_seam_edges = seams.edges;
  input.creases_opened = sharp_angle >= 0;
  if(seam_values.uvs) // each copy has its side's
    input.uv_seam_vertices = 0;
}

/// One line on stderr when the colours of a surface with a border were blended across
/// the edges where the file changes them.
inline void report_blended_seams(const std::string& path, const Input& input)
{
  if(input.blended_seam_edges == 0)
    return;
  std::cerr << "range_space_remesh: " << quote(path) << ": " << input.blended_seam_edges
            << (input.blended_seam_edges == 1 ? " edge where" : " edges where")
            << " the file's colours change, on a surface with a border: "
               "they are blended across (--strict keeps their points apart)"
            << std::endl;
}

/// One line on stderr when the input's texture coordinates were dropped.
inline void report_dropped_uvs(const std::string& path, const Input& input)
{
  std::ostringstream line;
  line << "range_space_remesh: " << quote(path) << ": ";
  if(input.uv_seam_vertices > 0)
    line << input.uv_seam_vertices << (input.uv_seam_vertices == 1 ? " vertex has" : " vertices have")
         << " several texture coordinates (a seam)";
  else if(input.uv_missing_corners > 0)
    line << input.uv_missing_corners
         << (input.uv_missing_corners == 1 ? " face corner has" : " face corners have")
         << " no texture coordinate where others have one";
  else
    return;
  std::cerr << line.str() << ": the texture coordinates are dropped" << std::endl;
}

/// Reads INPUT into a triangle mesh (see rsr_io::read_mesh_file): repaired into an
/// oriented 2-manifold unless --strict, polygons triangulated, vertex colours and
/// texture coordinates kept.
inline Input read_input(const std::string& path, bool strict, double sharp_angle)
{
  Input input;
  const auto start = std::chrono::steady_clock::now();
  rsr_io::Polygon_soup soup;
  try {
    // an OBJ texture seam as PLY stores one, points per side: opened below on a closed
    // surface (--strict keeps points at one position apart: it would cut the surface)
    soup = rsr_io::read_mesh_file(path, strict ? rsr_io::Uv_seams::DROP : rsr_io::Uv_seams::SPLIT);
  } catch(const rsr_io::Read_error& e) {
    fail(e.what());
  }
  const auto read = std::chrono::steady_clock::now();
  std::vector<K::Point_3> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  const Soup_values values = soup_values(soup);
  const std::optional<Corner_points> corners = seam_corners(soup, values);
  try {
    input.repairs = RSR::prepare_input(points, soup.polygons, input.mesh,
                                       strict ? RSR::Input_repair::REFUSE : RSR::Input_repair::REPAIR);
  } catch(const RSR::Remeshing_error& e) {
    fail(quote(path) + ": " + e.what() + (strict ? " (drop --strict to repair it)" : ""));
  }
  // the copies are the program's, not the file's: their merge is no repair
  input.repairs.merged_points -= (std::min)(input.repairs.merged_points, soup.uv_seam_copies);
  add_vertex_values(soup, values, input);
  open_seams(soup, values, corners, sharp_angle, input);
  input.reader_notes = std::move(soup.notes);
  const auto repaired = std::chrono::steady_clock::now();
  input.read_ms = std::chrono::duration<double, std::milli>(read - start).count();
  input.repair_ms = std::chrono::duration<double, std::milli>(repaired - read).count();
  return input;
}

/// One line on stderr for each place where the reader took the file otherwise than
/// it says.
inline void report_reader_notes(const std::string& path, const Input& input)
{
  for(const std::string& note : input.reader_notes)
    std::cerr << "range_space_remesh: " << quote(path) << ": " << note << std::endl;
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
  // --strict takes a mesh with points at one position as it is, and refuses the rest
  const bool only_merged = r.merged_points > 0 && r.removed_repeated_corners + r.removed_degenerate_polygons +
                                                           r.removed_duplicate_polygons + r.reversed_polygons +
                                                           r.reversed_to_face_outward + r.non_manifold_edges +
                                                           r.split_non_manifold_points ==
                                                       0;
  std::cerr << line.str()
            << (only_merged ? " (--strict keeps such points apart)" : r.repaired() ? " (--strict refuses such input)" : "")
            << std::endl;
}

/// The values of `map` (if any) on `from`, as the property `name` of `to`'s vertices at
/// the same positions: the crease copies sit at their original's position.
template <class Map>
void copy_by_position(const Mesh& from, const std::optional<Map>& map, const std::string& name, Mesh& to)
{
  if(!map)
    return;
  using Value = typename boost::property_traits<Map>::value_type;
  std::unordered_map<Position, Value, Position_hash> by_position;
  for(auto v : vertices(from))
    by_position[{{from.point(v).x(), from.point(v).y(), from.point(v).z()}}] = (*map)[v];
  auto copied = to.add_property_map<Mesh::Vertex_index, Value>(name).first;
  for(auto v : vertices(to))
    copied[v] = by_position[{{to.point(v).x(), to.point(v).y(), to.point(v).z()}}];
}

/// With --sharp-angle, the input with zero-area triangles along its creases, so that
/// the normal maps see each side's normal (vertex colours and UVs follow the copies).
inline Mesh with_creases_opened(Mesh input, const Options& options, bool already_opened)
{
  if(!(options.sharp_angle >= 0) || already_opened)
    return input;
  if(!CGAL::is_closed(input)) // what insert_crease_triangles() needs
    fail("--sharp-angle needs a closed surface, and " + quote(options.input) + " has a border");
  Mesh creased;
  RSR::insert_crease_triangles(input, creased, options.sharp_angle);
  copy_by_position(input, find_vertex_colors(input), "v:color", creased);
  copy_by_position(input, find_vertex_uvs(input), "v:uv", creased);
  return creased;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_INPUT_H
