// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_FACE_CORNERS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_FACE_CORNERS_H

// The faces of a mesh as flat arrays of vertex indices, and the shape of a face at
// given positions (fine, non-convex, folded): what the relaxation's fold test and the
// untangling walk.

#include <CGAL/Range_space_remeshing/internal/Polygon_tests.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The corners of every face and the faces of every corner, by index, in flat arrays:
/// what the fold test of the relaxation walks at every iteration.
struct Face_corners
{
  std::vector<std::size_t> first, corners; // face k: corners[first[k]] .. corners[first[k + 1]]
  std::vector<std::size_t> first_face, incident_faces; // vertex i: incident_faces[first_face[i]] .. [first_face[i + 1]]

  template <class PolygonMesh, class VertexIndexMap>
  Face_corners(const PolygonMesh& mesh, VertexIndexMap vertex_index, std::size_t number_of_vertices)
  {
    first.push_back(0);
    for(auto f : faces(mesh)) {
      for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        corners.push_back(get(vertex_index, v));
      first.push_back(corners.size());
    }
    first_face.assign(number_of_vertices + 1, 0);
    for(std::size_t i : corners)
      ++first_face[i + 1];
    for(std::size_t i = 0; i < number_of_vertices; ++i)
      first_face[i + 1] += first_face[i];
    incident_faces.resize(corners.size());
    std::vector<std::size_t> filled(first_face.begin(), first_face.end() - 1);
    for(std::size_t k = 0; k + 1 < first.size(); ++k)
      for(std::size_t c = first[k]; c < first[k + 1]; ++c)
        incident_faces[filled[corners[c]]++] = k;
  }
  std::size_t size() const { return first.size() - 1; }
  std::size_t corner_count(std::size_t k) const { return first[k + 1] - first[k]; }
};

/// What a face is at given positions, from best to worst: the relaxation refuses a
/// move that makes a face's shape worse, and the untangling repairs what is not fine.
enum class Face_shape : unsigned char
{
  FINE,       ///< turns left at every corner, seen from its vector-area normal
  NON_CONVEX, ///< not folded, but some corner turns against its vector-area normal (a dart, a bow-tie)
  FOLDED      ///< its vector area faces against its corners' normals: folded over its neighbours
};

/// Twice the vector area of a polygon of `count` corners (the fan from its first
/// corner, not from (0, 0, 0): no cancellation far from it) and the sum of its
/// corners' unit normals; `position(i)` and `normal(i)` give corner i's.
template <class Position, class Normal>
void polygon_area_and_reference(std::size_t count, const Position& position, const Normal& normal, Vec3& area,
                                Vec3& reference)
{
  area = {{0, 0, 0}};
  reference = {{0, 0, 0}};
  const Vec3& origin = position(0);
  for(std::size_t c = 0; c < count; ++c) {
    const Vec3 ab = cross(difference(position(c), origin), difference(position(next_corner(c, count)), origin));
    const Vec3& n = normal(c);
    for(int d = 0; d < 3; ++d) {
      area[d] += ab[d];
      reference[d] += n[d];
    }
  }
}

/// The shape of a polygon (corner test: (e_next x e_prev) . area > 0 at every corner,
/// the sign only, as the benchmark's quality measure).
template <class Position, class Normal>
Face_shape polygon_shape(std::size_t count, const Position& position, const Normal& normal)
{
  Vec3 area, reference;
  polygon_area_and_reference(count, position, normal, area, reference);
  if(dot(area, reference) < 0)
    return Face_shape::FOLDED;
  return turns_left_at_every_corner(count, position, area) ? Face_shape::FINE : Face_shape::NON_CONVEX;
}

/// The corner quality of a polygon: at each corner, the least over two normals (its
/// vector-area normal and its corners' mean normal) of (e_next x e_prev) . n over the
/// edges' lengths. Positive at every corner only where the face is fine and turns left
/// seen from the surface too, so that raising it unfolds as well as it opens reflex
/// corners. Returns the least; adds each corner's, at most `cap`, to `capped_sum`. A
/// polygon with a side or an area of length 0 counts -1 at every corner. With
/// `own_area_only`, the vector-area normal alone (where the corners' normals do not
/// tell the surface's side: over a fold of the input).
template <class Position, class Normal>
double polygon_corner_quality(std::size_t count, const Position& position, const Normal& normal, double cap,
                              double& capped_sum, bool own_area_only = false)
{
  Vec3 area, reference;
  polygon_area_and_reference(count, position, normal, area, reference);
  const Vec3 n[2] = {normalized(area), own_area_only ? normalized(area) : normalized(reference)};
  double worst = 1, sum = 0;
  for(std::size_t i = 0; i < count; ++i) {
    const Vec3& p = position(i);
    const Vec3 next = difference(position(next_corner(i, count)), p);
    const Vec3 prev = difference(position(previous_corner(i, count)), p);
    const double lengths = std::sqrt(dot(next, next) * dot(prev, prev));
    if(!(lengths > 0) || n[0] == Vec3{{0, 0, 0}} || n[1] == Vec3{{0, 0, 0}}) {
      capped_sum -= double(count);
      return -1;
    }
    const Vec3 turn = cross(next, prev);
    const double q = (std::min)(dot(turn, n[0]), dot(turn, n[1])) / lengths;
    worst = (std::min)(worst, q);
    sum += (std::min)(q, cap);
  }
  capped_sum += sum;
  return worst;
}

/// The shape of face k at these positions (see `polygon_shape()`).
inline Face_shape shape_of(const Face_corners& fc, std::size_t k, const std::vector<Vec3>& position,
                           const std::vector<Vec3>& normal)
{
  const std::size_t* corner = fc.corners.data() + fc.first[k];
  return polygon_shape(
      fc.corner_count(k), [&](std::size_t i) -> const Vec3& { return position[corner[i]]; },
      [&](std::size_t i) -> const Vec3& { return normal[corner[i]]; });
}

/// Whether face k turns left at every corner seen from its own vector area (the
/// issue's and the benchmark's criterion, which does not look at the normals).
inline bool is_convex_in_itself(const Face_corners& fc, std::size_t k, const std::vector<Vec3>& position)
{
  const std::size_t* corner = fc.corners.data() + fc.first[k];
  auto point = [&](std::size_t i) -> const Vec3& { return position[corner[i]]; };
  Vec3 area, reference;
  polygon_area_and_reference(fc.corner_count(k), point, point, area, reference);
  return turns_left_at_every_corner(fc.corner_count(k), point, area);
}

/// The corner quality of face k (see `polygon_corner_quality()`).
inline double corner_quality(const Face_corners& fc, std::size_t k, const std::vector<Vec3>& position,
                             const std::vector<Vec3>& normal, double cap, double& capped_sum,
                             bool own_area_only = false)
{
  const std::size_t* corner = fc.corners.data() + fc.first[k];
  return polygon_corner_quality(
      fc.corner_count(k), [&](std::size_t i) -> const Vec3& { return position[corner[i]]; },
      [&](std::size_t i) -> const Vec3& { return normal[corner[i]]; }, cap, capped_sum, own_area_only);
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_FACE_CORNERS_H
