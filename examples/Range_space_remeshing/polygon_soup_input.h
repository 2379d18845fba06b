// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Turns a polygon soup read from a file into a triangle mesh the remesher accepts,
// or says in one line why it cannot. Shared by the command-line program and the
// fuzz target, so that the fuzzer exercises the program's own input path.

#ifndef RANGE_SPACE_REMESHING_EXAMPLES_POLYGON_SOUP_INPUT_H
#define RANGE_SPACE_REMESHING_EXAMPLES_POLYGON_SOUP_INPUT_H

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstdint>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rsr_input {

/// Why a soup is no usable mesh, in one line.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Checks the header of a PLY file of `file_size` bytes before CGAL's reader sees
/// it (both found by the fuzzer): CGAL 5.5's reader reads out of bounds on a
/// `property` line that comes before any `element` line, and allocates for the
/// element counts it is given (a count of -12 became minutes of allocation). A
/// count must be a whole number no larger than the file, as each element takes at
/// least one byte. Throws Input_error naming the file (`name`).
inline void check_ply_header(std::istream& in, const std::string& name, std::uintmax_t file_size)
{
  std::string line;
  bool has_element = false;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if(number == 1 && keyword != "ply")
      throw Input_error(name + " is not a PLY file (no 'ply' on its first line)");
    if(keyword == "end_header")
      return;
    if(keyword == "element") {
      has_element = true;
      std::string element, count;
      words >> element >> count;
      if(count.empty() || count.size() > 19 || count.find_first_not_of("0123456789") != std::string::npos ||
         std::stoull(count) > file_size)
        throw Input_error(name + " has a PLY element count that cannot be right (line " + std::to_string(number) +
                          ": '" + count + "')");
    }
    else if(keyword == "property" && !has_element)
      throw Input_error(name + " has a PLY property before any element (line " + std::to_string(number) + ")");
  }
  throw Input_error(name + " has a PLY header without end_header");
}

/// The numbers on a line of an OFF file, its comment removed.
inline std::vector<std::string> off_tokens(std::string line)
{
  line = line.substr(0, line.find('#'));
  std::istringstream words(line);
  std::vector<std::string> tokens;
  for(std::string word; words >> word;)
    tokens.push_back(word);
  return tokens;
}

/// Whether `token` is a number that no count could be: negative, not a number, or
/// above `bound` (CGAL's OFF reader reads counts as floating-point numbers, "1e3",
/// and converts them unchecked). Other words are left to CGAL's reader to refuse.
inline bool is_absurd_count(const std::string& token, double bound)
{
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  const bool is_number = end != token.c_str() && *end == '\0';
  return is_number && !(value >= 0 && value <= bound);
}

/// Checks the counts of a text OFF file of `file_size` bytes before CGAL's reader sees
/// it (found by the fuzzer): CGAL 5.5's reader allocates what the header and each
/// face's degree say, so a face line "1e9 3" made it fill 8 GB before failing. The
/// header's counts must be no larger than the file; a face line's degree above a
/// million must be matched by as many indices on its line. Binary OFF is left
/// to CGAL. Throws Input_error naming the file (`name`).
inline void check_off_counts(std::istream& in, const std::string& name, std::uintmax_t file_size)
{
  std::string line;
  std::vector<std::string> tokens;
  std::size_t number = 0;
  auto next_tokens = [&] { // the next line with something on it
    while(std::getline(in, line)) {
      ++number;
      tokens = off_tokens(line);
      if(!tokens.empty())
        return true;
    }
    return false;
  };
  if(!next_tokens() || tokens[0].find("OFF") == std::string::npos)
    return; // not an OFF header: CGAL's reader refuses it
  if(tokens.size() > 1 && tokens[1] == "BINARY")
    return;
  const bool has_dimension = tokens[0].find('n') != std::string::npos; // nOFF: a dimension comes first
  std::vector<std::string> header(tokens.begin() + 1, tokens.end());
  while(header.size() < (has_dimension ? 4u : 3u) && next_tokens())
    header.insert(header.end(), tokens.begin(), tokens.end());
  const std::size_t first_count = has_dimension ? 1 : 0;
  if(header.size() < first_count + 3)
    return; // a truncated header: CGAL's reader refuses it
  for(std::size_t c = first_count; c < first_count + 3; ++c)
    if(is_absurd_count(header[c], double(file_size)))
      throw Input_error(name + " has an OFF count that cannot be right ('" + header[c] + "' in its header)");
  const double vertices = std::strtod(header[first_count].c_str(), nullptr);
  for(double v = 0; v < vertices && next_tokens(); ++v) {
  }
  while(next_tokens()) // the faces: the degree, then as many indices
    if(is_absurd_count(tokens[0], std::max(1e6, double(tokens.size() - 1))))
      throw Input_error(name + " has an OFF face whose degree cannot be right (line " + std::to_string(number) +
                        ": '" + tokens[0] + "')");
}

/// Splits every face that is not a triangle into a fan: always possible, whatever
/// the geometry (used where the constrained triangulation gives up).
template <class Mesh>
void fan_triangulate(Mesh& mesh)
{
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> polygons;
  for(auto f : faces(mesh))
    if(degree(f, mesh) > 3)
      polygons.push_back(f);
  for(auto f : polygons) {
    auto h = halfedge(f, mesh);
    while(degree(face(h, mesh), mesh) > 3)
      h = prev(CGAL::Euler::split_face(h, next(next(h, mesh), mesh), mesh), mesh);
  }
}

/// Whether every face is a triangle whose halfedges point back to it and chain up
/// (vertices no face uses, which soups may have, do not matter here).
template <class Mesh>
bool is_triangle_structure(const Mesh& mesh)
{
  for(auto f : faces(mesh)) {
    const auto h0 = halfedge(f, mesh), h1 = next(h0, mesh), h2 = next(h1, mesh);
    if(next(h2, mesh) != h0)
      return false;
    for(auto h : {h0, h1, h2})
      if(face(h, mesh) != f || target(h, mesh) != source(next(h, mesh), mesh) ||
         opposite(opposite(h, mesh), mesh) != h)
        return false;
  }
  return true;
}

/// Rebuilds `mesh` from the soup with each polygon split into a fan from its first
/// corner; throws Input_error if the fans do not form a 2-manifold.
template <class Point, class Mesh>
void rebuild_from_fans(const std::vector<Point>& points, const std::vector<std::vector<std::size_t>>& polygons,
                       const std::string& name, Mesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<std::vector<std::size_t>> triangles;
  for(const auto& polygon : polygons)
    for(std::size_t i = 1; i + 1 < polygon.size(); ++i)
      triangles.push_back({polygon[0], polygon[i], polygon[i + 1]});
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
    throw Input_error(name + " has a polygon that cannot be split into triangles without breaking the mesh");
  Mesh fans;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, fans);
  mesh = std::move(fans);
}

/// Builds `mesh` from the soup (`name` names it in messages): finite coordinates,
/// faces of 3 or more existing vertices, an oriented 2-manifold (with or without
/// border); polygons are triangulated. Returns whether any face was triangulated.
/// The mesh's vertices are the points some face uses, in the soup's order.
template <class Point, class Mesh>
bool polygon_soup_to_triangle_mesh(const std::vector<Point>& points,
                                   const std::vector<std::vector<std::size_t>>& polygons,
                                   const std::string& name, Mesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(polygons.empty())
    throw Input_error(name + " contains no face");
  for(const auto& p : points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Input_error(name + " has a NaN or infinite vertex coordinate");
  for(const auto& polygon : polygons) {
    if(polygon.size() < 3)
      throw Input_error(name + " has a face with fewer than 3 vertices");
    for(std::size_t v : polygon)
      if(v >= points.size())
        throw Input_error(name + " has a face referring to a missing vertex");
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error(name + " is not a 2-manifold oriented mesh (non-manifold edge or vertex, "
                             "or inconsistent orientation)");
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const bool triangulated = !CGAL::is_triangle_mesh(mesh);
  if(triangulated) {
    bool all_triangulated = false;
    try {
      all_triangulated = PMP::triangulate_faces(mesh);
    } catch(const std::exception&) {
      all_triangulated = false;
    }
    if(!all_triangulated)
      fan_triangulate(mesh);
    // on degenerate polygons the triangulation can leave a broken structure (found by
    // the fuzzer: a pentagon folded onto a plane): fans built in the soup instead
    if(!is_triangle_structure(mesh))
      rebuild_from_fans(points, polygons, name, mesh);
  }
  return triangulated;
}

} // namespace rsr_input

#endif // RANGE_SPACE_REMESHING_EXAMPLES_POLYGON_SOUP_INPUT_H
