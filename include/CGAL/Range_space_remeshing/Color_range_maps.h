// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_COLOR_RANGE_MAPS_H
#define CGAL_RANGE_SPACE_REMESHING_COLOR_RANGE_MAPS_H

#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/internal/Color.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {


/*!
\ingroup PkgRangeSpaceRemeshingMaps

The magnitudes \f$(\|\nabla r\|, \|\nabla g\|, \|\nabla b\|)\f$ of the gradients of the
colour channels at a vertex, computed when asked for: on each incident triangle the
colour is linear and its gradient constant; the vertex takes the area-weighted mean
of the gradient magnitudes of its triangles. Colours in [0, 1] per channel (from
`CGAL::IO::Color` or any triple); the result is in colour units per length unit.
Used as the colour part of `Position_normal_color_range_map`, it gives the paper's
\f$\mathbb{R}^9\f$ map: faces shrink where the colour changes fast.

\cgalModels `ReadablePropertyMap`
*/
template <class TriangleMesh, class VertexColorMap,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Color_gradient_magnitude_map
{
public:
  using key_type = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Color_gradient_magnitude_map(const TriangleMesh& tm, VertexColorMap colors, VertexPointMap vpm)
    : tm_(&tm), colors_(colors), vpm_(vpm)
  {}
  Color_gradient_magnitude_map(const TriangleMesh& tm, VertexColorMap colors)
    : Color_gradient_magnitude_map(tm, colors, get(CGAL::vertex_point, tm))
  {}

  friend value_type get(const Color_gradient_magnitude_map& map, key_type v) { return map.magnitudes(v); }

private:
  value_type magnitudes(key_type v) const
  {
    using internal::Vec3;
    Vec3 sum = {{0, 0, 0}};
    double total_area = 0;
    for(auto h : CGAL::halfedges_around_target(v, *tm_)) {
      if(is_border(h, *tm_))
        continue;
      const auto u = source(h, *tm_), w = target(next(h, *tm_), *tm_);
      const Vec3 p = internal::to_vec3(get(vpm_, v));
      const Vec3 e1 = internal::difference(internal::to_vec3(get(vpm_, w)), p);
      const Vec3 e2 = internal::difference(internal::to_vec3(get(vpm_, u)), p);
      const Vec3 n = internal::cross(e1, e2); // |n| = twice the area
      const double n2 = internal::dot(n, n);
      if(!(n2 > 0))
        continue;
      const Vec3 cv = internal::to_rgb(get(colors_, v)), cw = internal::to_rgb(get(colors_, w)),
                 cu = internal::to_rgb(get(colors_, u));
      // gradient of the linear function with values dw, du along e1, e2 (and 0 at p):
      // (dw (e2 x n) + du (n x e1)) / |n|^2
      const Vec3 a = internal::cross(e2, n), b = internal::cross(n, e1);
      const double area = std::sqrt(n2) / 2;
      for(int c = 0; c < 3; ++c) {
        const double dw = cw[c] - cv[c], du = cu[c] - cv[c];
        const Vec3 g = {{(dw * a[0] + du * b[0]) / n2, (dw * a[1] + du * b[1]) / n2, (dw * a[2] + du * b[2]) / n2}};
        sum[c] += area * std::sqrt(internal::dot(g, g));
      }
      total_area += area;
    }
    if(!(total_area > 0))
      return {{0, 0, 0}};
    return {{sum[0] / total_area, sum[1] / total_area, sum[2] / total_area}};
  }

  const TriangleMesh* tm_;
  VertexColorMap colors_;
  VertexPointMap vpm_;
};

/*!
\ingroup PkgRangeSpaceRemeshingMaps

Position, normal and colour into \f$\mathbb{R}^9\f$: \f$(w_p\,p, w_n\,n, w_c\,c)\f$. With
the vertex colours as c (in [0, 1] per channel), a cell of size h bounds the colour
variation of every output face by \f$h / w_c\f$ per channel, besides the bounds of
`Position_normal_range_map`: faces shrink along colour transitions. With a
`Color_gradient_magnitude_map` as c, it is the paper's map.

\tparam ColorMap a readable property map, vertex -> `CGAL::IO::Color` or a triple of
  numbers.

\cgalModels `ReadablePropertyMap`
*/
template <class VertexPointMap, class NormalMap, class ColorMap>
class Position_normal_color_range_map
{
public:
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = std::array<double, 9>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  Position_normal_color_range_map(VertexPointMap vpm, NormalMap normals, ColorMap colors,
                                  double position_weight = 1., double normal_weight = 1.,
                                  double color_weight = 1.)
    : vpm_(vpm), normals_(normals), colors_(colors), weights_{{position_weight, normal_weight, color_weight}}
  {}

  friend value_type get(const Position_normal_color_range_map& map, const key_type& v)
  {
    const internal::Vec3 parts[3] = {internal::to_vec3(get(map.vpm_, v)),
                                     internal::normalized(internal::to_vec3(get(map.normals_, v))),
                                     internal::to_rgb(get(map.colors_, v))};
    value_type value;
    for(int part = 0; part < 3; ++part)
      for(int d = 0; d < 3; ++d)
        value[3 * part + d] = map.weights_[part] * parts[part][d];
    return value;
  }

private:
  VertexPointMap vpm_;
  NormalMap normals_;
  ColorMap colors_;
  std::array<double, 3> weights_;
};

/// Position, area-weighted normal and the colours of `colors` (direct flavour).
template <class TriangleMesh, class ColorMap>
Position_normal_color_range_map<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
                                Lazy_vertex_normal_map<TriangleMesh>, ColorMap>
make_position_normal_color_range_map(const TriangleMesh& tm, ColorMap colors, double position_weight = 1.,
                                     double normal_weight = 1., double color_weight = 1.)
{
  return {get(CGAL::vertex_point, tm), Lazy_vertex_normal_map<TriangleMesh>(tm), colors,
          position_weight, normal_weight, color_weight};
}

/// Position, area-weighted normal and the colour-gradient magnitudes (the paper's map).
template <class TriangleMesh, class ColorMap>
Position_normal_color_range_map<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
                                Lazy_vertex_normal_map<TriangleMesh>,
                                Color_gradient_magnitude_map<TriangleMesh, ColorMap>>
make_position_normal_color_gradient_range_map(const TriangleMesh& tm, ColorMap colors,
                                              double position_weight = 1., double normal_weight = 1.,
                                              double color_weight = 1.)
{
  return {get(CGAL::vertex_point, tm), Lazy_vertex_normal_map<TriangleMesh>(tm),
          Color_gradient_magnitude_map<TriangleMesh, ColorMap>(tm, colors), position_weight, normal_weight,
          color_weight};
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_COLOR_RANGE_MAPS_H
