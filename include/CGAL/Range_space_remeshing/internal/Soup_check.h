// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team
//
// Whether a polygon soup is already an oriented 2-manifold mesh, by sorting its
// corners instead of CGAL's tree-based `is_polygon_soup_a_polygon_mesh()` (the
// test that decides whether the repair must run is on the path of every input).

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_CHECK_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_CHECK_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Union_find.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

/// The corners of a soup, numbered polygon by polygon: the point at each, and the
/// next corner of its polygon.
struct Soup_corners
{
  std::vector<std::size_t> point_of, next_of;

  Soup_corners() = default;
  template <class PolygonRange>
  explicit Soup_corners(const PolygonRange& polygons)
  {
    for(const auto& polygon : polygons) {
      const std::size_t first = point_of.size();
      for(std::size_t v : polygon) {
        next_of.push_back(point_of.size() + 1);
        point_of.push_back(v);
      }
      if(point_of.size() > first)
        next_of.back() = first;
    }
  }
  std::size_t size() const { return point_of.size(); }
};

/// An edge of a polygon: its points in increasing order in one key (the high 32 bits
/// the lower point), the corner it starts at, and whether it goes up.
struct Polygon_edge
{
  std::uint64_t key;
  std::uint32_t corner;
  bool forward;
  bool operator<(const Polygon_edge& e) const { return key < e.key || (key == e.key && corner < e.corner); }
};

/// Sorts the edges of one lower point (a run of `sorted_polygon_edges()`), which
/// arrive in corner order, by their upper point: by insertion, which keeps the corner
/// order of equal keys, as there are about six; by std::sort where a point has many.
inline void sort_edges_of_a_point(Polygon_edge* first, Polygon_edge* last)
{
  if(last - first > 32) {
    std::sort(first, last);
    return;
  }
  for(Polygon_edge* e = first + (first != last); e < last; ++e)
    for(Polygon_edge* f = e; f > first && f->key < (f - 1)->key; --f)
      std::swap(*f, *(f - 1));
}

/// The edges of the polygons sorted by their points: one edge of the mesh is a run of
/// equal keys, one polygon's (a border edge) or two going opposite ways (an inner edge)
/// in an oriented 2-manifold; in a run, the corners keep their order. A counting sort
/// by the lower point, then each point's few edges by the upper one: linear, where a
/// comparison sort of all the edges took most of the time of reading a clean mesh.
inline std::vector<Polygon_edge> sorted_polygon_edges(const Soup_corners& corners)
{
  if(corners.size() >= (std::size_t(1) << 32))
    throw Remeshing_error("the input has more than 2^32 face corners");
  std::size_t points = 0;
  for(std::size_t p : corners.point_of)
    points = (std::max)(points, p + 1);
  std::vector<std::size_t> start(points + 1, 0); // of each lower point's run
  auto lower_point = [&corners](std::size_t c) {
    return (std::min)(corners.point_of[c], corners.point_of[corners.next_of[c]]);
  };
  for(std::size_t c = 0; c < corners.size(); ++c)
    ++start[lower_point(c) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Polygon_edge> edges(corners.size());
  std::vector<std::size_t> end(start.begin(), start.end() - 1);
  for(std::size_t c = 0; c < corners.size(); ++c) {
    const std::uint64_t from = corners.point_of[c], to = corners.point_of[corners.next_of[c]];
    edges[end[lower_point(c)]++] = {((std::min)(from, to) << 32) | (std::max)(from, to), std::uint32_t(c), from < to};
  }
  for(std::size_t p = 0; p < points; ++p)
    sort_edges_of_a_point(edges.data() + start[p], edges.data() + start[p + 1]);
  return edges;
}

/// A soup's corners and its polygons' edges sorted (`sorted_polygon_edges()`): what
/// `soup_problem()` finds, which `soup_to_mesh()` builds the mesh from when the soup
/// did not change in between (one sort of the edges, not two).
struct Soup_edges
{
  Soup_corners corners;
  std::vector<Polygon_edge> sorted;

  Soup_edges() = default;
  template <class PolygonRange>
  explicit Soup_edges(const PolygonRange& polygons) : corners(polygons), sorted(sorted_polygon_edges(corners))
  {}
  bool empty() const { return corners.size() == 0; }
};

/// What `soup_problem()` says of a soup that is an oriented 2-manifold mesh but for
/// points at the same position (a seam, or a soup of separate polygons).
inline const char* const coinciding_points = "two vertices are at the same position";

/// What keeps the soup from being an oriented 2-manifold mesh without unused or
/// coinciding points, in words ("" if nothing): the first problem found, coinciding
/// points only if there is no other. `edges` gets the soup's sorted edges where the
/// check gets as far as sorting them (it stays empty otherwise).
template <class PointRange, class PolygonRange>
std::string soup_problem(const PointRange& points, const PolygonRange& polygons, Soup_edges& edges)
{
  std::vector<std::size_t> last_polygon(points.size(), std::size_t(-1)); // the last polygon using a point
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    if(polygons[f].size() < 3)
      return "a face has fewer than 3 corners";
    for(std::size_t v : polygons[f]) {
      if(last_polygon[v] == f)
        return "a face passes twice through the same vertex";
      last_polygon[v] = f;
    }
  }
  if(std::find(last_polygon.begin(), last_polygon.end(), std::size_t(-1)) != last_polygon.end())
    return "a vertex is used by no face";

  // Across an inner edge a->b / b->a, the corners at a are neighbours around a, and
  // those at b around b; a manifold vertex has all its corners in one such fan.
  edges = Soup_edges(polygons);
  const auto& point_of = edges.corners.point_of;
  const auto& next_of = edges.corners.next_of;
  const std::vector<Polygon_edge>& sorted = edges.sorted;
  std::vector<std::size_t> fans(point_of.size()); // union-find forest of the corners
  std::iota(fans.begin(), fans.end(), std::size_t(0));
  auto unite = [&fans](std::size_t a, std::size_t b) { fans[union_find_root(fans, a)] = union_find_root(fans, b); };
  for(std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i + 1;
    while(j < sorted.size() && sorted[j].key == sorted[i].key)
      ++j;
    if(j - i > 2)
      return "an edge is shared by more than two faces";
    if(j - i == 2) {
      if(sorted[i].forward == sorted[i + 1].forward)
        return "two faces sharing an edge have opposite orientations";
      const std::size_t c1 = sorted[i].corner, c2 = sorted[i + 1].corner;
      unite(c1, next_of[c2]);
      unite(c2, next_of[c1]);
    }
    i = j;
  }
  std::vector<std::size_t> fan_of(points.size(), std::size_t(-1));
  for(std::size_t c = 0; c < point_of.size(); ++c) {
    const std::size_t fan = union_find_root(fans, c);
    std::size_t& seen = fan_of[point_of[c]];
    if(seen == std::size_t(-1))
      seen = fan;
    else if(seen != fan)
      return "a vertex is non-manifold (its faces form more than one fan)";
  }
  // last: a soup with no other problem is a mesh even with coinciding points
  std::vector<std::size_t> by_position(points.size());
  std::iota(by_position.begin(), by_position.end(), std::size_t(0));
  auto less = [&points](std::size_t a, std::size_t b) {
    return std::make_tuple(points[a].x(), points[a].y(), points[a].z()) <
           std::make_tuple(points[b].x(), points[b].y(), points[b].z());
  };
  std::sort(by_position.begin(), by_position.end(), less);
  for(std::size_t i = 1; i < by_position.size(); ++i)
    if(!less(by_position[i - 1], by_position[i]))
      return coinciding_points;

  return "";
}

template <class PointRange, class PolygonRange>
std::string soup_problem(const PointRange& points, const PolygonRange& polygons)
{
  Soup_edges edges;
  return soup_problem(points, polygons, edges);
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_CHECK_H
