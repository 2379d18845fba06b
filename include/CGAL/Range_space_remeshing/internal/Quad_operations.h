// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_OPERATIONS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_OPERATIONS_H

// The operations of the quad collapse (Quad_collapser.h), each with the tests that
// allow it: the collapse of a quad along a diagonal, the rotation of an edge between
// two quads, the removal of a doublet; the valences and the border they keep up to
// date. Which operations to do, and in which order, is the collapser's.
//
// A quad (a, b, c, d) with halfedges h0 = a->b, h1 = b->c, h2 = c->d, h3 = d->a is
// collapsed along (a, c) by merging c into a: h0 takes the place of opposite(h1) and
// h3 the place of opposite(h2), so edges a-b, b-c become one and so do c-d, d-a; the
// quad, the edges of h1 and h2, and c are removed. Only pointers are rewired: no new
// element, so descriptors and indices of the survivors stay valid.

#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_kernel.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class PolygonMesh, class VertexPointMap, class TangentPlanesMap, class ConstrainedMap,
          class VertexIndexMap, class FaceIndexMap>
class Quad_operations
{
protected:
  using GT = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

  /// `normals` holds unit normals by vertex index; merged vertices' are updated.
  Quad_operations(PolygonMesh& mesh, VertexPointMap vpm, TangentPlanesMap planes, ConstrainedMap constrained,
                  VertexIndexMap vertex_index, FaceIndexMap face_index, std::vector<Vec3>& normals)
    : mesh_(mesh), vpm_(vpm), planes_(planes), constrained_(constrained), vertex_index_(vertex_index),
      normals_(normals), face_index_(face_index), removed_faces_(index_bound(faces(mesh), face_index), 0),
      is_quad_(removed_faces_.size(), 0), valences_(index_bound(vertices(mesh), vertex_index)),
      on_border_(valences_.size(), 0)
  {
    for(face_descriptor f : faces(mesh_))
      is_quad_[get(face_index_, f)] = degree(f, mesh_) == 4;
    for(vertex_descriptor v : vertices(mesh_)) {
      valences_[index(v)] = int(degree(v, mesh_));
      on_border_[index(v)] = bool(is_border(v, mesh_));
      // a border vertex keeps its border halfedge, which no collapse removes (see
      // set_inner_halfedge()); meshes from elsewhere need not point there yet
      if(on_border_[index(v)])
        set_halfedge(v, *is_border(v, mesh_), mesh_);
    }
  }

  std::size_t index(vertex_descriptor v) const { return get(vertex_index_, v); }
  int valence(vertex_descriptor v) const { return valences_[index(v)]; }
  // Border vertices are never moved nor merged; a regular one has valence 3 (two border
  // edges and one inside), and may go down to 2 (a corner of the surface).
  bool on_border(vertex_descriptor v) const { return on_border_[index(v)]; }
  int regular_valence(vertex_descriptor v) const { return on_border(v) ? 3 : 4; }
  int lowest_valence(vertex_descriptor v) const { return on_border(v) ? 2 : 3; }
  /// Sets the halfedge of v, unless v is on the border: its halfedge stays the border one.
  void set_inner_halfedge(vertex_descriptor v, halfedge_descriptor h)
  {
    if(!on_border(v))
      set_halfedge(v, h, mesh_);
  }
  Vec3 position(vertex_descriptor v) const { return to_vec3(get(vpm_, v)); }
  static halfedge_descriptor null_halfedge() { return GT::null_halfedge(); }

  /// The six halfedges around the two quads of the edge of h (u -> v), from v on:
  /// hexagon[i] goes from corner i to corner i + 1, corner 0 is v and corner 3 is u.
  /// False where the edge is not between two distinct quads.
  bool hexagon_around(halfedge_descriptor h, std::array<halfedge_descriptor, 6>& hexagon) const
  {
    const halfedge_descriptor o = opposite(h, mesh_);
    if(is_border(h, mesh_) || is_border(o, mesh_) || face(h, mesh_) == face(o, mesh_) ||
       !is_quad(face(h, mesh_)) || !is_quad(face(o, mesh_)))
      return false;
    hexagon[0] = next(h, mesh_);
    hexagon[3] = next(o, mesh_);
    for(int i : {1, 2, 4, 5})
      hexagon[i] = next(hexagon[i - 1], mesh_);
    return true;
  }

  // No operation changes the degree of a face it keeps (see is_quad_).
  bool is_quad(face_descriptor f) const { return is_quad_[get(face_index_, f)]; }
  bool is_live_quad(face_descriptor f) const { return !removed_faces_[get(face_index_, f)] && is_quad(f); }

  /// The hexagon's corners are six distinct vertices, the new edge's ends are not
  /// joined yet, u and v keep their lowest valence, and neither is constrained (its
  /// edges may be a feature the caller keeps).
  bool rotation_keeps_manifold(halfedge_descriptor h, const std::array<halfedge_descriptor, 6>& hexagon,
                               int k) const
  {
    const vertex_descriptor u = source(h, mesh_), v = target(h, mesh_);
    if(get(constrained_, u) || get(constrained_, v) || valence(u) <= lowest_valence(u) ||
       valence(v) <= lowest_valence(v))
      return false;
    std::array<vertex_descriptor, 6> corners;
    for(int i = 0; i < 6; ++i)
      corners[i] = source(hexagon[i], mesh_);
    for(int i = 0; i < 6; ++i)
      for(int j = i + 1; j < 6; ++j)
        if(corners[i] == corners[j])
          return false;
    const vertex_descriptor p = corners[k], q = corners[k + 3];
    for(vertex_descriptor w : CGAL::vertices_around_target(halfedge(p, mesh_), mesh_))
      if(w == q)
        return false;
    return true;
  }

  /// Both new quads face like the two old ones together, and, as in a collapse, stay
  /// convex where both old ones were (else each fan from the new edge turns like its quad).
  bool rotation_keeps_faces_unfolded(const std::array<halfedge_descriptor, 6>& hexagon, int k) const
  {
    corners_.clear();
    for(int i = 0; i < 6; ++i)
      corners_.push_back(position(source(hexagon[i], mesh_)));
    const Vec3 normal_before = newell_normal(corners_); // the hexagon's: both old quads'
    std::vector<Vec3>& quad = quad_corners_;
    auto quad_from = [&](int first) -> const std::vector<Vec3>& {
      quad.clear();
      for(int i = 0; i < 4; ++i)
        quad.push_back(corners_[(first + i) % 6]);
      return quad;
    };
    const bool were_convex = is_convex(quad_from(0), newell_normal(quad_from(0))) &&
                             is_convex(quad_from(3), newell_normal(quad_from(3)));
    return turns_like_before(quad_from(k), normal_before, were_convex) &&
           turns_like_before(quad_from(k + 3), normal_before, were_convex);
  }

  /// The rule of both operations for a changed face: its normal keeps the direction of
  /// `normal_before`, and it stays convex if it was, else every triangle of its fan from
  /// the first corner turns like it.
  static bool turns_like_before(const std::vector<Vec3>& polygon, const Vec3& normal_before, bool was_convex)
  {
    const Vec3 normal = newell_normal(polygon);
    return dot(normal, normal_before) > 0 &&
           (was_convex ? is_convex(polygon, normal) : fan_turns_with(polygon, normal));
  }

  /// Turns the edge of h (u -> v) to join hexagon corners k and k + 3 (mod 6): h's face
  /// becomes corners k .. k + 3, the opposite face corners k + 3 .. k + 6. (k = 4 or 5
  /// gives the diagonal of k = 1 or 2 with the two faces the other way round.)
  void rotate(halfedge_descriptor h, const std::array<halfedge_descriptor, 6>& hexagon, int k)
  {
    const halfedge_descriptor o = opposite(h, mesh_);
    const vertex_descriptor u = source(h, mesh_), v = target(h, mesh_);
    const vertex_descriptor p = source(hexagon[k], mesh_), q = source(hexagon[(k + 3) % 6], mesh_);
    auto link = [this](halfedge_descriptor diagonal, const halfedge_descriptor* sides) {
      const face_descriptor f = face(diagonal, mesh_);
      set_next(diagonal, sides[0], mesh_);
      set_next(sides[0], sides[1], mesh_);
      set_next(sides[1], sides[2], mesh_);
      set_next(sides[2], diagonal, mesh_);
      for(int i = 0; i < 3; ++i)
        set_face(sides[i], f, mesh_);
      set_halfedge(f, diagonal, mesh_);
    };
    const std::array<halfedge_descriptor, 6> from_k = {hexagon[k], hexagon[(k + 1) % 6], hexagon[(k + 2) % 6],
                                                       hexagon[(k + 3) % 6], hexagon[(k + 4) % 6],
                                                       hexagon[(k + 5) % 6]};
    if(halfedge(u, mesh_) == o)
      set_inner_halfedge(u, hexagon[2]); // hexagon[2] ends at corner 3, u
    if(halfedge(v, mesh_) == h)
      set_inner_halfedge(v, hexagon[5]); // hexagon[5] ends at corner 0, v
    set_target(h, p, mesh_);
    set_target(o, q, mesh_);
    link(h, &from_k[0]);
    link(o, &from_k[3]);
    --valences_[index(u)];
    --valences_[index(v)];
    ++valences_[index(p)];
    ++valences_[index(q)];
  }

  /// Link condition for quads: the merged vertex has one disk of faces, no two edges
  /// join the same vertices, no face visits a vertex twice, b and d keep valence 3
  /// (or, with `doublets_allowed`, b and d inside may drop to 2: a caller dissolves them).
  bool keeps_manifold(halfedge_descriptor h0, bool doublets_allowed = false) const
  {
    const halfedge_descriptor h1 = next(h0, mesh_), h2 = next(h1, mesh_);
    const vertex_descriptor a = source(h0, mesh_), b = target(h0, mesh_), c = target(h1, mesh_),
                            d = target(h2, mesh_);
    if(a == c || b == d || get(constrained_, a) || get(constrained_, c) || on_border(a) || on_border(c))
      return false;
    auto keeps_its_valence = [&](vertex_descriptor v) {
      return valence(v) > lowest_valence(v) || (doublets_allowed && !on_border(v) && valence(v) == 3);
    };
    if(!keeps_its_valence(b) || !keeps_its_valence(d) || valence(a) < 3 || valence(c) < 3)
      return false;
    auto& around_a = around_a_;
    around_a.clear();
    for(vertex_descriptor w : CGAL::vertices_around_target(opposite(h0, mesh_), mesh_))
      around_a.push_back(w);
    for(vertex_descriptor w : CGAL::vertices_around_target(h1, mesh_))
      if(w != b && w != d && std::find(around_a.begin(), around_a.end(), w) != around_a.end())
        return false;
    if(std::find(around_a.begin(), around_a.end(), c) != around_a.end())
      return false;
    const face_descriptor quad = face(h0, mesh_);
    auto& faces_a = faces_a_;
    faces_a.clear();
    for(face_descriptor g : CGAL::faces_around_target(opposite(h0, mesh_), mesh_))
      if(g != quad)
        faces_a.push_back(g);
    for(face_descriptor g : CGAL::faces_around_target(h1, mesh_))
      if(g != quad && std::find(faces_a.begin(), faces_a.end(), g) != faces_a.end())
        return false;
    return true;
  }

  /// The paper's placement, generalised as in the relaxation: the midpoint of a and c
  /// moved to the nearest minimiser of the distances to the union of their tangent
  /// planes (along the normal in a smooth region, onto the line of a crease); on opened
  /// creases, `merged_on_creases()`.
  Vec3 merged_position(halfedge_descriptor h0) const
  {
    const vertex_descriptor a = source(h0, mesh_), c = target(next(h0, mesh_), mesh_);
    const Vec3 pa = position(a), pc = position(c);
    Vec3 mid = {{(pa[0] + pc[0]) / 2, (pa[1] + pc[1]) / 2, (pa[2] + pc[2]) / 2}};
    if(merged_on_creases(get(planes_, a), pa, get(planes_, c), pc, mid, corners_, quad_corners_))
      return mid;
    Quadric quadric;
    quadric.add_planes(get(planes_, a));
    quadric.add_planes(get(planes_, c));
    return Quadric_projection(quadric, quadric_truncation)(mid);
  }

  Vec3 merged_normal(vertex_descriptor a, vertex_descriptor c) const
  {
    const Vec3& na = normals_[index(a)];
    const Vec3& nc = normals_[index(c)];
    return normalized(Vec3{{na[0] + nc[0], na[1] + nc[1], na[2] + nc[2]}});
  }

  /// Whether every face around a and c (but the quad) stays unfolded once a and c are
  /// one vertex at `merged`: its normal keeps its direction, a convex face stays
  /// convex, and every triangle of the fan from the merged vertex turns like the face.
  bool keeps_faces_unfolded(halfedge_descriptor h0, const Vec3& merged) const
  {
    const face_descriptor quad = face(h0, mesh_);
    for(halfedge_descriptor around : {opposite(h0, mesh_), next(h0, mesh_)}) // targets a, c
      for(halfedge_descriptor h : CGAL::halfedges_around_target(around, mesh_)) {
        if(is_border(h, mesh_) || face(h, mesh_) == quad)
          continue;
        corners_.clear();
        halfedge_descriptor g = h; // corners from the merged vertex on
        do {
          corners_.push_back(position(target(g, mesh_)));
          g = next(g, mesh_);
        } while(g != h);
        const Vec3 normal_before = newell_normal(corners_);
        const bool was_convex = is_convex(corners_, normal_before);
        corners_.front() = merged;
        if(!turns_like_before(corners_, normal_before, was_convex))
          return false;
      }
    return true;
  }

  void collapse(halfedge_descriptor h0, const Vec3& merged)
  {
    const halfedge_descriptor h1 = next(h0, mesh_), h2 = next(h1, mesh_), h3 = next(h2, mesh_);
    const halfedge_descriptor o1 = opposite(h1, mesh_), o2 = opposite(h2, mesh_);
    const vertex_descriptor a = source(h0, mesh_), b = target(h0, mesh_), c = target(h1, mesh_),
                            d = target(h2, mesh_);
    const Vec3 normal = merged_normal(a, c);

    std::vector<halfedge_descriptor>& into_c = into_c_;
    into_c.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_target(h1, mesh_))
      if(h != h1 && h != o2)
        into_c.push_back(h);
    for(halfedge_descriptor h : into_c)
      set_target(h, a, mesh_);
    valences_[index(a)] += valences_[index(c)] - 2;
    valences_[index(c)] = 0; // merged away
    --valences_[index(b)];
    --valences_[index(d)];

    replace_in_face(o1, h0);
    replace_in_face(o2, h3);
    set_halfedge(a, opposite(h0, mesh_), mesh_);
    set_inner_halfedge(b, h0);
    set_inner_halfedge(d, opposite(h3, mesh_));

    append_planes(a, c);
    put(vpm_, a, Point(merged[0], merged[1], merged[2]));
    normals_[index(a)] = normal;

    const face_descriptor quad = face(h1, mesh_);
    removed_faces_[get(face_index_, quad)] = true;
    unlinked_.push_back({quad, h1, h2, c});
  }

  /// A vertex v of valence 2 inside and its two faces F (of o2 = b -> v) and G (of
  /// o1 = a -> v), which share both its edges: dissolving v makes them one face
  /// (a, x, b, y).
  struct Doublet
  {
    vertex_descriptor v;
    halfedge_descriptor o2, e1, o1, e2; // b -> v, v -> a (in F); a -> v, v -> b (in G)
  };

  /// Whether v is a doublet whose two faces are distinct quads that can become one:
  /// a and b distinct and keeping their lowest valence, x and y distinct, v free.
  /// With `cascade`, a or b inside the surface, free, and whose third face is a quad
  /// may drop from 3 to 2: it becomes a doublet in turn, which the caller tries next.
  bool find_doublet(vertex_descriptor v, Doublet& d, bool cascade = false) const
  {
    if(valence(v) != 2 || on_border(v) || get(constrained_, v))
      return false;
    d.v = v;
    d.o2 = halfedge(v, mesh_);
    d.e1 = next(d.o2, mesh_);
    d.o1 = opposite(d.e1, mesh_);
    d.e2 = next(d.o1, mesh_);
    if(d.e2 != opposite(d.o2, mesh_) || is_border(d.o2, mesh_) || is_border(d.o1, mesh_))
      return false;
    const face_descriptor f = face(d.o2, mesh_), g = face(d.o1, mesh_);
    if(f == g || !is_quad(f) || !is_quad(g))
      return false;
    const vertex_descriptor a = target(d.e1, mesh_), b = target(d.e2, mesh_);
    // w's third face is across its edge to the corner after it in F (a) or G (b)
    auto keeps_its_valence = [&](vertex_descriptor w, halfedge_descriptor from_w) {
      const halfedge_descriptor across = opposite(from_w, mesh_);
      return valence(w) > lowest_valence(w) || (cascade && !on_border(w) && !get(constrained_, w) &&
                                                valence(w) == 3 && !is_border(across, mesh_) &&
                                                is_quad(face(across, mesh_)));
    };
    return a != b && target(next(d.e1, mesh_), mesh_) != target(next(d.e2, mesh_), mesh_) &&
           keeps_its_valence(a, next(d.e1, mesh_)) && keeps_its_valence(b, next(d.e2, mesh_));
  }

  /// Whether the doublet's merged quad (a, x, b, y) turns like its two quads together.
  bool merged_doublet_turns_like_before(const Doublet& d) const
  {
    const vertex_descriptor a = target(d.e1, mesh_), b = target(d.e2, mesh_);
    const vertex_descriptor x = target(next(d.e1, mesh_), mesh_), y = target(next(d.e2, mesh_), mesh_);
    corners_ = {position(a), position(x), position(b), position(y)};
    const Vec3 merged = newell_normal(corners_);
    corners_ = {position(d.v), position(a), position(x), position(b)};
    Vec3 before = newell_normal(corners_);
    corners_ = {position(d.v), position(b), position(y), position(a)};
    const Vec3 other = newell_normal(corners_);
    for(int i = 0; i < 3; ++i)
      before[i] += other[i];
    return dot(merged, before) > 0;
  }

  /// Makes the doublet's two quads one, F, and unlinks G, v and its two edges.
  void dissolve(const Doublet& d)
  {
    const face_descriptor f = face(d.o2, mesh_), g = face(d.o1, mesh_);
    const vertex_descriptor a = target(d.e1, mesh_), b = target(d.e2, mesh_);
    const halfedge_descriptor a_x = next(d.e1, mesh_), x_b = prev(d.o2, mesh_);
    const halfedge_descriptor b_y = next(d.e2, mesh_), y_a = prev(d.o1, mesh_);
    set_next(x_b, b_y, mesh_);
    set_next(y_a, a_x, mesh_);
    set_face(b_y, f, mesh_);
    set_face(y_a, f, mesh_);
    set_halfedge(f, a_x, mesh_);
    set_inner_halfedge(a, y_a);
    set_inner_halfedge(b, x_b);
    --valences_[index(a)];
    --valences_[index(b)];
    valences_[index(d.v)] = 0;
    removed_faces_[get(face_index_, g)] = true;
    unlinked_.push_back({g, d.e1, d.e2, d.v});
  }

  /// Dissolves the vertices of valence 2 (doublets: two quads sharing two edges, as
  /// the dual leaves where it joins faces) whose two faces are distinct quads: the two
  /// become one quad. A neighbour of valence 3 that this leaves with 2 is tried in turn
  /// (a row of them goes one by one), so that a doublet next to a vertex of valence 3
  /// is not left for want of a step. Refused where a border vertex would drop below
  /// its lowest valence, where a constrained vertex would be a doublet, where the merged
  /// face would visit a vertex twice, or where it would fold over.
  std::size_t remove_doublets()
  {
    std::vector<vertex_descriptor> doublets; // in vertex order, then as they appear
    for(vertex_descriptor v : vertices(mesh_))
      if(valence(v) == 2 && !on_border(v))
        doublets.push_back(v);
    std::size_t removed = 0;
    for(std::size_t k = 0; k < doublets.size(); ++k) { // grows: each step removes a face, so it ends
      Doublet d;
      if(!find_doublet(doublets[k], d, true) || !merged_doublet_turns_like_before(d))
        continue;
      std::array<vertex_descriptor, 2> ends = {target(d.e1, mesh_), target(d.e2, mesh_)};
      if(index(ends[1]) < index(ends[0])) // the order of the mesh's vertices, not of its halfedges
        std::swap(ends[0], ends[1]);
      dissolve(d);
      ++removed;
      for(vertex_descriptor w : ends)
        if(valence(w) == 2 && !on_border(w))
          doublets.push_back(w);
    }
    return removed;
  }

  /// Removes the elements of the collapsed quads. Deferred to the end of the run: a
  /// `Polyhedron_3` frees removed faces, and the pass lists may still name them.
  void remove_unlinked_elements()
  {
    for(const Unlinked& u : unlinked_) {
      remove_face(u.quad, mesh_);
      remove_edge(edge(u.h1, mesh_), mesh_);
      remove_edge(edge(u.h2, mesh_), mesh_);
      remove_vertex(u.c, mesh_);
    }
    unlinked_.clear();
  }

  /// The tangent planes of `to` become those of both: in place where the map gives
  /// references (no copy of the list), through get and put otherwise.
  void append_planes(vertex_descriptor to, vertex_descriptor from)
  {
    using Reference = typename boost::property_traits<TangentPlanesMap>::reference;
    if constexpr(std::is_lvalue_reference<Reference>::value &&
                 !std::is_const<std::remove_reference_t<Reference>>::value) {
      auto& merged = get(planes_, to);
      const auto& added = get(planes_, from);
      merged.insert(merged.end(), added.begin(), added.end());
    } else {
      auto merged = get(planes_, to);
      const auto added = get(planes_, from);
      merged.insert(merged.end(), added.begin(), added.end());
      put(planes_, to, merged);
    }
  }

  /// `replacement` takes the place of `h` in h's face.
  void replace_in_face(halfedge_descriptor h, halfedge_descriptor replacement)
  {
    const face_descriptor f = face(h, mesh_);
    set_next(prev(h, mesh_), replacement, mesh_);
    set_next(replacement, next(h, mesh_), mesh_);
    set_face(replacement, f, mesh_);
    if(halfedge(f, mesh_) == h)
      set_halfedge(f, replacement, mesh_);
  }

  PolygonMesh& mesh_;
  VertexPointMap vpm_;
  TangentPlanesMap planes_;
  ConstrainedMap constrained_;
  VertexIndexMap vertex_index_;
  std::vector<Vec3>& normals_;
  FaceIndexMap face_index_;
  // by face index: faces are never created. (Bytes, not bits: read for every quad examined.)
  std::vector<std::uint8_t> removed_faces_;
  // by face index, the degree test cached: a collapse replaces a corner of the faces
  // around it, a rotation or a doublet removal makes quads of quads
  std::vector<std::uint8_t> is_quad_;
  std::vector<int> valences_;           // by vertex index
  std::vector<std::uint8_t> on_border_; // by vertex index
  mutable std::vector<vertex_descriptor> around_a_;
  mutable std::vector<face_descriptor> faces_a_;
  std::vector<halfedge_descriptor> into_c_;
  struct Unlinked // what a collapse (or a doublet removal) took out of the connectivity
  {
    face_descriptor quad;
    halfedge_descriptor h1, h2; // one halfedge of each of the two removed edges
    vertex_descriptor c;
  };
  std::vector<Unlinked> unlinked_;
  mutable std::vector<Vec3> corners_;
  mutable std::vector<Vec3> quad_corners_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_OPERATIONS_H
