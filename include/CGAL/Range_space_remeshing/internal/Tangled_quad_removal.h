// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGLED_QUAD_REMOVAL_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGLED_QUAD_REMOVAL_H

// The last resort of the untangling: a face that no move of its vertices on their
// tangent planes makes fine (Quad_untangler.h) is changed in connectivity. A tangled
// quad is collapsed along a diagonal, or one of its edges is rotated, where that
// leaves fewer tangled faces among those it changes; the untangling then moves the
// vertices of what is left. Every operation lowers the number of tangled faces, so
// the stage ends; each keeps the mesh an all-quad 2-manifold of the same topology
// (the tests of Quad_operations.h).

#include <CGAL/Range_space_remeshing/internal/Face_corners.h>
#include <CGAL/Range_space_remeshing/internal/Quad_operations.h>

#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class PolygonMesh, class VertexPointMap, class TangentPlanesMap, class ConstrainedMap,
          class VertexIndexMap, class FaceIndexMap>
class Tangled_quad_remover
    : Quad_operations<PolygonMesh, VertexPointMap, TangentPlanesMap, ConstrainedMap, VertexIndexMap, FaceIndexMap>
{
  using Operations =
      Quad_operations<PolygonMesh, VertexPointMap, TangentPlanesMap, ConstrainedMap, VertexIndexMap, FaceIndexMap>;
  using typename Operations::vertex_descriptor;
  using typename Operations::halfedge_descriptor;
  using typename Operations::face_descriptor;
  using Operations::mesh_;
  using Operations::normals_;
  using Operations::index;
  using Operations::position;
  using Operations::is_live_quad;
  using Operations::hexagon_around;
  using Operations::rotation_keeps_manifold;
  using Operations::keeps_manifold;
  using Operations::merged_position;
  using Operations::merged_normal;
  using Operations::collapse;
  using Operations::rotate;
  using Operations::remove_unlinked_elements;

public:
  /// `normals` holds unit normals by vertex index; merged vertices' are updated.
  Tangled_quad_remover(PolygonMesh& mesh, VertexPointMap vpm, TangentPlanesMap planes, ConstrainedMap constrained,
                       VertexIndexMap vertex_index, FaceIndexMap face_index, std::vector<Vec3>& normals)
    : Operations(mesh, vpm, planes, constrained, vertex_index, face_index, normals)
  {}

  /// Collapses or rotates around each tangled quad, in the order of `faces()`, where
  /// that leaves the faces it changes less tangled; removes what the collapses
  /// unlinked. Adds the operations done to `collapses` and `rotations`.
  void run(std::size_t& collapses, std::size_t& rotations)
  {
    std::vector<face_descriptor> tangled;
    for(face_descriptor f : faces(mesh_))
      if(tangle(f).any())
        tangled.push_back(f);
    for(face_descriptor f : tangled) {
      if(!is_live_quad(f) || !tangle(f).any())
        continue;
      if(collapse_away(f))
        ++collapses;
      else if(rotate_away(f))
        ++rotations;
    }
    remove_unlinked_elements();
  }

private:
  // How tangled some faces are: first the faces that do not turn left at every corner
  // seen from their own vector area (a dart, a bow-tie: a bad element on any surface),
  // then those whose vector area faces against their corners' normals (folded over
  // their neighbours, or only bent across a thin limb: the normals may not tell).
  // Every operation makes this smaller in this order, so the stage ends.
  struct Tangle
  {
    std::size_t non_convex = 0, folded = 0;
    bool any() const { return non_convex + folded > 0; }
    Tangle& operator+=(const Tangle& other)
    {
      non_convex += other.non_convex;
      folded += other.folded;
      return *this;
    }
    bool operator<(const Tangle& other) const
    {
      return non_convex < other.non_convex || (non_convex == other.non_convex && folded < other.folded);
    }
  };

  // The tangle of a face, with corner `moved` (if any) at `at` with normal `at_normal`.
  Tangle tangle(face_descriptor f, vertex_descriptor moved = vertex_descriptor(), const Vec3& at = Vec3(),
                const Vec3& at_normal = Vec3()) const
  {
    points_.clear();
    normals_of_corners_.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh_), mesh_)) {
      const bool is_moved = v == moved;
      points_.push_back(is_moved ? at : position(v));
      normals_of_corners_.push_back(is_moved ? at_normal : normals_[index(v)]);
    }
    return tangle_of_corners();
  }

  Tangle tangle_of_corners() const
  {
    auto point = [&](std::size_t i) -> const Vec3& { return points_[i]; };
    Vec3 area, reference;
    polygon_area_and_reference(
        points_.size(), point, [&](std::size_t i) -> const Vec3& { return normals_of_corners_[i]; }, area, reference);
    Tangle t;
    t.non_convex = !turns_left_at_every_corner(points_.size(), point, area);
    t.folded = dot(area, reference) < 0;
    return t;
  }

  // The faces around a and c but `quad` (each once).
  std::vector<face_descriptor>& faces_around(halfedge_descriptor h0, face_descriptor quad) const
  {
    around_.clear();
    for(halfedge_descriptor start : {opposite(h0, mesh_), next(h0, mesh_)}) // targets a, c
      for(face_descriptor g : CGAL::faces_around_target(start, mesh_))
        if(g != quad && g != boost::graph_traits<PolygonMesh>::null_face() &&
           std::find(around_.begin(), around_.end(), g) == around_.end())
          around_.push_back(g);
    return around_;
  }

  // Collapses the quad along a diagonal where the faces around the merged vertex are
  // then less tangled than they and the quad were: at the paper's place
  // (merged_position()) or, failing that, at a or at c.
  bool collapse_away(face_descriptor quad)
  {
    const halfedge_descriptor h = halfedge(quad, mesh_);
    for(halfedge_descriptor h0 : {h, next(h, mesh_), next(next(h, mesh_), mesh_), prev(h, mesh_)}) {
      if(!keeps_manifold(h0))
        continue;
      const vertex_descriptor a = source(h0, mesh_), c = target(next(h0, mesh_), mesh_);
      const std::vector<face_descriptor>& around = faces_around(h0, quad);
      Tangle before = tangle(quad);
      for(face_descriptor g : around)
        before += tangle(g);
      const Vec3 normal = merged_normal(a, c);
      for(const Vec3& merged : {merged_position(h0), position(a), position(c)}) {
        Tangle after;
        for(face_descriptor g : around) // a's faces and c's: a and c both go to `merged`
          after += tangle(g, has_corner(g, a) ? a : c, merged, normal);
        if(after < before) {
          collapse(h0, merged);
          return true;
        }
      }
    }
    return false;
  }

  // Rotates an edge of the quad where the two new quads are less tangled than the
  // two old ones.
  bool rotate_away(face_descriptor quad)
  {
    std::array<halfedge_descriptor, 6> hexagon;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(quad, mesh_), mesh_)) {
      if(!hexagon_around(h, hexagon))
        continue;
      Tangle before = tangle(quad);
      before += tangle(face(opposite(h, mesh_), mesh_));
      for(int k : {1, 2}) {
        if(!rotation_keeps_manifold(h, hexagon, k))
          continue;
        Tangle after = tangle_after_rotation(hexagon, k);
        after += tangle_after_rotation(hexagon, k + 3);
        if(after < before) {
          rotate(h, hexagon, k);
          return true;
        }
      }
    }
    return false;
  }

  // The tangle of the quad of hexagon corners `first` .. `first` + 3 (mod 6).
  Tangle tangle_after_rotation(const std::array<halfedge_descriptor, 6>& hexagon, int first) const
  {
    points_.clear();
    normals_of_corners_.clear();
    for(int i = 0; i < 4; ++i) {
      const vertex_descriptor v = source(hexagon[(first + i) % 6], mesh_);
      points_.push_back(position(v));
      normals_of_corners_.push_back(normals_[index(v)]);
    }
    return tangle_of_corners();
  }

  bool has_corner(face_descriptor g, vertex_descriptor v) const
  {
    for(vertex_descriptor w : CGAL::vertices_around_face(halfedge(g, mesh_), mesh_))
      if(w == v)
        return true;
    return false;
  }

  mutable std::vector<Vec3> points_, normals_of_corners_;
  mutable std::vector<face_descriptor> around_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGLED_QUAD_REMOVAL_H
