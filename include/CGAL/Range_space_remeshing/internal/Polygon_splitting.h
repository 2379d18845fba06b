// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team
//
// Splits the polygons of a soup into triangles before the remesher sees them: a
// convex polygon as a fan (a quadrilateral along its shorter diagonal), a
// non-convex one by a constrained triangulation in its plane, so that no triangle
// leaves the polygon (a fan from a corner next to a reflex one folds over it).

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_SPLITTING_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_SPLITTING_H

#include <CGAL/Range_space_remeshing/internal/Polygon_tests.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Projection_traits_yz_3.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <queue>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

using Index_pairs = std::unordered_set<std::pair<std::size_t, std::size_t>, boost::hash<std::pair<std::size_t, std::size_t>>>;
using Index_triangles = std::vector<std::array<std::size_t, 3>>;

/// The largest polygon whose diagonals the split checks against the other faces' edges
/// (the search is quadratic). A larger one is split as a fan from its first corner or
/// by its constrained triangulation, and a soup of triangles and such polygons only
/// does not collect its edges at all.
constexpr std::size_t largest_checked_polygon = 32;


/// The edges of the soup's polygons, each as its two point indices in increasing order.
template <class PolygonRange>
Index_pairs polygon_edges(const PolygonRange& polygons)
{
  Index_pairs edges;
  edges.reserve(2 * polygons.size());
  for(const auto& polygon : polygons)
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const std::size_t a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      edges.emplace((std::min)(a, b), (std::max)(a, b));
    }
  return edges;
}

/// The axis most nearly normal to the polygon (0, 1 or 2), by its Newell normal:
/// dropping it projects the polygon onto the plane where it is widest. Computed in
/// doubles: it only chooses the plane, every decision after is exact in it.
template <class Point>
int axis_most_normal(const std::vector<Point>& corners)
{
  std::vector<Vec3> polygon;
  polygon.reserve(corners.size());
  for(const Point& p : corners)
    polygon.push_back(to_vec3(p));
  const Vec3 n = newell_normal(polygon);
  int axis = 2;
  for(int i = 0; i < 2; ++i)
    if(std::abs(n[i]) > std::abs(n[axis]))
      axis = i;
  return axis;
}

/// Marks the faces of `cdt` inside its constraints (a simple polygon): those not
/// reached from the infinite face without crossing a constraint.
template <class Cdt>
void mark_inside(Cdt& cdt)
{
  for(auto f : cdt.all_face_handles())
    f->info() = true;
  std::queue<typename Cdt::Face_handle> outside;
  cdt.infinite_face()->info() = false;
  outside.push(cdt.infinite_face());
  while(!outside.empty()) {
    const auto f = outside.front();
    outside.pop();
    for(int i = 0; i < 3; ++i) {
      const auto g = f->neighbor(i);
      if(g->info() && !cdt.is_constrained(std::make_pair(f, i))) {
        g->info() = false;
        outside.push(g);
      }
    }
  }
}

/// The triangles of the constrained triangulation of `corners` (a simple polygon
/// seen along `Projection`'s axis) inside it, as indices into `corners` and turning
/// as the polygon does; empty if the triangulation does not give the `n - 2`
/// triangles a simple polygon has. CGAL's triangulation rather than ear clipping by
/// hand: it is exact and O(n log n) on polygons of any size.
template <class Projection, class Point>
Index_triangles triangulate_simple_polygon(const std::vector<Point>& corners)
{
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Projection>;
  using Fb = CGAL::Triangulation_face_base_with_info_2<bool, Projection,
                                                       CGAL::Constrained_triangulation_face_base_2<Projection>>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Projection, Tds, CGAL::No_constraint_intersection_tag>;
  const std::size_t n = corners.size();
  Cdt cdt;
  std::vector<typename Cdt::Vertex_handle> vertices;
  vertices.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    vertices.push_back(cdt.insert(corners[i]));
    vertices.back()->info() = i;
  }
  if(cdt.number_of_vertices() != n)
    return {}; // two corners at one place in the projection
  for(std::size_t i = 0; i < n; ++i)
    cdt.insert_constraint(vertices[i], vertices[(i + 1) % n]);
  mark_inside(cdt);
  const bool reversed = CGAL::orientation_2(corners.begin(), corners.end(), Projection()) == CGAL::CLOCKWISE;
  Index_triangles triangles;
  for(auto f : cdt.finite_face_handles())
    if(f->info()) {
      const std::size_t a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
      triangles.push_back(reversed ? std::array<std::size_t, 3>{a, c, b} : std::array<std::size_t, 3>{a, b, c});
    }
  if(triangles.size() != n - 2)
    triangles.clear();
  return triangles;
}

/// Whether triangles of a polygon (indices into its corners) have a diagonal that is
/// `taken`: an edge of the mesh, or a diagonal of a polygon split before.
template <class Polygon>
bool uses_a_taken_diagonal(const Index_triangles& triangles, const Polygon& polygon, const Index_pairs& taken)
{
  const std::size_t n = polygon.size();
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i) {
      const std::size_t a = t[i], b = t[(i + 1) % 3];
      const bool side = (a + 1) % n == b || (b + 1) % n == a;
      if(!side && taken.count(std::minmax(std::size_t(polygon[a]), std::size_t(polygon[b]))))
        return true;
    }
  return false;
}

/// A fan of a simple polygon (seen along `Projection`'s axis) from a corner that sees
/// all the others (every triangle turns as the polygon does, so none leaves it) and
/// whose diagonals are all free; empty if there is none. Where the constrained
/// triangulation takes an edge of the mesh as a diagonal (two faces sharing two
/// corners that are not neighbours in one of them), it would give an edge of more
/// than two triangles.
template <class Projection, class Point, class Polygon>
Index_triangles star_fan_with_free_diagonals(const std::vector<Point>& corners, const Polygon& polygon,
                                             const Index_pairs& taken)
{
  const std::size_t n = corners.size();
  const CGAL::Orientation turn = CGAL::orientation_2(corners.begin(), corners.end(), Projection());
  const auto orientation = Projection().orientation_2_object();
  for(std::size_t apex = 0; apex < n; ++apex) {
    Index_triangles fan;
    for(std::size_t i = 1; i + 1 < n; ++i) {
      const std::size_t b = (apex + i) % n, c = (apex + i + 1) % n;
      if(orientation(corners[apex], corners[b], corners[c]) != turn ||
         (i > 1 && taken.count(std::minmax(std::size_t(polygon[apex]), std::size_t(polygon[b])))))
        break;
      fan.push_back({apex, b, c});
    }
    if(fan.size() == n - 2)
      return fan;
  }
  return {};
}

/// The triangles of a polygon with a reflex corner, seen along `Projection`'s axis,
/// or empty if it is convex there (CGAL's test: consistent turns, once around) or not
/// simple (it crosses itself: no triangulation stays inside it, and CGAL's would have
/// to construct the crossings).
template <class Projection, class Point, class Polygon>
Index_triangles triangulate_if_non_convex(const std::vector<Point>& corners, const Polygon& polygon,
                                          const Index_pairs& taken)
{
  if(CGAL::is_convex_2(corners.begin(), corners.end(), Projection()) ||
     !CGAL::is_simple_2(corners.begin(), corners.end(), Projection()))
    return {};
  Index_triangles triangles = triangulate_simple_polygon<Projection>(corners);
  if(!triangles.empty() && polygon.size() <= largest_checked_polygon &&
     uses_a_taken_diagonal(triangles, polygon, taken)) {
    Index_triangles fan = star_fan_with_free_diagonals<Projection>(corners, polygon, taken);
    if(!fan.empty())
      triangles = std::move(fan);
  }
  return triangles;
}

/// The triangles of a non-convex simple polygon (as indices into `points`) in the
/// plane where it is widest; empty for a convex polygon, or one that is not simple.
template <class PointRange, class Polygon>
Index_triangles triangulate_non_convex(const PointRange& points, const Polygon& polygon, const Index_pairs& taken)
{
  using Point = typename PointRange::value_type;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  std::vector<Point> corners;
  corners.reserve(polygon.size());
  for(std::size_t v : polygon)
    corners.push_back(points[v]);
  Index_triangles triangles;
  switch(axis_most_normal(corners)) {
  case 0: triangles = triangulate_if_non_convex<CGAL::Projection_traits_yz_3<K>>(corners, polygon, taken); break;
  case 1: triangles = triangulate_if_non_convex<CGAL::Projection_traits_xz_3<K>>(corners, polygon, taken); break;
  default: triangles = triangulate_if_non_convex<CGAL::Projection_traits_xy_3<K>>(corners, polygon, taken); break;
  }
  for(auto& triangle : triangles)
    for(std::size_t& corner : triangle)
      corner = polygon[corner];
  return triangles;
}

/// Whether a quadrilateral of `points` is split along its diagonal p[0]p[2]: the
/// shorter one, unless it is an edge already or another quadrilateral's diagonal
/// (two quadrilaterals around a vertex of valence 2 both find that diagonal shorter:
/// split along it, they would give one triangle twice). `taken` holds the edges and
/// the diagonals chosen so far, and gets this one.
template <class PointRange, class Polygon>
bool split_along_first_diagonal(const PointRange& points, const Polygon& p, Index_pairs& taken)
{
  const auto key = [](std::size_t a, std::size_t b) { return std::make_pair((std::min)(a, b), (std::max)(a, b)); };
  // both lengths compared exactly: a squared length computed apart can overflow
  bool first = CGAL::compare_distance(points[p[0]], points[p[2]], points[p[1]], points[p[3]]) != CGAL::LARGER;
  if(taken.count(first ? key(p[0], p[2]) : key(p[1], p[3])) && !taken.count(first ? key(p[1], p[3]) : key(p[0], p[2])))
    first = !first;
  taken.insert(first ? key(p[0], p[2]) : key(p[1], p[3]));
  return first;
}

/// The corner of polygon `p` to split it from as a fan: the first whose diagonals are
/// all free (neither an edge nor a diagonal taken: two faces sharing two corners that
/// are not neighbours in one of them, as beside a split parallel edge of the primal,
/// would give an edge of more than two triangles), or the first corner if none is or
/// the polygon is too large to look (a quadratic search).
template <class Polygon>
std::size_t fan_corner(const Polygon& p, const Index_pairs& taken)
{
  if(taken.empty() || p.size() > largest_checked_polygon)
    return 0;
  for(std::size_t apex = 0; apex < p.size(); ++apex) {
    bool free = true;
    for(std::size_t i = 2; i + 1 < p.size() && free; ++i)
      free = !taken.count(std::minmax(std::size_t(p[apex]), std::size_t(p[(apex + i) % p.size()])));
    if(free)
      return apex;
  }
  return 0;
}

/// The triangles of a convex polygon (or of one that crosses itself, which no split
/// mends): a quadrilateral along a diagonal (see above), a larger polygon as a fan
/// from a corner whose diagonals are free (see above).
template <class PointRange, class Polygon>
Index_triangles split_convex(const PointRange& points, const Polygon& p, Index_pairs& taken)
{
  if(p.size() == 4) {
    if(split_along_first_diagonal(points, p, taken))
      return {{p[0], p[1], p[2]}, {p[0], p[2], p[3]}};
    return {{p[1], p[2], p[3]}, {p[1], p[3], p[0]}};
  }
  const std::size_t apex = fan_corner(p, taken), k = p.size();
  Index_triangles fan;
  for(std::size_t i = 1; i + 1 < k; ++i) {
    fan.push_back({p[apex], p[(apex + i) % k], p[(apex + i + 1) % k]});
    if(!taken.empty() && i > 1 && k <= largest_checked_polygon)
      taken.insert(std::minmax(std::size_t(p[apex]), std::size_t(p[(apex + i) % k])));
  }
  return fan;
}

/// The edge two triangles share, its point indices in increasing order.
inline std::pair<std::size_t, std::size_t> shared_edge(const std::array<std::size_t, 3>& t,
                                                       const std::array<std::size_t, 3>& u)
{
  std::vector<std::size_t> common;
  for(std::size_t a : t)
    if(std::find(u.begin(), u.end(), a) != u.end())
      common.push_back(a);
  CGAL_assertion(common.size() == 2);
  return std::minmax(common[0], common[1]);
}

/// Whether the split of a non-convex quadrilateral `p` into `triangles` (along the
/// diagonal through its reflex corner) can stand, and if so takes that diagonal.
/// Not if another quadrilateral took the diagonal and the other one is free: two
/// quadrilaterals around a vertex of valence 2 would give one triangle twice (a
/// non-manifold edge), where the other diagonal only folds the quadrilateral.
template <class Polygon>
bool take_reflex_diagonal(const Polygon& p, const Index_triangles& triangles, Index_pairs& taken)
{
  using Pair = std::pair<std::size_t, std::size_t>;
  const Pair diagonal = shared_edge(triangles[0], triangles[1]);
  const Pair first = std::minmax(std::size_t(p[0]), std::size_t(p[2]));
  const Pair other = diagonal == first ? Pair(std::minmax(std::size_t(p[1]), std::size_t(p[3]))) : first;
  if(taken.count(diagonal) && !taken.count(other))
    return false;
  taken.insert(diagonal);
  return true;
}

/// Adds the diagonals of a split polygon's triangles (point indices) to `taken`.
inline void take_diagonals(const Index_triangles& triangles, Index_pairs& taken)
{
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i)
      taken.insert(std::minmax(t[i], t[(i + 1) % 3])); // the sides are in it already
}

/// Splits every polygon of the soup into triangles, in the soup: a non-convex one by
/// a constrained triangulation in its plane, a convex one as `split_convex()` does.
/// Not CGAL's `triangulate_faces()`: on a non-planar polygon whose projection crosses
/// itself its constrained triangulation can run without end (found by the fuzzers
/// on a quadrilateral), and it falls back to hole filling, whose time grows as the
/// cube of the corners. A split that still breaks the mesh (a fan's diagonal that
/// is an edge already) is then repaired like any other defect. Returns the polygons
/// split.
template <class PointRange, class PolygonRange>
std::size_t split_polygons(const PointRange& points, PolygonRange& polygons)
{
  const bool has_polygons = std::any_of(polygons.begin(), polygons.end(), [](const auto& polygon) {
    return polygon.size() > 3 && polygon.size() <= largest_checked_polygon;
  });
  Index_pairs taken; // edges, and diagonals chosen
  if(has_polygons)
    taken = polygon_edges(polygons);
  std::size_t split = 0;
  const std::size_t count = polygons.size();
  for(std::size_t f = 0; f < count; ++f) {
    auto& polygon = polygons[f];
    if(polygon.size() <= 3)
      continue;
    ++split;
    Index_triangles triangles = triangulate_non_convex(points, polygon, taken);
    if(triangles.empty() || (polygon.size() == 4 && !take_reflex_diagonal(polygon, triangles, taken)))
      triangles = split_convex(points, polygon, taken);
    else if(polygon.size() > 4 && polygon.size() <= largest_checked_polygon && !taken.empty())
      take_diagonals(triangles, taken);
    polygon.assign(triangles[0].begin(), triangles[0].end()); // before emplace_back() may move it
    for(std::size_t t = 1; t < triangles.size(); ++t)
      polygons.emplace_back(triangles[t].begin(), triangles[t].end());
  }
  return split;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_POLYGON_SPLITTING_H
