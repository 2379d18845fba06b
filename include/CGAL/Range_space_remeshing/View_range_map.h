// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_VIEW_RANGE_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_VIEW_RANGE_MAP_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/property_map.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {

/// A pinhole camera: the view-projection matrix (row-major, OpenGL conventions: the
/// camera looks along its -z axis, clip = matrix * (x, y, z, 1)) and the viewport.
struct Camera
{
  std::array<double, 16> view_projection = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
  double width = 1, height = 1; // viewport, in pixels
};

/*!
\ingroup PkgRangeSpaceRemeshingMaps

Makes the `Camera` at `eye` looking at `target`, `up` giving the vertical, with a
vertical field of view of `fov_degrees` and a viewport of `width` x `height` pixels.
*/
inline Camera make_look_at_camera(const std::array<double, 3>& eye, const std::array<double, 3>& target,
                                  const std::array<double, 3>& up, double fov_degrees, double width,
                                  double height)
{
  using namespace internal;
  const Vec3 back = normalized(difference(eye, target)); // the camera's +z
  const Vec3 right = normalized(cross(up, back));
  const Vec3 true_up = cross(back, right);
  if(!(dot(back, back) > 0) || !(dot(right, right) > 0) || !(fov_degrees > 0 && fov_degrees < 180) ||
     !(width > 0 && height > 0))
    throw Remeshing_error("camera: eye and target must differ, up must not be along the view, the field "
                          "of view must be between 0 and 180 degrees and the viewport positive",
                          Remeshing_error::Kind::BAD_PARAMETER);
  const double f = 1 / std::tan(fov_degrees * 3.14159265358979323846 / 360), aspect = width / height;
  // projection without near/far clipping terms: the third row keeps the view depth
  const std::array<Vec3, 3> rows = {{right, true_up, back}};
  Camera camera;
  camera.width = width;
  camera.height = height;
  const double scale[3] = {f / aspect, f, 1};
  for(int r = 0; r < 3; ++r) {
    for(int c = 0; c < 3; ++c)
      camera.view_projection[4 * r + c] = scale[r] * rows[r][c];
    camera.view_projection[4 * r + 3] = -scale[r] * dot(rows[r], eye);
  }
  // w = distance in front of the camera = -(view z)
  for(int c = 0; c < 3; ++c)
    camera.view_projection[12 + c] = -back[c];
  camera.view_projection[15] = dot(back, eye);
  return camera;
}

/*!
\ingroup PkgRangeSpaceRemeshingMaps

The view-dependent map into \f$\mathbb{R}^3\f$: a vertex goes to its pixel coordinates
for `camera`, and its distance in front of the camera times `depth_weight` (so that
sheets one behind the other stay apart). A cell of h pixels then bounds every output
face to h pixels on the screen: faces far from the camera come out larger in space.
Vertices must be in front of the camera: a vertex behind it raises `Remeshing_error`
when the map is evaluated on it.

\cgalModels `ReadablePropertyMap`
*/
template <class VertexPointMap>
class View_range_map
{
public:
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = std::array<double, 3>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  View_range_map(VertexPointMap vpm, const Camera& camera, double depth_weight = 0)
    : vpm_(vpm), camera_(camera), depth_weight_(depth_weight)
  {}

  friend value_type get(const View_range_map& map, const key_type& v)
  {
    const internal::Vec3 p = internal::to_vec3(get(map.vpm_, v));
    const auto& m = map.camera_.view_projection;
    double clip[4];
    for(int r = 0; r < 4; ++r)
      clip[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
    if(!(clip[3] > 0))
      throw Remeshing_error("view map: a vertex is behind the camera (or on its plane)");
    return {{(clip[0] / clip[3] + 1) / 2 * map.camera_.width, (clip[1] / clip[3] + 1) / 2 * map.camera_.height,
             map.depth_weight_ * clip[3]}};
  }

private:
  VertexPointMap vpm_;
  Camera camera_;
  double depth_weight_;
};

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_VIEW_RANGE_MAP_H
