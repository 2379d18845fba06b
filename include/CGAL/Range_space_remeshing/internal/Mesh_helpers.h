// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_MESH_HELPERS_H

// Small FaceGraph helpers shared by the dual, the collapse and the relaxation.

#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/assertions_behaviour.h>
#include <CGAL/exceptions.h>
#include <CGAL/boost/graph/iterator.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
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

/// The unit normal of vertex v: CGAL's `compute_vertex_normal()` where it works; on
/// faces so degenerate that its construction fails (an assertion on a circumcentre of
/// underflowing coordinates, found by the fuzzer) or gives a non-finite vector, the
/// sum of the incident faces' area vectors, normalised (zero if they all vanish).
template <class PolygonMesh, class VertexPointMap>
Vec3 robust_vertex_normal(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                          const PolygonMesh& mesh, VertexPointMap vpm)
{
  try {
    const auto n = CGAL::Polygon_mesh_processing::compute_vertex_normal(
        v, mesh, CGAL::parameters::vertex_point_map(vpm));
    const Vec3 result = {{CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())}};
    if(std::isfinite(result[0]) && std::isfinite(result[1]) && std::isfinite(result[2]))
      return result;
  } catch(const CGAL::Failure_exception&) {
  }
  std::vector<Vec3> corners;
  Vec3 sum = {{0, 0, 0}};
  for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh)) {
    if(is_border(h, mesh))
      continue;
    corners.clear();
    for(auto w : CGAL::vertices_around_face(h, mesh))
      corners.push_back(to_vec3(get(vpm, w)));
    const Vec3 area = newell_normal(corners);
    for(int d = 0; d < 3; ++d)
      sum[d] += area[d];
  }
  const Vec3 unit = normalized(sum);
  return std::isfinite(unit[0]) && std::isfinite(unit[1]) && std::isfinite(unit[2]) ? unit : Vec3{{0, 0, 0}};
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
