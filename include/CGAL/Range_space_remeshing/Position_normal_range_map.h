// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_POSITION_NORMAL_RANGE_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_POSITION_NORMAL_RANGE_MAP_H

#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <array>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingMaps

Position and normal into \f$\mathbb{R}^6\f$: a vertex goes to
\f$(w_p\,p, w_n\,n)\f$, its position and unit normal with their own weights. A cell of
size h bounds, on every output face, the extent of the positions by \f$h / w_p\f$ and
the variation of the normals by \f$h / w_n\f$: a large normal weight gives faces that
are small where the surface bends and elongated along its flat directions
(anisotropic), a normal weight going to 0 gives the uniform remesh of the identity map.

\tparam VertexPointMap a readable property map, vertex -> 3-D CGAL point.
\tparam NormalMap a readable property map, vertex -> 3-D vector (need not be unit).

\cgalModels `ReadablePropertyMap`
*/
template <class VertexPointMap, class NormalMap>
class Position_normal_range_map
{
public:
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = std::array<double, 6>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Position_normal_range_map(VertexPointMap vpm, NormalMap normals, double position_weight = 1.,
                            double normal_weight = 1.)
    : vpm_(vpm), normals_(normals), position_weight_(position_weight), normal_weight_(normal_weight)
  {}

  double position_weight() const { return position_weight_; }
  double normal_weight() const { return normal_weight_; }

  friend value_type get(const Position_normal_range_map& map, const key_type& v)
  {
    const internal::Vec3 p = internal::to_vec3(get(map.vpm_, v));
    const internal::Vec3 n = internal::normalized(internal::to_vec3(get(map.normals_, v)));
    const double wp = map.position_weight_, wn = map.normal_weight_;
    return {{wp * p[0], wp * p[1], wp * p[2], wn * n[0], wn * n[1], wn * n[2]}};
  }

private:
  VertexPointMap vpm_;
  NormalMap normals_;
  double position_weight_, normal_weight_;
};

/// Position and area-weighted normal (computed lazily) of the vertices of `tm`.
template <class TriangleMesh>
Position_normal_range_map<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
                          Lazy_vertex_normal_map<TriangleMesh>>
make_position_normal_range_map(const TriangleMesh& tm, double position_weight = 1., double normal_weight = 1.)
{
  return {get(CGAL::vertex_point, tm), Lazy_vertex_normal_map<TriangleMesh>(tm), position_weight, normal_weight};
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_POSITION_NORMAL_RANGE_MAP_H
