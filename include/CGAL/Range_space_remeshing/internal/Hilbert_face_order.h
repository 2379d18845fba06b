// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_HILBERT_FACE_ORDER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_HILBERT_FACE_ORDER_H

// The order of copy_in_spatial_order(): the faces along a Hilbert curve through their
// centroids (CGAL's hilbert_sort), the centroids in double precision since they only
// order the faces.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The faces of `tm` in the order of a Hilbert curve through their centroids.
/// Throws `Remeshing_error` if a corner has a NaN or infinite coordinate.
template <class PolygonMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>
faces_in_hilbert_order(const PolygonMesh& tm, VertexPointMap vpm)
{
  using face_descriptor = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  using Sorting_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<face_descriptor> input_faces;
  std::vector<Sorting_kernel::Point_3> centroids;
  for(face_descriptor f : faces(tm)) {
    Vec3 sum = {{0, 0, 0}};
    double corners = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      const Vec3 p = to_vec3(get(vpm, v));
      for(int d = 0; d < 3; ++d)
        sum[d] += p[d];
      ++corners;
    }
    // a NaN would break the sort's ordering (undefined behaviour), an infinity its subdivision
    if(!(std::isfinite(sum[0]) && std::isfinite(sum[1]) && std::isfinite(sum[2])))
      throw Remeshing_error("copy_in_spatial_order: a corner of input face " + std::to_string(input_faces.size()) +
                            " (in the order of faces(tm)) has a NaN or infinite coordinate");
    input_faces.push_back(f);
    centroids.emplace_back(sum[0] / corners, sum[1] / corners, sum[2] / corners);
  }
  std::vector<std::size_t> order(input_faces.size());
  for(std::size_t k = 0; k < order.size(); ++k)
    order[k] = k;
  const auto centroid_of = CGAL::make_property_map(centroids);
  CGAL::hilbert_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Sorting_kernel, decltype(centroid_of)>(centroid_of));
  std::vector<face_descriptor> ordered;
  ordered.reserve(order.size());
  for(std::size_t k : order)
    ordered.push_back(input_faces[k]);
  return ordered;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_HILBERT_FACE_ORDER_H
