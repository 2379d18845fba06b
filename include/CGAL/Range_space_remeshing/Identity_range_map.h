// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_IDENTITY_RANGE_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_IDENTITY_RANGE_MAP_H

#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <array>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingMaps

The identity map into \f$\mathbb{R}^3\f$, scaled: a vertex goes to `scale` times its
position. Remeshing under it bounds the extent of every output face by the cell
size (divided by `scale`) in each coordinate: a uniform remesh.

\tparam VertexPointMap a readable property map, vertex -> 3-D CGAL point.

\cgalModels `ReadablePropertyMap`
*/
template <class VertexPointMap>
class Identity_range_map
{
public:
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  explicit Identity_range_map(VertexPointMap vpm = VertexPointMap(), double scale = 1.)
    : vpm_(vpm), scale_(scale)
  {}

  double scale() const { return scale_; }

  friend value_type get(const Identity_range_map& map, const key_type& v)
  {
    const auto& p = get(map.vpm_, v);
    return {{map.scale_ * CGAL::to_double(p.x()), map.scale_ * CGAL::to_double(p.y()),
             map.scale_ * CGAL::to_double(p.z())}};
  }

private:
  VertexPointMap vpm_;
  double scale_;
};

/// Makes an `Identity_range_map` from a vertex point map and a scale factor.
template <class VertexPointMap>
Identity_range_map<VertexPointMap> make_identity_range_map(VertexPointMap vpm, double scale = 1.)
{
  return Identity_range_map<VertexPointMap>(vpm, scale);
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_IDENTITY_RANGE_MAP_H
