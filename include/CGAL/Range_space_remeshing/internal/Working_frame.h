// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_WORKING_FRAME_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_WORKING_FRAME_H

// The stages of remesh() after the primal (dual placement, collapse, relaxation,
// untangling) compute in doubles with squares and higher powers of lengths:
// quadrics, squared lengths, areas, angles. Where the surface is much larger than 1
// (1e300) they overflow, where much smaller (1e-300, subnormal) they underflow, and the
// output's points became NaN. Those stages then run in a working frame where the
// primal's extent is about 1: its points are moved to the centre of their bounding box
// and scaled by a power of two, and the output's points are moved back. Within ordinary
// extents the frame is the identity, and changes no bit of the output.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

// extents of the primal within these powers of two are worked on as they are: their
// fourth powers stay normal doubles
constexpr int smallest_worked_exponent = -100;
constexpr int largest_worked_exponent = 100;

class Working_frame
{
public:
  /// The frame for a mesh with points `vpm`: the identity unless its extent is outside
  /// [2^-100, 2^100].
  template <class PolygonMesh, class VertexPointMap>
  static Working_frame of(const PolygonMesh& mesh, VertexPointMap vpm)
  {
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh, CGAL::parameters::vertex_point_map(vpm));
    const Vec3 low = {{box.xmin(), box.ymin(), box.zmin()}}, high = {{box.xmax(), box.ymax(), box.zmax()}};
    double extent = 0;
    for(int d = 0; d < 3; ++d)
      extent = (std::max)(extent, high[d] / 2 - low[d] / 2); // halves: never beyond doubles
    Working_frame frame;
    if(!(extent > 0) || !std::isfinite(extent))
      return frame;
    const int exponent = std::ilogb(extent) + 1;
    if(exponent >= smallest_worked_exponent && exponent <= largest_worked_exponent)
      return frame;
    for(int d = 0; d < 3; ++d)
      frame.centre_[d] = low[d] + (high[d] / 2 - low[d] / 2);
    frame.exponent_ = exponent;
    return frame;
  }

  bool is_identity() const { return exponent_ == 0; }

  /// Moves the points of `mesh` into the frame.
  template <class PolygonMesh, class VertexPointMap>
  void move_into(const PolygonMesh& mesh, VertexPointMap vpm) const
  {
    if(is_identity())
      return;
    for(auto v : vertices(mesh))
      put_point(vpm, v, scaled_by_power_of_two(difference(to_vec3(get(vpm, v)), centre_), -exponent_));
  }

  /// Moves the points of `mesh` out of the frame, back to the input's coordinates;
  /// throws Remeshing_error if one is then beyond doubles.
  template <class PolygonMesh, class VertexPointMap>
  void move_back(const PolygonMesh& mesh, VertexPointMap vpm) const
  {
    if(is_identity())
      return;
    for(auto v : vertices(mesh)) {
      Vec3 p = scaled_by_power_of_two(to_vec3(get(vpm, v)), exponent_);
      for(int d = 0; d < 3; ++d) {
        p[d] += centre_[d];
        if(!std::isfinite(p[d]))
          throw Remeshing_error("an output point lies beyond the largest double (1.8e308)",
                                Remeshing_error::Kind::BAD_INPUT);
      }
      put_point(vpm, v, p);
    }
  }

private:
  template <class VertexPointMap, class Vertex>
  static void put_point(VertexPointMap vpm, Vertex v, const Vec3& p)
  {
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    put(vpm, v, Point(p[0], p[1], p[2]));
  }

  Vec3 centre_ = {{0, 0, 0}};
  int exponent_ = 0; // points are scaled by 2^-exponent_ in the frame
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_WORKING_FRAME_H
