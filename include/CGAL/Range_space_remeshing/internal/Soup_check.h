// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Range_space_remeshing team
//
// Whether a polygon soup is already an oriented 2-manifold mesh, by sorting its
// corners instead of CGAL's tree-based `is_polygon_soup_a_polygon_mesh()` (the
// test that decides whether the repair must run is on the path of every input).

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_CHECK_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_CHECK_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Throws Remeshing_error if the soup has no polygon, a corner naming no point or
/// a point that is not finite: nothing a repair could mend.
template <class PointRange, class PolygonRange>
void check_soup_values(const PointRange& points, const PolygonRange& polygons)
{
  if(polygons.empty())
    throw Remeshing_error("the input has no face");
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
      if(v >= points.size())
        throw Remeshing_error("the input has a face that names a missing vertex (index " + std::to_string(v) + ")");
  for(const auto& p : points)
    if(!std::isfinite(double(p.x())) || !std::isfinite(double(p.y())) || !std::isfinite(double(p.z())))
      throw Remeshing_error("the input has a NaN or infinite vertex coordinate");
}

/// Union-find over the corners of the soup.
class Corner_sets
{
public:
  explicit Corner_sets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }
  std::size_t find(std::size_t c)
  {
    while(parent_[c] != c)
      c = parent_[c] = parent_[parent_[c]];
    return c;
  }
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

private:
  std::vector<std::size_t> parent_;
};

/// One corner of a polygon: its point, the next corner's point, and where it is.
struct Directed_edge
{
  std::size_t from, to, corner;
  bool operator<(const Directed_edge& e) const { return std::tie(from, to) < std::tie(e.from, e.to); }
};

/// What keeps the soup from being an oriented 2-manifold mesh without unused or
/// coinciding points, in words ("" if nothing): the first problem found.
template <class PointRange, class PolygonRange>
std::string soup_problem(const PointRange& points, const PolygonRange& polygons)
{
  // corners: numbered polygon by polygon; first[f] is polygon f's first corner
  std::vector<std::size_t> first(polygons.size() + 1, 0), point_of;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    first[f + 1] = first[f] + polygons[f].size();
  point_of.reserve(first.back());
  std::vector<std::size_t> last_polygon(points.size(), std::size_t(-1)); // the last polygon using a point
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    if(polygons[f].size() < 3)
      return "a face has fewer than 3 corners";
    for(std::size_t v : polygons[f]) {
      if(last_polygon[v] == f)
        return "a face passes twice through the same vertex";
      last_polygon[v] = f;
      point_of.push_back(v);
    }
  }
  if(std::find(last_polygon.begin(), last_polygon.end(), std::size_t(-1)) != last_polygon.end())
    return "a vertex is used by no face";

  std::vector<std::size_t> by_position(points.size());
  std::iota(by_position.begin(), by_position.end(), std::size_t(0));
  auto less = [&points](std::size_t a, std::size_t b) {
    return std::make_tuple(points[a].x(), points[a].y(), points[a].z()) <
           std::make_tuple(points[b].x(), points[b].y(), points[b].z());
  };
  std::sort(by_position.begin(), by_position.end(), less);
  for(std::size_t i = 1; i < by_position.size(); ++i)
    if(!less(by_position[i - 1], by_position[i]))
      return "two vertices are at the same position";

  auto next_corner = [&](std::size_t f, std::size_t c) { return c + 1 < first[f + 1] ? c + 1 : first[f]; };
  std::vector<Directed_edge> edges;
  edges.reserve(point_of.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t c = first[f]; c < first[f + 1]; ++c)
      edges.push_back({point_of[c], point_of[next_corner(f, c)], c});
  std::sort(edges.begin(), edges.end());
  for(std::size_t i = 0; i < edges.size(); ++i) {
    if(i > 0 && !(edges[i - 1] < edges[i]))
      return "an edge is used twice in the same direction (inconsistent orientation or non-manifold edge)";
  }
  auto find_edge = [&edges](std::size_t from, std::size_t to) -> const Directed_edge* {
    const auto it = std::lower_bound(edges.begin(), edges.end(), Directed_edge{from, to, 0});
    return it != edges.end() && it->from == from && it->to == to ? &*it : nullptr;
  };

  // The corners around a point are linked across the edges they share; a manifold
  // vertex has them all in one fan. The corner at v before edge v->w is linked to
  // the corner at v after the opposite edge w->v (the one following w's corner).
  std::vector<std::size_t> polygon_of(point_of.size());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    std::fill(polygon_of.begin() + std::ptrdiff_t(first[f]), polygon_of.begin() + std::ptrdiff_t(first[f + 1]), f);
  Corner_sets fans(point_of.size());
  for(const Directed_edge& e : edges)
    if(const Directed_edge* opposite = find_edge(e.to, e.from))
      fans.unite(e.corner, next_corner(polygon_of[opposite->corner], opposite->corner));
  std::vector<std::size_t> fan_of(points.size(), std::size_t(-1));
  for(std::size_t c = 0; c < point_of.size(); ++c) {
    const std::size_t fan = fans.find(c);
    std::size_t& seen = fan_of[point_of[c]];
    if(seen == std::size_t(-1))
      seen = fan;
    else if(seen != fan)
      return "a vertex is non-manifold (its faces form more than one fan)";
  }
  return "";
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_CHECK_H
