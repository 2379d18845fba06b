// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CREASE_TRIANGLES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CREASE_TRIANGLES_H

// The builder behind insert_crease_triangles() (section 8 of the paper): the creases
// are marked, each vertex is copied once per smooth sector of faces around it, the
// faces take the copies of their sectors, two zero-area triangles per crease edge
// close the crack between its sides, and a fan closes the zero-size polygon left at
// each corner where three or more sectors meet.

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>
#include <CGAL/Range_space_remeshing/internal/Soup_to_mesh.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

inline double cosine_of_degrees(double degrees) { return std::cos(degrees * 3.14159265358979323846 / 180); }

/// Whether the unit normals of the two faces of the edge of `h` make an angle whose
/// cosine is below `cos_sharp` (a face without area has the zero normal).
template <class TriangleMesh, class VertexPointMap>
bool is_sharper_than(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm,
                     const VertexPointMap& vpm, double cos_sharp)
{
  auto face_normal = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor g) {
    const Vec3 a = to_vec3(get(vpm, source(g, tm))), b = to_vec3(get(vpm, target(g, tm))),
               c = to_vec3(get(vpm, target(next(g, tm), tm)));
    return normalized(cross(difference(b, a), difference(c, a)));
  };
  return dot(face_normal(h), face_normal(opposite(h, tm))) < cos_sharp;
}

template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class HalfedgeIndexMap>
class Crease_triangles
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

public:
  Crease_triangles(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vertex_index,
                   HalfedgeIndexMap halfedge_index)
    : tm_(tm), vpm_(vpm), vertex_index_(vertex_index), halfedge_index_(halfedge_index),
      feature_(num_halfedges(tm), 0), copy_of_(num_halfedges(tm)), copies_(num_vertices(tm))
  {}

  /// Builds `out` with the edges for which `is_feature(h)` holds as creases.
  template <class IsFeature>
  Crease_statistics run(IsFeature is_feature, TriangleMesh& out)
  {
    mark_creases(is_feature);
    for(vertex_descriptor v : vertices(tm_))
      copy_per_sector(v);
    add_faces();
    add_crease_strips();
    build(out);
    close_corners(out);
    return stats_;
  }

private:
  std::size_t index(halfedge_descriptor h) const { return get(halfedge_index_, h); }

  template <class IsFeature>
  void mark_creases(IsFeature is_feature)
  {
    for(edge_descriptor e : edges(tm_))
      if(is_feature(halfedge(e, tm_))) {
        feature_[index(halfedge(e, tm_))] = feature_[index(opposite(halfedge(e, tm_), tm_))] = 1;
        ++stats_.feature_edges;
      }
  }

  // A copy of v per sector: the faces around it between two creases. The copy used by
  // the corner of face(h) at target(h) is copy_of_[h].
  void copy_per_sector(vertex_descriptor v)
  {
    halfedge_descriptor start = halfedge(v, tm_); // target v; a sector starts after a crease
    std::size_t creases = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_))
      if(feature_[index(h)]) {
        start = h;
        ++creases;
      }
    const Vec3 p = to_vec3(get(vpm_, v));
    std::vector<std::size_t>& copies = copies_[get(vertex_index_, v)];
    if(creases < 2) { // one crease ending here does not split the faces around v
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_))
        copy_of_[index(h)] = points_.size();
      copies.push_back(points_.size());
      points_.push_back(p);
      return;
    }
    // walk around the target from `start`: each crease halfedge begins a new sector
    halfedge_descriptor h = start;
    do {
      if(feature_[index(h)]) {
        copies.push_back(points_.size());
        points_.push_back(p);
      }
      copy_of_[index(h)] = points_.size() - 1;
      h = opposite(next(h, tm_), tm_);
    } while(h != start);
    stats_.added_vertices += copies.size() - 1;
  }

  void add_faces()
  {
    for(auto f : faces(tm_)) {
      const halfedge_descriptor h = halfedge(f, tm_);
      triangles_.push_back({{copy_of_[index(prev(h, tm_))], copy_of_[index(h)], copy_of_[index(next(h, tm_))]}});
    }
  }

  // Two zero-area triangles per crease edge, closing the crack between its sides:
  // f has a_f -> b_f, g has b_g -> a_g; the strip is b_f, a_f, a_g, b_g.
  void add_crease_strips()
  {
    for(edge_descriptor e : edges(tm_)) {
      const halfedge_descriptor h = halfedge(e, tm_), o = opposite(h, tm_);
      if(!feature_[index(h)])
        continue;
      const std::size_t b_f = copy_of_[index(h)], a_f = copy_of_[index(prev(h, tm_))];
      const std::size_t a_g = copy_of_[index(o)], b_g = copy_of_[index(prev(o, tm_))];
      if(a_f != a_g) {
        triangles_.push_back({{b_f, a_f, a_g}});
        ++stats_.crease_triangles;
      }
      if(b_f != b_g) {
        triangles_.push_back({{b_f, a_g, b_g}});
        ++stats_.crease_triangles;
      }
    }
  }

  void build(TriangleMesh& out) const
  {
    std::vector<std::vector<std::size_t>> polygons(triangles_.size());
    for(std::size_t t = 0; t < triangles_.size(); ++t)
      polygons[t].assign(triangles_[t].begin(), triangles_[t].end());
    clear(out);
    std::vector<Point> out_points;
    for(const Vec3& p : points_)
      out_points.emplace_back(p[0], p[1], p[2]);
    // the package's builder, not CGAL's polygon_soup_to_polygon_mesh(), which looks each
    // new edge up around its vertex: k^2 steps at a vertex of valence k
    soup_to_mesh(out_points, polygons, out);
  }

  // At a vertex with three or more sectors the copies bound a zero-size polygon, a
  // hole of `out`: filled, then split into a fan from one corner.
  void close_corners(TriangleMesh& out)
  {
    std::vector<halfedge_descriptor> holes;
    for(auto h : halfedges(out))
      if(is_border(h, out))
        holes.push_back(h);
    std::vector<char> filled(num_halfedges(out), 0);
    auto out_halfedge_index = CGAL::get_initialized_halfedge_index_map(out);
    for(halfedge_descriptor h : holes) {
      if(filled[get(out_halfedge_index, h)] || !is_border(h, out))
        continue;
      std::size_t corners = 0; // the hole's, counted once: degree() at each split is O(k), O(k^2) in all
      for(halfedge_descriptor g : CGAL::halfedges_around_face(h, out)) {
        filled[get(out_halfedge_index, g)] = 1;
        ++corners;
      }
      CGAL::Euler::fill_hole(h, out);
      halfedge_descriptor g = h;
      for(; corners > 3; --corners) { // each split cuts a triangle off the polygon
        g = prev(CGAL::Euler::split_face(g, next(next(g, out), out), out), out);
        ++stats_.crease_triangles;
      }
      ++stats_.crease_triangles;
    }
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  VertexIndexMap vertex_index_;
  HalfedgeIndexMap halfedge_index_;
  std::vector<char> feature_;             // by halfedge index, both halves of a crease
  std::vector<std::size_t> copy_of_;      // by halfedge index
  std::vector<std::vector<std::size_t>> copies_; // by vertex index, in ccw order
  std::vector<Vec3> points_;
  std::vector<std::array<std::size_t, 3>> triangles_;
  Crease_statistics stats_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CREASE_TRIANGLES_H
