// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_LAZY_VERTEX_NORMAL_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_LAZY_VERTEX_NORMAL_MAP_H

#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

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

namespace internal {

/// A face's share of its corner's normal, from the corner's two edges: its area
/// vector (twice the area, normal direction), scaled to the corner's angle for ANGLE.
inline Vec3 corner_term(const Vec3& to_next, const Vec3& to_previous, Normal_weighting weighting)
{
  Vec3 twice_area_normal = cross(to_next, to_previous);
  if(weighting == Normal_weighting::ANGLE) {
    const double length = std::sqrt(dot(twice_area_normal, twice_area_normal));
    const double weight = length > 0 ? std::atan2(length, dot(to_next, to_previous)) / length : 0.;
    for(double& x : twice_area_normal)
      x *= weight;
  }
  return twice_area_normal;
}

} // namespace internal

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
    return internal::unit_vertex_normal(v, *tm_, vpm_, [&](int exponent) { return weighted_sum(v, exponent); });
  }

  /// The sum of the faces' normals around v, weighted, with the star scaled by 2^exponent.
  internal::Vec3 weighted_sum(key_type v, int exponent) const
  {
    using internal::Vec3;
    Vec3 sum = {{0, 0, 0}};
    const Vec3 p = internal::to_vec3(get(vpm_, v));
    auto edge_to = [&](auto w) {
      return internal::scaled_by_power_of_two(internal::difference(internal::to_vec3(get(vpm_, w)), p), exponent);
    };
    for(auto h : CGAL::halfedges_around_target(v, *tm_)) {
      if(is_border(h, *tm_))
        continue;
      // the face's corner at v: from v to the next and the previous corner
      const Vec3 term =
          internal::corner_term(edge_to(target(next(h, *tm_), *tm_)), edge_to(source(h, *tm_)), weighting_);
      for(int d = 0; d < 3; ++d)
        sum[d] += term[d];
    }
    return sum;
  }

  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  Normal_weighting weighting_;
};

namespace internal {

template <class Vector>
Vector make_vector(const Vec3& v)
{
  if constexpr(std::is_constructible<Vector, double, double, double>::value)
    return Vector(v[0], v[1], v[2]); // CGAL's vectors and points
  else
    return Vector{{v[0], v[1], v[2]}}; // std::array
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingMaps

writes into `normals` the unit normal of every vertex of `tm`, the one
`Lazy_vertex_normal_map` computes with the same weighting, in one pass over the faces.

For the complete scan of a mesh, which maps every vertex anyway, this is the cheaper
way to feed a normal-based range map (`Position_normal_range_map`,
`Position_normal_color_range_map`, `Gauss_range_map`): the lazy map reads each vertex's
star on its own, scattered in memory, which makes it several times slower than this
pass when every vertex is read. The lazy map keeps the seeded traversal sublinear: use
it there.

\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`.
\tparam VertexNormalMap a writable property map, vertex -> `std::array<double, 3>` or a
        CGAL 3-D vector.
\tparam VertexPointMap a readable property map, vertex -> 3-D CGAL point.
*/
template <class TriangleMesh, class VertexNormalMap, class VertexPointMap>
void compute_vertex_normals(const TriangleMesh& tm, VertexNormalMap normals, Normal_weighting weighting,
                            VertexPointMap vpm)
{
  using Lazy = Lazy_vertex_normal_map<TriangleMesh, VertexPointMap>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Normal = typename boost::property_traits<VertexNormalMap>::value_type;
  const auto index = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<internal::Vec3> sums(internal::index_bound(vertices(tm), index), internal::Vec3{{0, 0, 0}});
  auto add = [&](vertex_descriptor v, const internal::Vec3& term) {
    internal::Vec3& sum = sums[get(index, v)];
    for(int d = 0; d < 3; ++d)
      sum[d] += term[d];
  };
  auto point = [&](vertex_descriptor v) { return internal::to_vec3(get(vpm, v)); };
  for(auto f : faces(tm)) {
    const auto h0 = halfedge(f, tm);
    if(weighting == Normal_weighting::AREA && next(next(next(h0, tm), tm), tm) == h0) {
      // a triangle: the same area vector for its three corners
      const vertex_descriptor a = source(h0, tm), b = target(h0, tm), c = target(next(h0, tm), tm);
      const internal::Vec3 p = point(a);
      const internal::Vec3 term =
          internal::corner_term(internal::difference(point(b), p), internal::difference(point(c), p), weighting);
      add(a, term);
      add(b, term);
      add(c, term);
      continue;
    }
    for(auto h : CGAL::halfedges_around_face(h0, tm)) {
      const internal::Vec3 p = point(target(h, tm));
      add(target(h, tm), internal::corner_term(internal::difference(point(target(next(h, tm), tm)), p),
                                               internal::difference(point(source(h, tm)), p), weighting));
    }
  }
  const Lazy lazy(tm, vpm, weighting);
  for(vertex_descriptor v : vertices(tm)) {
    const internal::Vec3 unit = internal::normalized(sums[get(index, v)]);
    // a vanishing or overflowing sum: the lazy map rescales the star
    const bool found = unit[0] != 0 || unit[1] != 0 || unit[2] != 0;
    put(normals, v, internal::make_vector<Normal>(found ? unit : get(lazy, v)));
  }
}

/// `compute_vertex_normals()` with the mesh's own vertex points.
template <class TriangleMesh, class VertexNormalMap>
void compute_vertex_normals(const TriangleMesh& tm, VertexNormalMap normals,
                            Normal_weighting weighting = Normal_weighting::AREA)
{
  compute_vertex_normals(tm, normals, weighting, get(CGAL::vertex_point, tm));
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_LAZY_VERTEX_NORMAL_MAP_H
