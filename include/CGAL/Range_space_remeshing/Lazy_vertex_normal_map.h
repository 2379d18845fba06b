// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_LAZY_VERTEX_NORMAL_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_LAZY_VERTEX_NORMAL_MAP_H

#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {

/// How `Lazy_vertex_normal_map` weighs the normals of a vertex's faces.
enum class Normal_weighting
{
  /// by the face's area: the gradient of the enclosed volume (the default)
  AREA,
  /// by the face's angle at the vertex: does not depend on how the faces around the
  /// vertex are tessellated
  ANGLE
};

/*!
\ingroup PkgRangeSpaceRemeshingMaps

The unit normal of a vertex of a triangle mesh, computed when asked for: the weighted
sum of its faces' normals, normalised. Range maps built on it (`Gauss_range_map`,
`Position_normal_range_map`) stay lazy: the remesher evaluates them only on the
vertices its arcs reach, so the seeded traversal stays sublinear. A vertex whose
faces all have zero area gets the zero vector.

\tparam TriangleMesh a model of `FaceGraph`.
\tparam VertexPointMap a readable property map, vertex -> 3-D CGAL point.

\cgalModels `ReadablePropertyMap`
*/
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Lazy_vertex_normal_map
{
public:
  using key_type = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Lazy_vertex_normal_map(const TriangleMesh& tm, VertexPointMap vpm,
                         Normal_weighting weighting = Normal_weighting::AREA)
    : tm_(&tm), vpm_(vpm), weighting_(weighting)
  {}

  explicit Lazy_vertex_normal_map(const TriangleMesh& tm, Normal_weighting weighting = Normal_weighting::AREA)
    : Lazy_vertex_normal_map(tm, get(CGAL::vertex_point, tm), weighting)
  {}

  friend value_type get(const Lazy_vertex_normal_map& map, key_type v) { return map.normal(v); }

private:
  value_type normal(key_type v) const
  {
    const internal::Vec3 sum = weighted_sum(v, 1.);
    const internal::Vec3 unit = internal::normalized(sum);
    if(unit[0] != 0 || unit[1] != 0 || unit[2] != 0)
      return unit;
    // Nothing, or an overflow: with coordinates near 1e-200 or 1e200 the cross
    // products under- or overflow. Both weightings are scale-invariant in direction:
    // retry with the star scaled to unit size (rare, so the common case pays nothing).
    const double largest = internal::star_extent(v, *tm_, vpm_);
    return largest > 0 && std::isfinite(largest) ? internal::normalized(weighted_sum(v, 1. / largest)) : unit;
  }

  /// The sum of the faces' normals around v, weighted, with the star scaled by `scale`.
  internal::Vec3 weighted_sum(key_type v, double scale) const
  {
    using internal::Vec3;
    Vec3 sum = {{0, 0, 0}};
    const Vec3 p = internal::to_vec3(get(vpm_, v));
    auto edge_to = [&](auto w) {
      Vec3 d = internal::difference(internal::to_vec3(get(vpm_, w)), p);
      for(double& x : d)
        x *= scale;
      return d;
    };
    for(auto h : CGAL::halfedges_around_target(v, *tm_)) {
      if(is_border(h, *tm_))
        continue;
      // the face's corner at v: from v to the next and the previous corner
      const Vec3 to_next = edge_to(target(next(h, *tm_), *tm_));
      const Vec3 to_previous = edge_to(source(h, *tm_));
      const Vec3 twice_area_normal = internal::cross(to_next, to_previous);
      double weight = 1; // AREA: the cross product's length is the weight
      if(weighting_ == Normal_weighting::ANGLE) {
        const double length = std::sqrt(internal::dot(twice_area_normal, twice_area_normal));
        if(!(length > 0))
          continue;
        weight = std::atan2(length, internal::dot(to_next, to_previous)) / length;
      }
      for(int d = 0; d < 3; ++d)
        sum[d] += weight * twice_area_normal[d];
    }
    return sum;
  }

  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  Normal_weighting weighting_;
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_LAZY_VERTEX_NORMAL_MAP_H
