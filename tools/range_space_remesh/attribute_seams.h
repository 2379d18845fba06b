// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// range_space_remesh: colour and texture seams. A file stores a sharp change of vertex
// colour, or a texture seam, as several points at one position, one per side, each with
// its own value. The repair merges points at one position, and one vertex holds one
// value: the values of one side would spread over the other. So the faces' corners keep
// the values of the file's own points, and on a closed surface the edges where they
// differ are opened as creases are (insert_crease_triangles(): a copy of each vertex per
// side, joined by zero-area triangles), each copy with its side's values. A surface
// with a border cannot be opened so: its values are blended across, and counted.

#ifndef RANGE_SPACE_REMESHING_TOOLS_ATTRIBUTE_SEAMS_H
#define RANGE_SPACE_REMESHING_TOOLS_ATTRIBUTE_SEAMS_H

#include "mesh_file_reader.h"
#include "mesh_types.h"

#include <CGAL/Range_space_remeshing/insert_crease_triangles.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

namespace rsr_program {

/// Which of the soup's per-point values the seams are about: colours, and UVs unless
/// the reading drops them anyway (points with several UVs, corners without).
struct Seam_values
{
  const rsr_io::Polygon_soup& soup;
  bool colors, uvs;

  Seam_values(const rsr_io::Polygon_soup& s)
    : soup(s), colors(!s.colors.empty()),
      uvs(!s.uvs.empty() && s.uv_seam_points == 0 && s.uv_missing_corners == 0)
  {}

  bool any() const { return colors || uvs; }

  bool same(std::size_t i, std::size_t j) const
  {
    return (!colors || soup.colors[i] == soup.colors[j]) && (!uvs || rsr_io::same_uv(soup.uvs[i], soup.uvs[j]));
  }
};

inline constexpr std::size_t no_point = (std::numeric_limits<std::size_t>::max)();

/// The soup's point of each corner of a mesh face, found among the soup's polygons that
/// hold the positions of the face's three corners (the repair triangulates polygons and
/// may flip them, so a face is known by its positions): the polygons at the corner
/// with the fewest are looked at, a few but at a pole. The first such polygon is
/// taken: two polygons through the same three positions (a duplicate, removed by the
/// repair, or two quadrilaterals of a pillow) are not told apart.
class Corner_points
{
  using Position = rsr_io::Position;

public:
  /// Taken before the repair, which renumbers the soup's polygons in place (its points
  /// stay as they are).
  explicit Corner_points(const rsr_io::Polygon_soup& soup) : soup_(soup)
  {
    first_corner_.reserve(soup.polygons.size() + 1);
    for(std::size_t f = 0; f < soup.polygons.size(); ++f) {
      first_corner_.push_back(corners_.size());
      for(std::size_t i : soup.polygons[f]) {
        corners_.push_back(i);
        if(auto& at = polygons_at_[soup.points[i]]; at.empty() || at.back() != f) // the reader checked i
          at.push_back(f);
      }
    }
    first_corner_.push_back(corners_.size());
  }

  /// The soup point of `mesh`'s face(h) at target(h), or no_point.
  std::size_t point(const Mesh& mesh, Mesh::Halfedge_index h) const
  {
    const std::array<Position, 3> corners{{position(mesh.point(target(h, mesh))),
                                           position(mesh.point(target(next(h, mesh), mesh))),
                                           position(mesh.point(source(h, mesh)))}};
    const std::vector<std::size_t>* fewest = nullptr;
    for(const Position& p : corners) {
      const auto found = polygons_at_.find(p);
      if(found == polygons_at_.end())
        return no_point;
      if(!fewest || found->second.size() < fewest->size())
        fewest = &found->second;
    }
    for(std::size_t f : *fewest) {
      std::size_t at_target = no_point;
      bool second = false, third = false;
      for(std::size_t c = first_corner_[f]; c < first_corner_[f + 1]; ++c) {
        const std::size_t i = corners_[c];
        if(soup_.points[i] == corners[0])
          at_target = i;
        second = second || soup_.points[i] == corners[1];
        third = third || soup_.points[i] == corners[2];
      }
      if(at_target != no_point && second && third)
        return at_target;
    }
    return no_point;
  }

private:
  static Position position(const K::Point_3& p) { return {{p.x(), p.y(), p.z()}}; }

  const rsr_io::Polygon_soup& soup_;
  std::vector<std::size_t> corners_, first_corner_; // the polygons' points, as read
  std::unordered_map<Position, std::vector<std::size_t>, rsr_io::Position_hash> polygons_at_;
};

/// The seams of a repaired mesh: the soup point of each face corner (by halfedge index:
/// face(h) at target(h)) and the edges whose two faces have different values at one
/// of its ends.
struct Attribute_seams
{
  std::vector<std::size_t> corner_point;
  std::vector<char> on_seam; // by edge index
  std::size_t edges = 0;
};

/// Whether two of the file's points at one position have different values: only then
/// can a merge have put two sides' values on one vertex. `point_at` gives the first
/// used point at each position.
template <class PointAt>
bool has_points_with_different_values(const Seam_values& values, const std::vector<std::size_t>& used,
                                      const PointAt& point_at)
{
  for(std::size_t i : used) {
    const auto first = point_at.find(values.soup.points[i]);
    if(first != point_at.end() && !values.same(i, first->second)) // not found: a NaN, refused by the repair
      return true;
  }
  return false;
}

inline Attribute_seams find_attribute_seams(const Seam_values& values, const Corner_points& corners, const Mesh& mesh)
{
  Attribute_seams seams;
  seams.corner_point.assign(mesh.number_of_halfedges(), no_point);
  for(auto h : halfedges(mesh))
    if(!is_border(h, mesh))
      seams.corner_point[h.idx()] = corners.point(mesh, h);
  auto differ = [&](Mesh::Halfedge_index a, Mesh::Halfedge_index b) { // two corners at one vertex
    const std::size_t i = seams.corner_point[a.idx()], j = seams.corner_point[b.idx()];
    return i != no_point && j != no_point && !values.same(i, j);
  };
  seams.on_seam.assign(mesh.number_of_edges(), 0);
  for(auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh), o = opposite(h, mesh);
    if(is_border(h, mesh) || is_border(o, mesh))
      continue;
    // h's face has target(h) at h and source(h) at prev(h); o's face the reverse
    if(differ(h, prev(o, mesh)) || differ(prev(h, mesh), o)) {
      seams.on_seam[e.idx()] = 1;
      ++seams.edges;
    }
  }
  return seams;
}

/// `mesh` with its seams (and its creases sharper than `sharp_angle` degrees, if not
/// negative) opened; each vertex copy takes the values of the file's point at a corner
/// of its side (of `point_at` its position's, where no corner tells). The first faces
/// of the result are `mesh`'s, in order: insert_crease_triangles() adds the strips
/// after them.
template <class PointAt>
Mesh open_attribute_seams(const Mesh& mesh, const Attribute_seams& seams, const Seam_values& values,
                          const PointAt& point_at, double sharp_angle)
{
  const auto is_crease = boost::make_function_property_map<Mesh::Edge_index, bool>([&](Mesh::Edge_index e) {
    // the seams, and the creases by insert_crease_triangles()'s own rule
    return seams.on_seam[e.idx()] || (sharp_angle >= 0 && RSR::is_sharp_edge(e, mesh, sharp_angle));
  });
  Mesh opened;
  RSR::insert_crease_triangles(mesh, opened, 0, CGAL::parameters::edge_is_constrained_map(is_crease));

  std::vector<std::size_t> point_of(opened.number_of_vertices(), no_point);
  for(auto f : faces(mesh)) {
    const Mesh::Face_index copy(f.idx());
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      if(const std::size_t i = seams.corner_point[h.idx()]; i != no_point)
        for(auto g : CGAL::halfedges_around_face(halfedge(copy, opened), opened))
          if(opened.point(target(g, opened)) == mesh.point(target(h, mesh)) &&
             point_of[target(g, opened).idx()] == no_point)
            point_of[target(g, opened).idx()] = i;
  }
  for(auto w : vertices(opened))
    if(point_of[w.idx()] == no_point) {
      const auto& p = opened.point(w);
      if(const auto found = point_at.find({{p.x(), p.y(), p.z()}}); found != point_at.end())
        point_of[w.idx()] = found->second;
    }
  auto copy_values = [&](auto value_of, const char* name) {
    using Value = decltype(value_of(std::size_t(0)));
    auto copied = opened.add_property_map<Mesh::Vertex_index, Value>(name).first;
    for(auto w : vertices(opened))
      if(point_of[w.idx()] != no_point)
        copied[w] = value_of(point_of[w.idx()]);
  };
  if(values.colors)
    copy_values([&](std::size_t i) {
      const auto& c = values.soup.colors[i];
      return CGAL::IO::Color(c[0], c[1], c[2]);
    }, "v:color");
  if(values.uvs)
    copy_values([&](std::size_t i) { return K::Point_2(values.soup.uvs[i][0], values.soup.uvs[i][1]); }, "v:uv");
  return opened;
}

} // namespace rsr_program

#endif // RANGE_SPACE_REMESHING_TOOLS_ATTRIBUTE_SEAMS_H
