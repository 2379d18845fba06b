// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_GAUSS_RANGE_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_GAUSS_RANGE_MAP_H

#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {

namespace internal {

/// The unit normal n pushed radially onto the cube [-1, 1]^3: n / max |n_i|. The paper
/// remeshes the Gauss map on the cube rather than on the sphere: cells of a grid cut
/// the cube's flat sides evenly. The zero vector stays zero.
inline Vec3 onto_unit_cube(const Vec3& n)
{
  const double largest = (std::max)({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
  if(!(largest > 0))
    return {{0, 0, 0}};
  return {{n[0] / largest, n[1] / largest, n[2] / largest}};
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingMaps

The Gauss map into \f$\mathbb{R}^3\f$: a vertex goes to `scale` times its unit normal,
pushed radially onto the cube \f$[-1, 1]^3\f$ (as in the paper, so that the grid cuts
the image evenly). Remeshing under it bounds the normal variation of every output
face; in the limit of small cells, faces are elongated along the direction of
minimum curvature, with an aspect ratio that follows the ratio of the principal
curvatures. The normals are read from `NormalMap` (e.g. a `Lazy_vertex_normal_map`,
or the user's own), and need not be unit.

\tparam NormalMap a readable property map, vertex -> 3-D vector (CGAL `Vector_3` or
  `std::array<double, 3>`).

\cgalModels `ReadablePropertyMap`
*/
template <class NormalMap>
class Gauss_range_map
{
public:
  using key_type = typename boost::property_traits<NormalMap>::key_type;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  explicit Gauss_range_map(NormalMap normals, double scale = 1.) : normals_(normals), scale_(scale) {}

  double scale() const { return scale_; }

  friend value_type get(const Gauss_range_map& map, const key_type& v)
  {
    const internal::Vec3 n = internal::onto_unit_cube(internal::normalized(internal::to_vec3(get(map.normals_, v))));
    return {{map.scale_ * n[0], map.scale_ * n[1], map.scale_ * n[2]}};
  }

private:
  NormalMap normals_;
  double scale_;
};

/// The Gauss map of `tm` with area-weighted vertex normals, computed lazily.
template <class TriangleMesh>
Gauss_range_map<Lazy_vertex_normal_map<TriangleMesh>> make_gauss_range_map(const TriangleMesh& tm,
                                                                          double scale = 1.)
{
  return Gauss_range_map<Lazy_vertex_normal_map<TriangleMesh>>(Lazy_vertex_normal_map<TriangleMesh>(tm), scale);
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_GAUSS_RANGE_MAP_H
