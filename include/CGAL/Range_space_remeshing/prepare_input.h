// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_PREPARE_INPUT_H
#define CGAL_RANGE_SPACE_REMESHING_PREPARE_INPUT_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_splitting.h>
#include <CGAL/Range_space_remeshing/internal/Soup_check.h>
#include <CGAL/Range_space_remeshing/internal/Soup_to_mesh.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingRef

What `prepare_input()` changed to turn a polygon soup into a triangle mesh the
remesher accepts. Nothing is dropped or changed without being counted here.
*/
struct Input_repair_statistics
{
  /// points at the same position as another one, merged into it
  std::size_t merged_points = 0;
  /// points no polygon uses, removed in any case (they would count in bounding boxes)
  std::size_t removed_isolated_points = 0;
  /// corners repeated one after the other in a polygon, removed
  std::size_t removed_repeated_corners = 0;
  /// polygons left with fewer than 3 corners, or passing twice through a point, removed
  std::size_t removed_degenerate_polygons = 0;
  /// polygons with the same corners as another one, removed
  std::size_t removed_duplicate_polygons = 0;
  /// polygons reversed against the file to orient their connected piece consistently
  /// (each counted once, in the mesh returned: a polygon reversed for consistency and
  /// then back to face outward is not)
  std::size_t reversed_polygons = 0;
  /// triangles reversed against the file so that a repaired closed surface faces
  /// outward, and not counted in `reversed_polygons`
  std::size_t reversed_to_face_outward = 0;
  /// edges with more than two polygons (they become borders)
  std::size_t non_manifold_edges = 0;
  /// points copied to split a non-manifold vertex into manifold ones
  std::size_t split_non_manifold_points = 0;
  /// polygons with more than three corners, split into triangles
  std::size_t triangulated_polygons = 0;

  /// Whether the input was repaired: changed by more than the removal of unused points
  /// and the triangulation of polygons, which `Input_repair::REFUSE` does too.
  bool repaired() const
  {
    return merged_points + removed_repeated_corners + removed_degenerate_polygons + removed_duplicate_polygons +
               reversed_polygons + reversed_to_face_outward + non_manifold_edges + split_non_manifold_points >
           0;
  }
};

/*!
\ingroup PkgRangeSpaceRemeshingRef

How `prepare_input()` treats a soup that is not already an oriented 2-manifold.
*/
enum class Input_repair
{
  /// Repairs it with CGAL's polygon soup repair and orientation (the default).
  REPAIR,
  /// Throws `Remeshing_error` naming the first problem found.
  REFUSE
};

namespace internal {

/// Counts what `orient_polygon_soup()` does, and marks the polygons it leaves reversed
/// (CGAL copies its visitor: counters by pointer).
struct Counting_orientation_visitor : public CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  Input_repair_statistics* statistics;
  std::vector<bool>* reversed; // by polygon
  Counting_orientation_visitor(Input_repair_statistics* s, std::vector<bool>* r) : statistics(s), reversed(r) {}
  void non_manifold_edge(std::size_t, std::size_t, std::size_t) { ++statistics->non_manifold_edges; }
  void duplicated_vertex(std::size_t, std::size_t) { ++statistics->split_non_manifold_points; }
  void polygon_orientation_reversed(std::size_t polygon) { (*reversed)[polygon] = !(*reversed)[polygon]; }
};

/// Removes the points no polygon uses, keeping the others in their order.
template <class PointRange, class PolygonRange>
void remove_isolated_points(PointRange& points, PolygonRange& polygons, Input_repair_statistics& statistics)
{
  std::vector<std::size_t> new_index(points.size(), 0);
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
      new_index[v] = 1;
  std::size_t kept = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(new_index[v]) {
      new_index[v] = kept;
      points[kept++] = points[v];
    }
  statistics.removed_isolated_points += points.size() - kept;
  if(kept == points.size())
    return;
  points.resize(kept);
  for(auto& polygon : polygons)
    for(std::size_t& v : polygon)
      v = new_index[v];
}

/// Merges the points at the same position if the soup is then still an oriented
/// 2-manifold; `edges` are then the merged soup's.
template <class PointRange, class PolygonRange>
void merge_if_still_a_mesh(PointRange& points, PolygonRange& polygons, Soup_edges& edges,
                           Input_repair_statistics& statistics)
{
  PointRange merged_points = points;
  PolygonRange merged_polygons = polygons;
  const std::size_t merged =
      CGAL::Polygon_mesh_processing::merge_duplicate_points_in_polygon_soup(merged_points, merged_polygons);
  Soup_edges merged_edges;
  if(!soup_problem(merged_points, merged_polygons, merged_edges).empty())
    return;
  edges = std::move(merged_edges);
  points.swap(merged_points);
  polygons.swap(merged_polygons);
  statistics.merged_points += merged;
}

/// Removes the corners equal to the one before them (cyclically), then the polygons
/// with fewer than 3 corners or a corner twice (pinched: no orientable disk).
template <class PolygonRange>
void remove_degenerate_polygons(PolygonRange& polygons, Input_repair_statistics& statistics)
{
  std::vector<std::size_t> sorted;
  auto kept = polygons.begin();
  for(auto& polygon : polygons) {
    std::vector<std::size_t> corners;
    for(std::size_t v : polygon)
      if(corners.empty() || corners.back() != v)
        corners.push_back(v);
    while(corners.size() > 1 && corners.front() == corners.back())
      corners.pop_back();
    statistics.removed_repeated_corners += polygon.size() - corners.size();
    sorted.assign(corners.begin(), corners.end());
    std::sort(sorted.begin(), sorted.end());
    if(corners.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      ++statistics.removed_degenerate_polygons;
      continue;
    }
    polygon.assign(corners.begin(), corners.end());
    if(&*kept != &polygon)
      *kept = std::move(polygon);
    ++kept;
  }
  polygons.erase(kept, polygons.end());
}

/// The repairs of CGAL's polygon mesh processing, each counted: merge coinciding
/// points, drop degenerate and duplicate polygons and unused points, orient the
/// polygons and split the non-manifold vertices and edges. Returns, by polygon of
/// the repaired soup, whether the orientation reversed it.
template <class PointRange, class PolygonRange>
std::vector<bool> repair_soup(PointRange& points, PolygonRange& polygons, Input_repair_statistics& statistics)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  statistics.merged_points += PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  remove_degenerate_polygons(polygons, statistics);
  statistics.removed_duplicate_polygons += PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  remove_isolated_points(points, polygons, statistics);
  std::vector<bool> reversed(polygons.size(), false);
  PMP::orient_polygon_soup(points, polygons,
                           CGAL::parameters::visitor(Counting_orientation_visitor(&statistics, &reversed)));
  statistics.reversed_polygons += std::size_t(std::count(reversed.begin(), reversed.end(), true));
  return reversed;
}

/// Whether some triangle of `mesh` has corners that are not on one line (exactly).
template <class TriangleMesh>
bool has_a_non_degenerate_face(const TriangleMesh& mesh)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    if(!CGAL::collinear(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)), get(vpm, target(next(h, mesh), mesh))))
      return true;
  }
  return false;
}

/// Orients each closed piece of a repaired triangle mesh outward (the repair's
/// orientation is consistent but arbitrary) and counts the triangles reversed.
template <class TriangleMesh>
void orient_outward(TriangleMesh& mesh, const std::vector<bool>& reversed_by_repair,
                    Input_repair_statistics& statistics)
{
  if(!CGAL::is_closed(mesh))
    return; // CGAL's orient() needs a closed surface; an open one has no outside
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> first_edges;
  for(auto f : faces(mesh))
    first_edges.emplace_back(source(halfedge(f, mesh), mesh), target(halfedge(f, mesh), mesh));
  try {
    CGAL::Polygon_mesh_processing::orient(mesh);
  } catch(const std::exception&) {
    // CGAL's assertions (on in debug builds) refuse a surface too degenerate to have
    // an outside (found by fuzz_read): it stays consistently oriented, either way
    return;
  }
  std::size_t i = 0;
  for(auto f : faces(mesh)) { // faces keep their descriptors: a reversed one has its edge backwards
    const std::size_t face = i++;
    const auto [u, v] = first_edges[face];
    bool kept = false;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      kept = kept || (source(h, mesh) == u && target(h, mesh) == v);
    // the faces are the repaired soup's polygons, in order: one reversed twice is as in the file
    const bool by_repair = face < reversed_by_repair.size() && reversed_by_repair[face];
    if(!kept && by_repair)
      --statistics.reversed_polygons;
    else if(!kept)
      ++statistics.reversed_to_face_outward;
  }
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

Turns a polygon soup, as files give it (STL: every triangle with its own three
points; scans: a few non-manifold vertices, inconsistent orientation, duplicated or
degenerate faces, unused points), into the triangle mesh the remesher needs.

A soup that is already an oriented 2-manifold without unused points is copied
as it is (in its order), after one hash-free check in O(n log n). Otherwise,
with `Input_repair::REPAIR`, CGAL's repair runs: points at the same position are
merged, polygons with a repeated corner or fewer than 3 corners and duplicated
polygons are removed, unused points are removed, the polygons are oriented
(`CGAL::Polygon_mesh_processing::orient_polygon_soup()`), which splits non-manifold
vertices and edges. Polygons are split into triangles first: a convex one (in the
plane where it is widest) as a quadrilateral along its shorter diagonal or a larger
polygon as a fan from its first corner, a non-convex one by a constrained Delaunay
triangulation inside it (a polygon whose projection crosses itself, as a fan); a repaired
closed surface is oriented outward (`CGAL::Polygon_mesh_processing::orient()`). Every change is counted in the
returned statistics. Since points are only merged where they coincide or copied,
every vertex of `mesh` sits at the position of some input point: an attribute of
the points follows them by position.

\tparam PointRange a `std::vector` of points (the `Point_3` of a CGAL kernel)
\tparam PolygonRange a `std::vector` of `std::vector<std::size_t>`
\tparam PolygonMesh a model of `MutableFaceGraph`

\param points the points of the soup; modified by the repair
\param polygons the polygons of the soup (indices into `points`); modified by the repair
\param mesh receives the triangle mesh (cleared first)
\param repair `Input_repair::REFUSE` throws instead of repairing

\throws Remeshing_error if the soup has no polygon, a corner that names no point, a
NaN or infinite coordinate, no area (every triangle with its corners on one line), or (with `Input_repair::REFUSE`) anything to repair; the
message names the problem.
*/
template <class PointRange, class PolygonRange, class PolygonMesh>
Input_repair_statistics prepare_input(PointRange& points, PolygonRange& polygons, PolygonMesh& mesh,
                                      Input_repair repair = Input_repair::REPAIR)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Input_repair_statistics statistics;
  internal::check_soup_values(points, polygons);
  internal::remove_isolated_points(points, polygons, statistics); // never repaired away: unused
  statistics.triangulated_polygons = internal::split_polygons(points, polygons);
  internal::Soup_edges edges; // sorted by the last check, of the soup as it is then
  std::string problem = internal::soup_problem(points, polygons, edges);
  std::vector<bool> reversed; // by polygon, by the repair's orientation
  if(problem == internal::coinciding_points) {
    // a mesh already, with points at the same position: joined where that closes seams
    // or a soup of separate polygons into a mesh, kept apart where it would not
    // (as at the pinched holes of CGAL's elephant-with-holes) and with REFUSE
    if(repair == Input_repair::REPAIR)
      internal::merge_if_still_a_mesh(points, polygons, edges, statistics);
    problem.clear();
  }
  if(!problem.empty()) {
    if(repair == Input_repair::REFUSE)
      throw Remeshing_error("the input is not an oriented 2-manifold mesh: " + problem);
    reversed = internal::repair_soup(points, polygons, statistics);
    if(polygons.empty())
      throw Remeshing_error("the input has no face left after removing its degenerate faces");
    // points left at the same position are apart in the mesh: what CGAL's repair keeps
    const std::string left = internal::soup_problem(points, polygons, edges);
    if(!left.empty() && left != internal::coinciding_points)
      throw Remeshing_error("the input could not be repaired into a 2-manifold mesh: " + left);
  }
  clear(mesh);
  internal::soup_to_mesh(points, polygons, edges, mesh);
  if(!problem.empty())
    internal::orient_outward(mesh, reversed, statistics);
  if(!internal::has_a_non_degenerate_face(mesh))
    throw Remeshing_error("the input has no area: every face is degenerate (its corners on one line)");
  return statistics;
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_PREPARE_INPUT_H
