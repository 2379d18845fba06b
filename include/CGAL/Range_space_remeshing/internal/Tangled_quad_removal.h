// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGLED_QUAD_REMOVAL_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGLED_QUAD_REMOVAL_H

// The last resort of the untangling: a face that no move of its vertices on their
// tangent planes makes fine (Quad_untangler.h) is changed in connectivity. A tangled
// quad is collapsed along a diagonal, or one of its edges is rotated, where that
// leaves the faces it changes less tangled (see Tangle); the untangling then moves
// the vertices of what is left. Every operation lowers the tangle of the whole mesh,
// so the stage ends; each keeps the mesh an all-quad 2-manifold of the same topology
// (the link conditions of Quad_operations.h, and for doublets doublet_after_collapse()).
//
// Tangled quads sit where the surface bends over a thin limb, often among corners of
// valence 3, which no collapse may lower to 2: there the corner becomes a doublet and
// is dissolved in the same step (its two other faces become one quad).

#include <CGAL/Range_space_remeshing/internal/Face_corners.h>
#include <CGAL/Range_space_remeshing/internal/Quad_operations.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
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
  using Operations::find_doublet;
  using Operations::dissolve;
  using Operations::valence;
  using typename Operations::Doublet;
  using Operations::rotate;
  using Operations::remove_unlinked_elements;

public:
  /// `normals` holds unit normals by vertex index; merged vertices' are updated.
  /// Without `rotate_edges`, only collapses.
  Tangled_quad_remover(PolygonMesh& mesh, VertexPointMap vpm, TangentPlanesMap planes, ConstrainedMap constrained,
                       VertexIndexMap vertex_index, FaceIndexMap face_index, std::vector<Vec3>& normals,
                       bool rotate_edges)
    : Operations(mesh, vpm, planes, constrained, vertex_index, face_index, normals), rotate_edges_(rotate_edges)
  {}

  /// Collapses or rotates around each tangled quad, in the order of `faces()`, where
  /// that leaves the faces it changes less tangled; removes what the collapses
  /// unlinked. Adds the operations done to `collapses` and `rotations`; sets `changed`
  /// (vertex -> bool) at a corner of every face an operation made.
  template <class ChangedMap>
  void run(std::size_t& collapses, std::size_t& rotations, ChangedMap changed)
  {
    std::vector<face_descriptor> tangled;
    for(face_descriptor f : faces(mesh_))
      if(tangle(f).any())
        tangled.push_back(f);
    for(face_descriptor f : tangled) {
      if(!is_live_quad(f) || !tangle(f).any())
        continue;
      vertex_descriptor corner;
      if(collapse_away(f, corner))
        ++collapses;
      else if(rotate_edges_ && rotate_away(f, corner))
        ++rotations;
      else
        continue;
      put(changed, corner, true);
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

  // Vertices a and c of a collapse, to be one vertex at `at` with normal `normal`.
  struct Merge
  {
    vertex_descriptor a, c;
    Vec3 at, normal;
  };

  // The tangle of the polygon of `corners`, where a and c of `merge` (if any) are merged.
  Tangle tangle(const std::vector<vertex_descriptor>& corners, const Merge* merge = nullptr) const
  {
    points_.clear();
    normals_of_corners_.clear();
    for(vertex_descriptor v : corners) {
      const bool merged = merge != nullptr && (v == merge->a || v == merge->c);
      points_.push_back(merged ? merge->at : position(v));
      normals_of_corners_.push_back(merged ? merge->normal : normals_[index(v)]);
    }
    return tangle_of_corners();
  }

  Tangle tangle(face_descriptor f) const { return tangle(corners_from(halfedge(f, mesh_))); }

  // The corners of h's face, from h's target on.
  const std::vector<vertex_descriptor>& corners_from(halfedge_descriptor h) const
  {
    polygon_.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(h, mesh_))
      polygon_.push_back(v);
    return polygon_;
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
  const std::vector<face_descriptor>& faces_around(halfedge_descriptor h0, face_descriptor quad)
  {
    around_.clear();
    for(halfedge_descriptor start : {opposite(h0, mesh_), next(h0, mesh_)}) // targets a, c
      for(face_descriptor g : CGAL::faces_around_target(start, mesh_))
        if(g != quad && g != boost::graph_traits<PolygonMesh>::null_face() &&
           std::find(around_.begin(), around_.end(), g) == around_.end())
          around_.push_back(g);
    return around_;
  }

  // A corner of valence 3 off the diagonal of a collapse, and its faces but the quad.
  struct Future_doublet
  {
    vertex_descriptor v;
    std::array<face_descriptor, 2> faces;
  };

  static bool in_doublet(face_descriptor g, const std::vector<Future_doublet>& doublets)
  {
    for(const Future_doublet& doublet : doublets)
      if(g == doublet.faces[0] || g == doublet.faces[1])
        return true;
    return false;
  }

  // Collapses the quad (a, b, c, d) along a diagonal, c into a, where the faces around
  // the merged vertex are then less tangled than they and the quad were: at the
  // paper's place (merged_position()) or, failing that, at a or at c. A corner b or d
  // of valence 3 becomes a doublet, dissolved in the same step. `corner`: the merged
  // vertex, a corner of every face the collapse changes.
  bool collapse_away(face_descriptor quad, vertex_descriptor& corner)
  {
    const halfedge_descriptor h = halfedge(quad, mesh_);
    for(halfedge_descriptor h0 : {h, next(h, mesh_)}) { // the two diagonals (the places tried are symmetric)
      if(!keeps_manifold(h0, true))
        continue;
      const halfedge_descriptor h1 = next(h0, mesh_), h2 = next(h1, mesh_), h3 = next(h2, mesh_);
      const vertex_descriptor a = source(h0, mesh_), b = target(h0, mesh_), c = target(h1, mesh_),
                              d = target(h2, mesh_);
      // the doublets the collapse would leave
      std::vector<Future_doublet> doublets;
      if(valence(b) == 3)
        doublets.push_back({b, {{face(opposite(h0, mesh_), mesh_), face(opposite(h1, mesh_), mesh_)}}});
      if(valence(d) == 3)
        doublets.push_back({d, {{face(opposite(h2, mesh_), mesh_), face(opposite(h3, mesh_), mesh_)}}});
      if(valence(a) + valence(c) - 2 - int(doublets.size()) < 3)
        continue;
      const std::vector<face_descriptor>& around = faces_around(h0, quad);
      Tangle before = tangle(quad);
      for(face_descriptor g : around)
        before += tangle(g);
      Merge merge{a, c, Vec3(), merged_normal(a, c)};
      for(const Vec3& merged : {merged_position(h0), position(a), position(c)}) {
        merge.at = merged;
        bool possible = true;
        Tangle after;
        for(face_descriptor g : around)
          if(!in_doublet(g, doublets))
            after += tangle(corners_from(halfedge(g, mesh_)), &merge);
        for(std::size_t k = 0; k < doublets.size() && possible; ++k)
          if((possible = doublet_after_collapse(doublets[k], merge)))
            after += tangle(doublet_polygon_, &merge);
        if(possible && after < before) {
          collapse(h0, merged);
          corner = a;
          for(vertex_descriptor v : {b, d}) {
            Doublet doublet;
            if(valence(v) == 2 && find_doublet(v, doublet))
              dissolve(doublet);
          }
          return true;
        }
      }
    }
    return false;
  }

  // Whether the doublet that the collapse of `merge` leaves at v (valence 3 now) can be
  // dissolved (as find_doublet() will test it); its merged quad into doublet_polygon_.
  // v's faces but the quad, from v on, are (v, p1, p2, p3) and (v, r1, r2, r3) with
  // p3 = r1 and r3 = p1 once a and c are one: they become (p1, p2, p3, r2).
  bool doublet_after_collapse(const Future_doublet& doublet, const Merge& merge)
  {
    const vertex_descriptor v = doublet.v;
    const std::array<face_descriptor, 2>& faces = doublet.faces;
    std::array<std::array<vertex_descriptor, 4>, 2> from_v;
    for(int k = 0; k < 2; ++k) {
      if(!is_live_quad(faces[k]))
        return false;
      halfedge_descriptor g = halfedge(faces[k], mesh_);
      while(source(g, mesh_) != v)
        g = next(g, mesh_);
      for(int i = 0; i < 4; ++i, g = next(g, mesh_))
        from_v[k][i] = source(g, mesh_);
      for(vertex_descriptor& w : from_v[k])
        if(w == merge.c)
          w = merge.a;
    }
    std::array<vertex_descriptor, 4> p = from_v[0], r = from_v[1];
    if(p[3] != r[1]) // the faces in the other order around v
      std::swap(p, r);
    if(faces[0] == faces[1] || p[3] != r[1] || p[1] != r[3] || p[2] == r[2] || p[1] == p[3] ||
       get(this->constrained_, v))
      return false;
    // p1 and p3 lose the edge to v: one of them is the merged vertex, the other must
    // keep its lowest valence
    const vertex_descriptor other = p[1] == merge.a ? p[3] : p[1];
    if(valence(other) <= this->lowest_valence(other))
      return false;
    doublet_polygon_ = {p[1], p[2], p[3], r[2]};
    return true;
  }

  // Rotates an edge of the quad where the two new quads are less tangled than the
  // two old ones. `corner`: an end of the new edge, a corner of both.
  bool rotate_away(face_descriptor quad, vertex_descriptor& corner)
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
          corner = source(hexagon[k], mesh_);
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
    std::vector<vertex_descriptor>& quad = polygon_;
    quad.clear();
    for(int i = 0; i < 4; ++i)
      quad.push_back(source(hexagon[(first + i) % 6], mesh_));
    return tangle(quad);
  }

  mutable std::vector<Vec3> points_, normals_of_corners_;
  bool rotate_edges_;
  std::vector<face_descriptor> around_;
  mutable std::vector<vertex_descriptor> polygon_;
  std::vector<vertex_descriptor> doublet_polygon_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGLED_QUAD_REMOVAL_H
