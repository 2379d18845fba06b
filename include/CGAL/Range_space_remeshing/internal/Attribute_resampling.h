// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H

// The vertex attributes of remesh()'s output, sampled where its vertices end: the
// collapse, the relaxation and the untangling move the vertices after the dual gave
// them the mean of their primal face's values, by up to about a cell, so a texture's
// lines would waver. Each output vertex takes the values at the nearest point of the
// input (CGAL's AABB tree finds it and its face).

#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_attributes.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/version.h>
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/AABB_traits_3.h>
#else
#include <CGAL/AABB_traits.h>
#endif
#include <CGAL/Kernel_traits.h>

#include <array>
#include <cstddef>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The barycentric coordinates of q, a point of the triangle (a, b, c), as the areas of
/// the triangles q makes with each side over their sum. Hand-written where CGAL has
/// `Polygon_mesh_processing::locate_in_face()`: that asserts on a triangle without
/// area, and the zero-area triangles of insert_crease_triangles() are inputs of
/// remesh() by design; here such a face gives its first corner's values.
inline std::array<double, 3> barycentric_weights(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c)
{
  auto area = [&q](const Vec3& x, const Vec3& y) {
    const Vec3 n = cross(difference(x, q), difference(y, q));
    return std::sqrt(dot(n, n));
  };
  const std::array<double, 3> areas = {area(b, c), area(c, a), area(a, b)};
  const double sum = areas[0] + areas[1] + areas[2];
  if(!(sum > 0) || !std::isfinite(sum))
    return {{1, 0, 0}};
  return {{areas[0] / sum, areas[1] / sum, areas[2] / sum}};
}

/// Puts at every vertex of `out` the mix of the attributes' input values at the
/// nearest point of `tm` (its vertex points `vpm`) to the vertex's point (`out_vpm`).
template <class TriangleMesh, class VertexPointMap, class PolygonMesh, class OutVertexPointMap, class Attributes>
void sample_attributes_at_nearest_points(const TriangleMesh& tm, VertexPointMap vpm, const PolygonMesh& out,
                                         OutVertexPointMap out_vpm, const Attributes& attributes,
                                         const Progress& progress)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VertexPointMap>;
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits_3<Kernel, Primitive>>;
#else
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
#endif
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  if(num_faces(tm) == 0)
    return;
  Tree tree(faces(tm).first, faces(tm).second, tm, vpm);
  tree.accelerate_distance_queries();
  std::array<std::pair<vertex_descriptor, double>, 3> sources;
  std::size_t done = 0;
  for(auto v : vertices(out)) {
    progress.report_every(Remeshing_stage::RELAXATION, done++, num_vertices(out));
    const auto& p = get(out_vpm, v);
    const Point query(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    const auto nearest = tree.closest_point_and_primitive(query);
    const auto h = halfedge(nearest.second, tm);
    const std::array<vertex_descriptor, 3> corners = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
    const std::array<double, 3> weights = barycentric_weights(to_vec3(nearest.first), to_vec3(get(vpm, corners[0])),
                                                              to_vec3(get(vpm, corners[1])),
                                                              to_vec3(get(vpm, corners[2])));
    for(int i = 0; i < 3; ++i)
      sources[i] = {corners[i], weights[i]};
    attributes.put_mixed(v, sources);
  }
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_ATTRIBUTE_RESAMPLING_H
