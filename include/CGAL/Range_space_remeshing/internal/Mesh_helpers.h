// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H

// Small FaceGraph helpers shared by the dual, the collapse and the relaxation.

#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/iterator.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <set>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

template <class Mesh>
void collect_garbage_if_any(Mesh&) {}
template <class P>
void collect_garbage_if_any(CGAL::Surface_mesh<P>& m)
{
  if(m.has_garbage())
    m.collect_garbage();
}

/// Room for nv more vertices, ne more edges and nf more faces, where the mesh can
/// make it: a `Surface_mesh` otherwise grows its property arrays by reallocation.
template <class PolygonMesh>
void reserve_if_possible(PolygonMesh&, std::size_t, std::size_t, std::size_t)
{}

template <class Point>
void reserve_if_possible(CGAL::Surface_mesh<Point>& out, std::size_t nv, std::size_t ne, std::size_t nf)
{
  using size_type = typename CGAL::Surface_mesh<Point>::size_type;
  out.reserve(size_type(num_vertices(out) + nv), size_type(num_edges(out) + ne),
              size_type(num_faces(out) + nf));
}

/// One more than the largest index of the elements of `range`: the size of a vector
/// indexed by them (a `Surface_mesh` with removed elements has gaps in its indices).
template <class Range, class IndexMap>
std::size_t index_bound(const Range& range, IndexMap index)
{
  std::size_t bound = 0;
  for(auto x : range)
    bound = (std::max)(bound, std::size_t(get(index, x)) + 1);
  return bound;
}

/// The sum of the Newell area vectors of the faces around v, with the coordinates
/// taken relative to v and multiplied by 2^exponent.
template <class PolygonMesh, class VertexPointMap>
Vec3 sum_of_face_areas(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& mesh,
                       VertexPointMap vpm, int exponent)
{
  const Vec3 origin = to_vec3(get(vpm, v));
  auto local = [&](auto w) { return scaled_by_power_of_two(difference(to_vec3(get(vpm, w)), origin), exponent); };
  Vec3 sum = {{0, 0, 0}};
  for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh)) {
    if(is_border(h, mesh))
      continue;
    for(auto e : CGAL::halfedges_around_face(h, mesh)) { // Newell's sum over the face's edges
      const Vec3 p = local(source(e, mesh)), q = local(target(e, mesh));
      sum[0] += (p[1] - q[1]) * (p[2] + q[2]);
      sum[1] += (p[2] - q[2]) * (p[0] + q[0]);
      sum[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
  }
  return sum;
}

/// The largest coordinate offset from v to a neighbour: the scale of its star, by
/// which normals are summed again where the cross products under- or overflowed.
template <class PolygonMesh, class VertexPointMap>
double star_extent(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& mesh,
                   VertexPointMap vpm)
{
  double largest = 0;
  const Vec3 p = to_vec3(get(vpm, v));
  for(auto w : CGAL::vertices_around_target(v, mesh)) {
    const Vec3 d = difference(to_vec3(get(vpm, w)), p);
    largest = (std::max)({largest, std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  }
  return largest;
}

/// Walks the connected component of `seed` (a face not in `reached`) across its
/// edges, depth first: each face newly reached goes into `reached` and to `visit`, the
/// seed first. `reached` is shared by the calls on one mesh, so that each component is
/// walked once. The one component walk of the output meshes (the input's, on millions
/// of faces, marks a vector by face index: `one_face_per_component()`).
template <class PolygonMesh, class Visit>
void walk_component(typename boost::graph_traits<PolygonMesh>::face_descriptor seed, const PolygonMesh& mesh,
                    std::set<typename boost::graph_traits<PolygonMesh>::face_descriptor>& reached,
                    const Visit& visit)
{
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  reached.insert(seed);
  visit(seed);
  std::vector<face_descriptor> stack(1, seed);
  while(!stack.empty()) {
    const face_descriptor f = stack.back();
    stack.pop_back();
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
      const auto o = opposite(h, mesh);
      if(!is_border(o, mesh) && reached.insert(face(o, mesh)).second) {
        visit(face(o, mesh));
        stack.push_back(face(o, mesh));
      }
    }
  }
}

/// The one way a vertex normal is made: `star_sum(e)` sums the faces' weighted normals
/// around v with the star scaled by 2^e (the direction does not depend on e), and the
/// sum is normalised; zero if it vanishes. Where it under- or overflows (coordinates
/// near 1e-200 or 1e200, or subnormal), the star is scaled to unit size and summed
/// again (rare, so the common case pays nothing).
template <class PolygonMesh, class VertexPointMap, class StarSum>
Vec3 unit_vertex_normal(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& mesh,
                        VertexPointMap vpm, const StarSum& star_sum)
{
  const Vec3 unit = normalized(star_sum(0));
  if(unit[0] != 0 || unit[1] != 0 || unit[2] != 0)
    return unit;
  const double largest = star_extent(v, mesh, vpm);
  return largest > 0 && std::isfinite(largest) ? normalized(star_sum(-std::ilogb(largest))) : unit;
}

/// The unit normal of vertex v of a polygon mesh: the sum of its faces' area vectors
/// (Newell's, which on a triangle is the area vector `Lazy_vertex_normal_map` sums).
/// Not CGAL's `compute_vertex_normal()`: its visibility-maximising normal is much dearer
/// than the contouring when the output asks for normals, and its circumcentre
/// construction asserts on underflowing coordinates (found by the fuzzer).
template <class PolygonMesh, class VertexPointMap>
Vec3 area_weighted_vertex_normal(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                 const PolygonMesh& mesh, VertexPointMap vpm)
{
  return unit_vertex_normal(v, mesh, vpm, [&](int exponent) { return sum_of_face_areas(v, mesh, vpm, exponent); });
}

/// The tangent planes of a mesh that comes without any (one it did not produce): for
/// each vertex, by vertex index, the planes (centroid, unit normal) of its faces.
/// Projecting on them keeps a vertex on its faces' planes, on a crease line between
/// two of them, at a corner among three.
template <class PolygonMesh, class VertexPointMap, class VertexIndexMap>
std::vector<Tangent_planes> planes_of_incident_faces(const PolygonMesh& mesh, VertexPointMap vpm,
                                                     VertexIndexMap vertex_index)
{
  std::vector<Tangent_planes> planes(index_bound(vertices(mesh), vertex_index));
  std::vector<Vec3> corners;
  for(auto f : faces(mesh)) {
    corners.clear();
    Vec3 centroid = {{0, 0, 0}};
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
      corners.push_back(to_vec3(get(vpm, v)));
      for(int d = 0; d < 3; ++d)
        centroid[d] += corners.back()[d];
    }
    for(int d = 0; d < 3; ++d)
      centroid[d] /= double(corners.size());
    const Vec3 normal = normalized(newell_normal(corners));
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      planes[get(vertex_index, v)].emplace_back(centroid, normal);
  }
  return planes;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H
