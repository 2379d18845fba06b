// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team
//
// A polygon mesh from a soup that is an oriented 2-manifold, in linear time (but for
// the edges of a point of very high valence, sorted by comparison).
//
// Not CGAL's `polygon_soup_to_polygon_mesh()`: it adds one face at a time with
// `Euler::add_face()`, which looks each new edge up around its vertex, so a vertex of
// valence k costs k^2 steps; a fan of a few hundred thousand triangles around one
// point (a cone's apex, a large polygon split from one corner) does not finish. Here
// the halfedges are paired by the polygons' edges sorted once, by `soup_problem()`
// when it checked the soup.

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_TO_MESH_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_TO_MESH_H

#include <CGAL/Range_space_remeshing/internal/Soup_check.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Kernel_traits.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// `p` as a point of the mesh's point type.
template <class MeshPoint, class Point>
MeshPoint mesh_point(const Point& p)
{
  if constexpr(std::is_same<MeshPoint, Point>::value)
    return p;
  else
    return CGAL::Cartesian_converter<typename CGAL::Kernel_traits<Point>::Kernel,
                                     typename CGAL::Kernel_traits<MeshPoint>::Kernel>()(p);
}

/// Builds the halfedges of `mesh` from a soup of polygons.
template <class PolygonMesh>
class Soup_to_mesh
{
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;

public:
  Soup_to_mesh(const Soup_corners& corners, PolygonMesh& mesh)
    : corners_(corners), mesh_(mesh), halfedge_of_(corners.size(), GT::null_halfedge())
  {}

  /// Adds the soup's points as vertices, in their order.
  template <class PointRange>
  void add_vertices(const PointRange& points)
  {
    auto vpm = get(CGAL::vertex_point, mesh_);
    using Mesh_point = typename boost::property_traits<decltype(vpm)>::value_type;
    vertex_of_.reserve(points.size());
    for(const auto& p : points) {
      vertex_of_.push_back(add_vertex(mesh_));
      put(vpm, vertex_of_.back(), mesh_point<Mesh_point>(p));
    }
  }

  /// One edge per run of equal keys (`sorted_polygon_edges()`), created in the order of
  /// the first corner along it, its halfedge going that corner's way.
  void add_edges(const std::vector<Polygon_edge>& edges)
  {
    std::vector<std::size_t> run_starts;
    for(std::size_t i = 0; i < edges.size(); ++i)
      if(i == 0 || edges[i].key != edges[i - 1].key)
        run_starts.push_back(i);
    // in a run the corners are increasing: the first is the first corner along the
    // edge; the runs in the order of their first corners, by marking those corners
    constexpr std::size_t none = std::size_t(-1);
    std::vector<std::size_t> run_first_at(corners_.size(), none);
    for(std::size_t i : run_starts)
      run_first_at[edges[i].corner] = i;
    for(std::size_t i : run_first_at) {
      if(i == none)
        continue;
      const std::size_t c = edges[i].corner;
      const halfedge_descriptor h = halfedge(add_edge(mesh_), mesh_);
      set_target(h, vertex_of_[corners_.point_of[corners_.next_of[c]]], mesh_);
      set_target(opposite(h, mesh_), vertex_of_[corners_.point_of[c]], mesh_);
      set_face(opposite(h, mesh_), GT::null_face(), mesh_);
      halfedge_of_[c] = h;
      if(i + 1 < edges.size() && edges[i + 1].key == edges[i].key)
        halfedge_of_[edges[i + 1].corner] = opposite(h, mesh_);
    }
  }

  /// The faces, in the order of the polygons, each with the halfedge into its first
  /// corner; every vertex gets an incoming halfedge.
  template <class PolygonRange>
  void add_faces(const PolygonRange& polygons)
  {
    std::size_t c = 0;
    for(const auto& polygon : polygons) {
      const auto f = add_face(mesh_);
      for(std::size_t i = 0; i < polygon.size(); ++i, ++c) {
        const halfedge_descriptor h = halfedge_of_[c];
        set_face(h, f, mesh_);
        set_next(h, halfedge_of_[corners_.next_of[c]], mesh_);
        set_halfedge(target(h, mesh_), h, mesh_);
      }
      set_halfedge(f, halfedge_of_[c - 1], mesh_);
    }
  }

  /// Links the border halfedges: in a 2-manifold, one border halfedge leaves each border
  /// vertex, and it follows the one that arrives there, which becomes the vertex's
  /// halfedge (CGAL's convention for a vertex on a border).
  void link_borders()
  {
    // the border halfedge across a corner's edge goes from the next corner's point to its point
    std::vector<std::size_t> border_corners;
    std::vector<halfedge_descriptor> leaving(vertex_of_.size(), GT::null_halfedge());
    for(std::size_t c = 0; c < corners_.size(); ++c) {
      const halfedge_descriptor b = opposite(halfedge_of_[c], mesh_);
      if(face(b, mesh_) == GT::null_face()) {
        border_corners.push_back(c);
        leaving[corners_.point_of[corners_.next_of[c]]] = b;
      }
    }
    for(std::size_t c : border_corners) {
      const halfedge_descriptor b = opposite(halfedge_of_[c], mesh_);
      set_next(b, leaving[corners_.point_of[c]], mesh_);
      set_halfedge(target(b, mesh_), b, mesh_);
    }
  }

private:
  const Soup_corners& corners_;
  PolygonMesh& mesh_;
  std::vector<vertex_descriptor> vertex_of_;
  std::vector<halfedge_descriptor> halfedge_of_; // the halfedge of each corner's polygon edge
};

/// Adds to the empty `mesh` the soup `points`, `polygons`, which `soup_problem()` finds
/// to be an oriented 2-manifold (points at the same position allowed): the vertices in
/// the points' order, the faces in the polygons' order. `edges`: the soup's, as that
/// check left them.
template <class PointRange, class PolygonRange, class PolygonMesh>
void soup_to_mesh(const PointRange& points, const PolygonRange& polygons, const Soup_edges& edges,
                  PolygonMesh& mesh)
{
  using GT = boost::graph_traits<PolygonMesh>;
  CGAL_precondition_code(std::size_t corners = 0; for(const auto& polygon : polygons) corners += polygon.size();)
  CGAL_precondition(edges.corners.size() == corners && edges.sorted.size() == corners);
  reserve(mesh, typename GT::vertices_size_type(points.size()), typename GT::edges_size_type(edges.corners.size()),
          typename GT::faces_size_type(polygons.size()));
  Soup_to_mesh<PolygonMesh> builder(edges.corners, mesh);
  builder.add_vertices(points);
  builder.add_edges(edges.sorted);
  builder.add_faces(polygons);
  builder.link_borders();
}

template <class PointRange, class PolygonRange, class PolygonMesh>
void soup_to_mesh(const PointRange& points, const PolygonRange& polygons, PolygonMesh& mesh)
{
  soup_to_mesh(points, polygons, Soup_edges(polygons), mesh);
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_SOUP_TO_MESH_H
