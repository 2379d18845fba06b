// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COMPLETION_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COMPLETION_H

// All quads: the faces of the dual that are not quads (where parallel
// edges were joined, pinches glued, pieces dropped) are turned into quads with
// local operations that keep the vertices, the Euler characteristic and the
// components. A face of more than four sides is cut by diagonals into quads and, if
// its degree is odd, one triangle. The triangles then come in pairs in each piece
// (the sum of the face degrees is twice the number of edges, less the border edges):
// each one walks along a shortest path of quads to the nearest other one, a quad at a
// time (joined with the quad ahead into a pentagon, cut again so that the triangle is
// on the far side), and the two are joined into a quad. Of the diagonals each step
// can take, the one whose faces have the better shape is chosen, so that what the
// relaxation and the untangling get to clean is as small as it can be.

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/internal/Face_corners.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <deque>
#include <map>
#include <set>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Makes the faces of a polygon mesh quads where the piece allows it. `NormalOf` is
/// called as `normal_of(v)`: a unit normal at vertex v (the reference against which a
/// face counts as folded).
template <class PolygonMesh, class VertexPointMap, class NormalOf>
class Quad_completion
{
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

public:
  // The quads a path may cross are tried again after a step they refused: each
  // refusal bars one quad, so a triangle gives up after this many.
  static constexpr int maximum_refusals = 16;

  Quad_completion(PolygonMesh& mesh, VertexPointMap vpm, NormalOf normal_of)
    : mesh_(mesh), vpm_(vpm), normal_of_(normal_of)
  {}

  All_quads_statistics run()
  {
    const auto start = std::chrono::steady_clock::now();
    All_quads_statistics stats;
    std::vector<face_descriptor> large, triangles;
    for(face_descriptor f : faces(mesh_)) {
      const std::size_t d = degree(f, mesh_);
      stats.non_quads_before += (d != 4);
      if(d > 4)
        large.push_back(f);
      else if(d == 3)
        triangles.push_back(f);
    }
    if(stats.non_quads_before > 0) {
      for(face_descriptor f : large)
        cut_into_quads(f, triangles, stats);
      pair_triangles(triangles, stats);
      count_what_is_left(stats);
    }
    stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats;
  }

private:
  using Polygon = std::vector<vertex_descriptor>;

  /// The faces still not quads, and the pieces (connected sets of faces) they are in.
  void count_what_is_left(All_quads_statistics& stats) const
  {
    std::set<face_descriptor> reached; // the faces of the pieces counted so far
    for(face_descriptor f : faces(mesh_)) {
      if(degree(f, mesh_) == 4)
        continue;
      ++stats.non_quads_after;
      if(reached.count(f) != 0)
        continue;
      ++stats.pieces_not_all_quads;
      walk_component(f, mesh_, reached, [](face_descriptor) {});
    }
  }

  // The shape of a polygon, best first, and its least corner quality: what the
  // choice between diagonals compares.
  struct Shape
  {
    Face_shape shape = Face_shape::FINE;
    double quality = 1;
    bool better_than(const Shape& other) const
    {
      return shape != other.shape ? shape < other.shape : quality > other.quality;
    }
  };

  Shape shape_of_polygon(const Polygon& polygon) const
  {
    std::vector<Vec3> position, normal;
    for(vertex_descriptor v : polygon) {
      position.push_back(to_vec3(get(vpm_, v)));
      normal.push_back(normal_of_(v));
    }
    const auto position_of = [&](std::size_t i) -> const Vec3& { return position[i]; };
    const auto normal_at = [&](std::size_t i) -> const Vec3& { return normal[i]; };
    double sum = 0;
    return {polygon_shape(polygon.size(), position_of, normal_at),
            polygon_corner_quality(polygon.size(), position_of, normal_at, 1, sum)};
  }

  // The worse of the two polygons a diagonal leaves.
  Shape shape_of_pair(const Polygon& a, const Polygon& b) const
  {
    const Shape sa = shape_of_polygon(a), sb = shape_of_polygon(b);
    return sa.better_than(sb) ? sb : sa;
  }

  bool adjacent(vertex_descriptor u, vertex_descriptor v) const { return halfedge(u, v, mesh_).second; }

  // The halfedges of a face, from h.
  std::vector<halfedge_descriptor> halfedges_of(halfedge_descriptor h) const
  {
    std::vector<halfedge_descriptor> result;
    for(halfedge_descriptor g : CGAL::halfedges_around_face(h, mesh_))
      result.push_back(g);
    return result;
  }

  // The polygon of the targets of hs[from], hs[from + 1], ..., hs[to] (indices mod n).
  Polygon corners_between(const std::vector<halfedge_descriptor>& hs, std::size_t from, std::size_t to) const
  {
    Polygon polygon;
    const std::size_t n = hs.size();
    for(std::size_t i = from % n;; i = (i + 1) % n) {
      polygon.push_back(target(hs[i], mesh_));
      if(i == to % n)
        break;
    }
    return polygon;
  }

  /// Cuts quads off face f, a face of more than four sides, until a quad or a triangle
  /// is left (pushed onto `triangles`); each cut by the diagonal whose two parts have
  /// the best shape, among those that join two vertices not yet joined.
  void cut_into_quads(face_descriptor f, std::vector<face_descriptor>& triangles, All_quads_statistics& stats)
  {
    while(degree(f, mesh_) > 4) {
      const std::vector<halfedge_descriptor> hs = halfedges_of(halfedge(f, mesh_));
      const std::size_t n = hs.size();
      std::size_t best = n;
      Shape best_shape;
      for(std::size_t i = 0; i < n; ++i) { // the quad of the targets of hs[i] .. hs[i + 3]
        if(adjacent(target(hs[i], mesh_), target(hs[(i + 3) % n], mesh_)))
          continue;
        const Shape s = shape_of_pair(corners_between(hs, i, i + 3), corners_between(hs, i + 3, i + n));
        if(best == n || s.better_than(best_shape)) {
          best = i;
          best_shape = s;
        }
      }
      if(best == n)
        return; // every diagonal would double an edge: left as it is, and counted
      CGAL::Euler::split_face(hs[best], hs[(best + 3) % n], mesh_);
      ++stats.split_faces;
      f = face(hs[best], mesh_); // the rest: the quad holds hs[best + 1] .. hs[best + 3]
    }
    if(degree(f, mesh_) == 3)
      triangles.push_back(f);
  }

  /// Walks each triangle, in order, to the nearest other one and joins the two; a
  /// triangle that finds no partner (its piece has an odd number of them, or the mesh
  /// refuses every path) stays, counted in `non_quads_after`.
  void pair_triangles(const std::vector<face_descriptor>& triangles, All_quads_statistics& stats)
  {
    std::set<face_descriptor> given_up; // the faces of the triangles left where they are
    for(face_descriptor t : triangles) {
      if(given_up.count(t) != 0 || degree(t, mesh_) != 3)
        continue; // joined as the partner of an earlier one (its face now a quad)
      std::set<face_descriptor> barred;
      bool done = false;
      for(int attempt = 0; !done && attempt <= maximum_refusals; ++attempt) {
        const std::vector<halfedge_descriptor> path = path_to_nearest_triangle(t, barred);
        if(path.empty())
          break;
        done = walk(t, path, barred, stats);
      }
      if(done)
        ++stats.joined_triangles;
      else
        given_up.insert(t);
    }
  }

  /// The halfedges crossed on a shortest path of quads (not barred) from triangle t to
  /// another triangle, each in the face it leaves; empty if there is none.
  std::vector<halfedge_descriptor> path_to_nearest_triangle(face_descriptor t,
                                                            const std::set<face_descriptor>& barred) const
  {
    std::map<face_descriptor, halfedge_descriptor> entered_by; // the halfedge crossed into each face
    std::deque<face_descriptor> queue{t};
    entered_by.emplace(t, GT::null_halfedge());
    while(!queue.empty()) {
      const face_descriptor f = queue.front();
      queue.pop_front();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh_), mesh_)) {
        const face_descriptor g = face(opposite(h, mesh_), mesh_);
        if(g == GT::null_face() || entered_by.count(g) != 0)
          continue;
        const std::size_t d = degree(g, mesh_);
        if(d == 3 && barred.count(g) == 0) {
          std::vector<halfedge_descriptor> path{h};
          for(face_descriptor back = f; back != t;) {
            const halfedge_descriptor in = entered_by[back];
            path.push_back(in);
            back = face(in, mesh_);
          }
          std::reverse(path.begin(), path.end());
          return path;
        }
        entered_by.emplace(g, h);
        if(d == 4 && barred.count(g) == 0)
          queue.push_back(g);
      }
    }
    return {};
  }

  /// Moves triangle t along `path` and joins it with the triangle at its end. A step
  /// that the mesh refuses (a joined face would visit a vertex twice, or both cuts
  /// would double an edge) bars its quad and returns false, the steps done kept: the
  /// triangle then sits nearer, and a new path is sought from where it is.
  bool walk(face_descriptor& t, const std::vector<halfedge_descriptor>& path, std::set<face_descriptor>& barred,
            All_quads_statistics& stats)
  {
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      const face_descriptor quad = face(opposite(path[i], mesh_), mesh_);
      if(!step(path[i], path[i + 1])) {
        barred.insert(quad);
        return false;
      }
      t = face(path[i + 1], mesh_);
      ++stats.triangle_steps;
    }
    if(!can_join(path.back())) { // the two share more than an edge: another partner
      barred.insert(face(opposite(path.back(), mesh_), mesh_));
      return false;
    }
    CGAL::Euler::join_face(path.back(), mesh_);
    return true;
  }

  /// Whether joining the two faces of h's edge gives a face that visits no vertex twice.
  bool can_join(halfedge_descriptor h) const
  {
    std::set<vertex_descriptor> seen;
    std::size_t count = 0;
    for(halfedge_descriptor side : {h, opposite(h, mesh_)})
      for(vertex_descriptor v : CGAL::vertices_around_face(side, mesh_)) {
        seen.insert(v);
        ++count;
      }
    return seen.size() + 2 == count; // only the edge's two ends are shared
  }

  /// One step of a triangle: the triangle of `in` (the halfedge into the quad ahead)
  /// joined with that quad, and the pentagon cut so that the triangle holds `out` (the
  /// halfedge out of the quad, kept by both operations). Done only if both can be.
  bool step(halfedge_descriptor in, halfedge_descriptor out)
  {
    if(!can_join(in))
      return false;
    const std::vector<halfedge_descriptor> hs = pentagon_from(in, out);
    // out in the triangle (targets of hs[3], hs[4], hs[0]) or (of hs[4], hs[0], hs[1])
    const bool first_ok = can_cut(target(hs[3], mesh_), target(hs[0], mesh_), in);
    const bool second_ok = can_cut(target(hs[4], mesh_), target(hs[1], mesh_), in);
    if(!first_ok && !second_ok)
      return false;
    bool first = first_ok;
    if(first_ok && second_ok)
      first = !shape_of_pair(corners_between(hs, 4, 6), corners_between(hs, 1, 4))
                   .better_than(shape_of_pair(corners_between(hs, 3, 5), corners_between(hs, 0, 3)));
    CGAL::Euler::join_face(in, mesh_);
    if(first)
      CGAL::Euler::split_face(hs[3], hs[0], mesh_);
    else
      CGAL::Euler::split_face(hs[4], hs[1], mesh_);
    return true;
  }

  /// The halfedges of the pentagon that joining the faces of `in` would make, from `out`.
  std::vector<halfedge_descriptor> pentagon_from(halfedge_descriptor in, halfedge_descriptor out) const
  {
    std::vector<halfedge_descriptor> hs;
    for(halfedge_descriptor g = out; hs.size() < 5;) {
      hs.push_back(g);
      g = next(g, mesh_);
      if(g == opposite(in, mesh_))
        g = next(in, mesh_);
      else if(g == in)
        g = next(opposite(in, mesh_), mesh_);
    }
    return hs;
  }

  /// Whether u and v may be joined by a new edge once the edge of `in` is removed.
  bool can_cut(vertex_descriptor u, vertex_descriptor v, halfedge_descriptor in) const
  {
    if(!adjacent(u, v))
      return true;
    const vertex_descriptor s = source(in, mesh_), e = target(in, mesh_);
    return (u == s && v == e) || (u == e && v == s);
  }

  PolygonMesh& mesh_;
  VertexPointMap vpm_;
  NormalOf normal_of_;
};

/// The stage of `remesh()` after the dual (see `All_quads_statistics`): reads
/// `vertex_point_map` and, if given, `vertex_normal_map` (else each vertex's normal is
/// the sum of its faces' area vectors). A `Surface_mesh` is garbage-collected at the end.
template <class PolygonMesh, class NamedParameters>
All_quads_statistics complete_quads(PolygonMesh& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, mesh));
  constexpr bool has_normals =
      !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value;
  auto normal_map = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_normal_map),
                                     CGAL::Constant_property_map<vertex_descriptor, Vec3>(Vec3{{0, 0, 0}}));
  auto normal_of = [&](vertex_descriptor v) -> Vec3 {
    if constexpr(has_normals)
      return normalized(to_vec3(get(normal_map, v)));
    else
      return area_weighted_vertex_normal(v, mesh, vpm);
  };
  const All_quads_statistics stats =
      Quad_completion<PolygonMesh, decltype(vpm), decltype(normal_of)>(mesh, vpm, normal_of).run();
  // as after the dual and the collapse: contiguous indices, and num_faces() (which
  // counts removed faces) right for the stages and the writers after it; no vertex is
  // removed, so the vertices keep their indices and properties
  collect_garbage_if_any(mesh);
  return stats;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_COMPLETION_H
