// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_RELAX_ON_TANGENT_PLANES_H
#define CGAL_RANGE_SPACE_REMESHING_RELAX_ON_TANGENT_PLANES_H

#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_kernel.h>
#include <CGAL/Range_space_remeshing/internal/Pooled_tangent_planes_map.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>

#include <CGAL/Iterator_range.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
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
};

/// Whether face k, at these positions, faces against the normals of its corners
/// (the sum of their unit normals): folded over its neighbours.
inline bool is_folded(const Face_corners& fc, std::size_t k, const std::vector<Vec3>& position,
                      const std::vector<Vec3>& normal)
{
  Vec3 area = {{0, 0, 0}}, reference = {{0, 0, 0}};
  const std::size_t begin = fc.first[k], end = fc.first[k + 1];
  const Vec3& origin = position[fc.corners[begin]]; // not (0, 0, 0): no cancellation far from it
  for(std::size_t c = begin; c < end; ++c) {
    const Vec3 a = difference(position[fc.corners[c]], origin);
    const Vec3 b = difference(position[fc.corners[c + 1 < end ? c + 1 : begin]], origin);
    const Vec3 ab = cross(a, b);
    const Vec3& n = normal[fc.corners[c]];
    for(int d = 0; d < 3; ++d) {
      area[d] += ab[d];
      reference[d] += n[d];
    }
  }
  return dot(area, reference) < 0;
}

/// Whether face k, at these positions, is folded (as `is_folded()`) or has a corner
/// that turns against its vector-area normal: (e_next x e_prev) . area <= 0, the
/// criterion of the benchmark's quality measure (no threshold: the sign only).
inline bool is_folded_or_non_convex(const Face_corners& fc, std::size_t k, const std::vector<Vec3>& position,
                                    const std::vector<Vec3>& normal)
{
  if(is_folded(fc, k, position, normal))
    return true;
  Vec3 area = {{0, 0, 0}};
  const std::size_t begin = fc.first[k], end = fc.first[k + 1];
  const Vec3& origin = position[fc.corners[begin]];
  for(std::size_t c = begin; c < end; ++c) {
    const Vec3 ab = cross(difference(position[fc.corners[c]], origin),
                          difference(position[fc.corners[c + 1 < end ? c + 1 : begin]], origin));
    for(int d = 0; d < 3; ++d)
      area[d] += ab[d];
  }
  for(std::size_t c = begin; c < end; ++c) {
    const Vec3& p = position[fc.corners[c]];
    const Vec3 next = difference(position[fc.corners[c + 1 < end ? c + 1 : begin]], p);
    const Vec3 prev = difference(position[fc.corners[c > begin ? c - 1 : end - 1]], p);
    if(!(dot(cross(next, prev), area) > 0))
      return true;
  }
  return false;
}

/// Takes back the moves of an iteration that fold a face that was not folded: the
/// average of the neighbours can pull a vertex across a concave crease or corner,
/// where the planes it is projected on do not hold it, and the face then spans the
/// notch. The corners of such faces go back; the faces around them are checked again,
/// until none is left (each round puts back at least one vertex). Faces folded before
/// may stay folded or unfold. One test per face and iteration, and more only around
/// the few vertices put back.
inline void keep_faces_unfolded(const Face_corners& fc, const std::vector<Vec3>& position,
                                const std::vector<Vec3>& normal, std::vector<Vec3>& next_position)
{
  auto newly_folded = [&](std::size_t k) {
    // a fold is refused even where the face was non-convex before
    return (is_folded(fc, k, next_position, normal) && !is_folded(fc, k, position, normal)) ||
           (is_folded_or_non_convex(fc, k, next_position, normal) && !is_folded_or_non_convex(fc, k, position, normal));
  };
  std::vector<std::size_t> found, again;
  for(std::size_t k = 0; k < fc.size(); ++k)
    if(newly_folded(k))
      found.push_back(k);
  while(!found.empty()) {
    again.clear();
    for(std::size_t k : found)
      for(std::size_t c = fc.first[k]; c < fc.first[k + 1]; ++c) {
        const std::size_t i = fc.corners[c];
        if(next_position[i] == position[i])
          continue;
        next_position[i] = position[i];
        again.insert(again.end(), fc.incident_faces.begin() + fc.first_face[i],
                     fc.incident_faces.begin() + fc.first_face[i + 1]);
      }
    std::sort(again.begin(), again.end());
    again.erase(std::unique(again.begin(), again.end()), again.end());
    found.clear();
    for(std::size_t k : again)
      if(newly_folded(k))
        found.push_back(k);
  }
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingRef

relaxes the vertices of `mesh` over the surface they sample (section 6 of the paper).
Each of the `number_of_relaxation_steps` steps (a) replaces every vertex's position
and normal by the average of its neighbours' (the normal renormalised), which spreads
the vertices evenly but shrinks and smooths, then (b) moves it back to the nearest
minimiser of the squared distances to its tangent planes, along the directions those
planes constrain and no other (directions whose eigenvalue in the planes' quadric is
below a tenth of the largest are free). The planes are weighted by how close their
points are to the averaged position (inverse square of the squared distance, softened,
and at least a tenth of the largest weight): a tangent plane strays from a curved
surface with the square of the distance to its point, so where the vertex has slid
towards one side of its planes, those on that side say where the surface is. Weighted
alike, they left the relaxed vertices off the surface (RMS distance to the input 3.6e-4
instead of 2.6e-4 on refined_elephant, \f$\mathbb{R}^6\f$, 11k quads; worse than
before the relaxation). This undoes the shrinking: in a smooth region
the vertex moves along the normal only, as the paper's projection on the line
\f$v' + \lambda n'\f$ does, and slides freely on the surface; on a crease, where the
planes of both sides meet, it goes back onto the crease line, and at a corner onto the
corner, which the paper's single line could not reach.

A vertex whose tangent planes' points, in order, are the corners of a polygon that
encloses nothing (a segment, or a tree of segments) stays where it is: `dualize()`
gives those to the dual vertex of a primal face inside the zero-area strips of
creases opened by `insert_crease_triangles()` (or where strips meet), and puts it on
the crease. Its planes (the two sides', or blends of
them where the primal had no crease normals) would let the average of its neighbours pull it along or off the
crease, across the notch of a concave corner, where the fold test below cannot see
it: on CGAL's fandisk with its creases opened (\f$\mathbb{R}^6\f$, the whole
pipeline, 4,000 to 16,000 quads) the largest distance to the input went down at
five sizes of six (at 16,000 quads from 3.6e-3 to 1.6e-3 bounding-box diagonals, at
8,000 from 6.6e-3 to 5.2e-3; up at 6,000, from 5.1e-3 to 5.5e-3), the RMS distance
at all six (by 5 % to 12 %).

No iteration folds a face that was not folded: where the moves would turn a face
against its corners' normals, its corners keep their places (and the faces around
them are checked again, until none is left). The average of the neighbours can
pull a vertex across a concave crease or a notch where creases meet, which its planes
do not hold it from; the face then spans the notch. On CGAL's fandisk with its
creases opened (`insert_crease_triangles()`, \f$\mathbb{R}^6\f$, the whole pipeline)
the largest distance from the output to the input went from 6.8e-3 to 2.6e-3
bounding-box diagonals at 8,000 quads, and down by 11 % to 20 % at 6,000, 10,000,
12,000 and 16,000 quads (unchanged at 4,000). On the smooth sample meshes the
results did not change beyond the noise of the measurement. The test costs about 5 %
of the relaxation's time, which walking flat arrays of neighbours instead of the
halfedges around each vertex won back.

Border vertices (paper, section 7) are averaged with their two border neighbours only,
and put back on the border they sample, so that it does not shrink: with
`vertex_tangent_planes_map`, on the segment between the points of their two tangent
planes (a dual border vertex from `dualize()` has those of the ends of the primal
border edge it lies on; a border vertex with another number of planes stays where it
is); without, on their own two border edges as they were before the relaxation, and
corners of the border (where it turns by more than 30 degrees) stay.

\param mesh a polygon mesh (any `FaceGraph`, e.g. the output of `dualize()`);
  positions (and normals if given) are updated, the connectivity is not.
\param np optional named parameters:
  \cgalNamedParamsBegin
    \cgalParamNBegin{number_of_relaxation_steps}
      \cgalParamDescription{the steps}
      \cgalParamType{int}
      \cgalParamDefault{3}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_tangent_planes_map}
      \cgalParamDescription{the planes each vertex is projected on (e.g. from `dualize()` and `collapse_quads()`)}
      \cgalParamType{a readable property map, vertex -> `Tangent_planes`}
      \cgalParamDefault{the planes of each vertex's incident faces, so that vertices of a mesh that came without planes stay on its faces, creases and corners}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{unit normals; updated}
      \cgalParamType{a read-write property map, vertex -> 3-D vector}
      \cgalParamDefault{the average normal of each vertex's tangent planes}
    \cgalParamNEnd
    \cgalParamNBegin{progress_visitor}
      \cgalParamDescription{told how far the steps are and asked whether to go on, as for `remesh()`; on cancellation the mesh is left unchanged}
      \cgalParamType{a callable `bool(Remeshing_stage, double)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{read-write}
      \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map}
      \cgalParamDefault{the mesh's, or one made for the run}
    \cgalParamNEnd
  \cgalNamedParamsEnd
\returns the time taken, in milliseconds.
\throws Remeshing_error of kind `BAD_PARAMETER` if `number_of_relaxation_steps` is
  negative or not whole.
*/
template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
double relax_on_tangent_planes(PolygonMesh& mesh, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using internal::Vec3;
  static_assert(internal::check_named_parameters<
                struct relax_on_tangent_planes_np, NamedParameters, internal_np::vertex_tangent_planes_map_t,
                CGAL::internal_np::number_of_relaxation_steps_t, CGAL::internal_np::vertex_point_t,
                CGAL::internal_np::vertex_normal_map_t, internal_np::progress_visitor_t,
                CGAL::internal_np::vertex_index_t>());

  const auto start = std::chrono::steady_clock::now();
  const internal::Progress progress = internal::progress_of(np);
  const int iterations = int(internal::count_parameter(np, CGAL::internal_np::number_of_relaxation_steps, 3,
                                                       "number_of_relaxation_steps"));
  using VPM = typename GetVertexPointMap<PolygonMesh, NamedParameters>::type;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, mesh));
  using Point = typename boost::property_traits<VPM>::value_type;
  using Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  constexpr bool has_normals =
      !is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value;
  auto normal_map = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_normal_map),
                                     CGAL::Constant_property_map<vertex_descriptor, Vector>(CGAL::NULL_VECTOR));
  auto vertex_index = CGAL::get_initialized_vertex_index_map(mesh, np);
  constexpr bool has_planes =
      !is_default_parameter<NamedParameters, internal_np::vertex_tangent_planes_map_t>::value;
  std::vector<Tangent_planes> own_planes;
  if constexpr(!has_planes)
    own_planes = internal::planes_of_incident_faces(mesh, vpm, vertex_index);
  const auto tangent_planes = choose_parameter(get_parameter(np, internal_np::vertex_tangent_planes_map),
                                               boost::make_iterator_property_map(own_planes.begin(), vertex_index));

  const std::size_t n = internal::index_bound(vertices(mesh), vertex_index);
  std::vector<Vec3> position(n), normal(n), next_position(n), next_normal(n);
  for(vertex_descriptor v : vertices(mesh)) {
    const std::size_t i = get(vertex_index, v);
    position[i] = internal::to_vec3(get(vpm, v));
    if constexpr(has_normals)
      normal[i] = internal::normalized(internal::to_vec3(get(normal_map, v)));
    else
      normal[i] = internal::normalized(internal::average_normal(get(tangent_planes, v)));
  }

  std::vector<std::uint8_t> on_border(n, 0);
  for(vertex_descriptor v : vertices(mesh))
    on_border[get(vertex_index, v)] = bool(is_border(v, mesh));

  // A border vertex slides along the border it samples: the primal border edge between
  // its two tangent planes' points (from `dualize()`), or, for a mesh that came without
  // planes, its own two border edges as they were before the relaxation.
  std::vector<std::array<std::size_t, 2>> border_neighbours(n);
  for(vertex_descriptor v : vertices(mesh)) {
    if(!on_border[get(vertex_index, v)])
      continue;
    std::size_t found = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
      if(is_border(edge(h, mesh), mesh) && found < 2)
        border_neighbours[get(vertex_index, v)][found++] = get(vertex_index, source(h, mesh));
    if(found < 2) // not a manifold border vertex: it stays
      on_border[get(vertex_index, v)] = 2;
  }
  const std::vector<Vec3> original = position;
  if constexpr(!has_planes) { // corners of the border, where it turns by more than 30 degrees, stay
    const double cos_30 = std::sqrt(3.) / 2;
    for(std::size_t i = 0; i < n; ++i) {
      if(on_border[i] != 1)
        continue;
      const Vec3 in = internal::difference(original[i], original[border_neighbours[i][0]]),
                 out = internal::difference(original[border_neighbours[i][1]], original[i]);
      const double lengths = std::sqrt(internal::dot(in, in) * internal::dot(out, out));
      if(!(internal::dot(in, out) >= cos_30 * lengths))
        on_border[i] = 2;
    }
  }
  auto slide_along_border = [&](std::size_t i, const Vec3& p, const Tangent_planes& planes) -> Vec3 {
    if(on_border[i] != 1)
      return position[i];
    if constexpr(has_planes) {
      if(planes.size() != 2)
        return position[i];
      return internal::closest_on_segment(p, planes[0].first, planes[1].first);
    } else {
      (void)planes;
      const Vec3 x = internal::closest_on_segment(p, original[border_neighbours[i][0]], original[i]);
      const Vec3 y = internal::closest_on_segment(p, original[i], original[border_neighbours[i][1]]);
      const Vec3 dx = internal::difference(x, p), dy = internal::difference(y, p);
      return internal::dot(dx, dx) <= internal::dot(dy, dy) ? x : y;
    }
  };

  // Each vertex's quadric, decomposed once: the projection that undoes the shrinking.
  // A vertex placed on a primal face that encloses nothing, on an opened crease, stays there.
  std::vector<internal::Quadric_projection> projection(n);
  std::vector<std::uint8_t> on_face_without_area(n, 0);
  std::vector<Vec3> scratch;
  // What each iteration fits a vertex to, made once: its planes with unit normals
  // (flat, by vertex index) and the box of their points (all of space if none), which
  // the averaged position is clamped to: a vertex relaxed on tangent planes stays over
  // the piece of surface they sample (past a crease, say, they no longer describe it).
  std::vector<std::pair<Vec3, Vec3>> unit_planes;
  std::vector<std::size_t> first_unit_plane(n, 0), end_unit_plane(n, 0);
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<std::pair<Vec3, Vec3>> planes_box(n, {{{-infinity, -infinity, -infinity}}, {{infinity, infinity, infinity}}});
  std::size_t prepared = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    progress.report_at_every(Remeshing_stage::RELAXATION, prepared++, 0.0); // the steps not begun
    const std::size_t i = get(vertex_index, v);
    if(on_border[i])
      continue;
    const auto& planes = get(tangent_planes, v);
    on_face_without_area[i] = internal::planes_of_face_without_area(planes, scratch);
    if(on_face_without_area[i])
      continue; // it stays: no projection needed
    internal::Quadric quadric;
    quadric.add_planes(planes);
    projection[i] =
        internal::Quadric_projection(internal::decomposition_of(tangent_planes, v, quadric), internal::quadric_truncation);
    first_unit_plane[i] = unit_planes.size();
    for(const auto& plane : planes)
      unit_planes.emplace_back(plane.first, internal::normalized(plane.second));
    end_unit_plane[i] = unit_planes.size();
    if(!planes.empty())
      planes_box[i] = internal::points_box(planes);
  }
  const internal::Face_corners face_corners(mesh, vertex_index, n);
  // The neighbours each vertex is averaged with, by index, in flat arrays walked at
  // every iteration (a walk of the halfedges around each vertex was a third of the
  // relaxation's time). A border vertex moves along the border only: its border
  // neighbours.
  std::vector<vertex_descriptor> vertex_order;
  std::vector<std::size_t> first_neighbour(1, 0), neighbours;
  for(vertex_descriptor v : vertices(mesh)) {
    const std::size_t i = get(vertex_index, v);
    vertex_order.push_back(v);
    for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
      if(!on_border[i] || is_border(edge(h, mesh), mesh))
        neighbours.push_back(get(vertex_index, source(h, mesh)));
    first_neighbour.push_back(neighbours.size());
  }
  for(int iteration = 0; iteration < iterations; ++iteration) {
    for(std::size_t k = 0; k < vertex_order.size(); ++k) {
      // the mesh is written after the last step: a cancellation leaves it unchanged
      progress.report_every(Remeshing_stage::RELAXATION, std::size_t(iteration) * vertex_order.size() + k,
                            std::size_t(iterations) * vertex_order.size());
      const vertex_descriptor v = vertex_order[k];
      const std::size_t i = get(vertex_index, v);
      Vec3 p = {{0, 0, 0}}, m = {{0, 0, 0}};
      for(std::size_t c = first_neighbour[k]; c < first_neighbour[k + 1]; ++c) {
        const std::size_t j = neighbours[c];
        for(int d = 0; d < 3; ++d) {
          p[d] += position[j][d];
          m[d] += normal[j][d];
        }
      }
      const double count = double(first_neighbour[k + 1] - first_neighbour[k]);
      for(int d = 0; d < 3; ++d)
        p[d] /= count;
      m = internal::normalized(m);
      if(on_border[i]) {
        next_position[i] = slide_along_border(i, p, get(tangent_planes, v));
        next_normal[i] = m == Vec3{{0, 0, 0}} ? normal[i] : m;
        continue;
      }
      const bool stays = on_face_without_area[i] && m != Vec3{{0, 0, 0}}; // its normal follows
      if(!stays && (projection[i].constrained_directions() == 0 || m == Vec3{{0, 0, 0}})) { // nothing to project on
        next_position[i] = position[i];
        next_normal[i] = normal[i];
        continue;
      }
      const auto planes = CGAL::make_range(unit_planes.cbegin() + first_unit_plane[i],
                                           unit_planes.cbegin() + end_unit_plane[i]);
      next_position[i] =
          stays ? position[i] : projection[i].fit_nearest_planes(internal::clamped_to_box(p, planes_box[i]), planes);
      next_normal[i] = m;
    }
    keep_faces_unfolded(face_corners, position, normal, next_position);
    position.swap(next_position);
    normal.swap(next_normal);
  }

  for(vertex_descriptor v : vertices(mesh)) {
    const std::size_t i = get(vertex_index, v);
    put(vpm, v, Point(position[i][0], position[i][1], position[i][2]));
    if constexpr(has_normals)
      put(normal_map, v, Vector(normal[i][0], normal[i][1], normal[i][2]));
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_RELAX_ON_TANGENT_PLANES_H
