// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGENT_PLANE_RELAXER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGENT_PLANE_RELAXER_H

// The body of `relax_on_tangent_planes()`: per iteration, smooth (the average of the
// neighbours), project (back onto the vertex's tangent planes, or along the border),
// and take back the moves that fold a face.

#include <CGAL/Range_space_remeshing/Remeshing_stage.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Face_corners.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_kernel.h>
#include <CGAL/Range_space_remeshing/internal/Pooled_tangent_planes_map.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Quad_untangler.h>
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
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Takes back the moves of an iteration that make a face's shape worse (a fine face
/// non-convex or folded, a non-convex one folded): the average of the neighbours can
/// pull a vertex across a concave crease or corner, where the planes it is projected
/// on do not hold it, and the face then spans the notch. The corners of such faces go
/// back; the faces around them are checked again, until none is left (each round puts
/// back at least one vertex). Faces folded or non-convex before may stay so or improve.
/// One shape test per face and position per iteration, and more only around the few
/// vertices put back.
inline void keep_faces_unfolded(const Face_corners& fc, const std::vector<Vec3>& position,
                                const std::vector<Vec3>& normal, std::vector<Vec3>& next_position)
{
  // refused: a worse shape (a fold also where the face was non-convex before), or a
  // face convex in itself made a dart (a folded face may be either)
  auto made_worse = [&](std::size_t k) {
    return shape_of(fc, k, next_position, normal) > shape_of(fc, k, position, normal) ||
           (!is_convex_in_itself(fc, k, next_position) && is_convex_in_itself(fc, k, position));
  };
  std::vector<std::size_t> found, again;
  for(std::size_t k = 0; k < fc.size(); ++k)
    if(made_worse(k))
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
      if(made_worse(k))
        found.push_back(k);
  }
}

/// Relaxes the vertices of a mesh over the surface they sample (see
/// `relax_on_tangent_planes()`): `run()` prepares the border, the projections and the
/// neighbours, then per iteration smooths and projects each vertex.
template <class PolygonMesh, class NamedParameters>
class Tangent_plane_relaxer
{
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  template <class Tag>
  static constexpr bool given = !CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value;
  static constexpr bool has_normals = given<CGAL::internal_np::vertex_normal_map_t>;
  static constexpr bool has_planes = given<internal_np::vertex_tangent_planes_map_t>;
  template <class Tag, class Default>
  using Chosen = std::decay_t<decltype(CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(std::declval<const NamedParameters&>(), Tag()), std::declval<const Default&>()))>;
  using VPM = typename GetVertexPointMap<PolygonMesh, NamedParameters>::type;
  using Point = typename boost::property_traits<VPM>::value_type;
  using Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3;
  using Normal_map = Chosen<CGAL::internal_np::vertex_normal_map_t, CGAL::Constant_property_map<vertex_descriptor, Vector>>;
  using Vertex_index = decltype(CGAL::get_initialized_vertex_index_map(std::declval<PolygonMesh&>(),
                                                                       std::declval<const NamedParameters&>()));
  using Own_planes_map =
      decltype(boost::make_iterator_property_map(std::declval<std::vector<Tangent_planes>::iterator>(),
                                                 std::declval<Vertex_index>()));
  using Planes_map = Chosen<internal_np::vertex_tangent_planes_map_t, Own_planes_map>;

  static std::vector<Tangent_planes> own_planes(const PolygonMesh& mesh, VPM vpm, Vertex_index vertex_index)
  {
    if constexpr(!has_planes)
      return planes_of_incident_faces(mesh, vpm, vertex_index);
    else {
      (void)mesh, (void)vpm, (void)vertex_index;
      return {};
    }
  }

public:
  Tangent_plane_relaxer(PolygonMesh& mesh, const NamedParameters& np, const Progress& progress)
    : mesh_(mesh), progress_(progress),
      vpm_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                              get_property_map(CGAL::vertex_point, mesh))),
      normal_map_(CGAL::parameters::choose_parameter(
          CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_normal_map),
          CGAL::Constant_property_map<vertex_descriptor, Vector>(CGAL::NULL_VECTOR))),
      vertex_index_(CGAL::get_initialized_vertex_index_map(mesh, np)),
      own_planes_(own_planes(mesh, vpm_, vertex_index_)),
      tangent_planes_(CGAL::parameters::choose_parameter(
          CGAL::parameters::get_parameter(np, internal_np::vertex_tangent_planes_map),
          boost::make_iterator_property_map(own_planes_.begin(), vertex_index_))),
      n_(index_bound(vertices(mesh), vertex_index_))
  {}

  void run(int iterations)
  {
    read_vertices();
    find_border();
    prepare_projections();
    const Face_corners face_corners(mesh_, vertex_index_, n_);
    collect_neighbours();
    for(int iteration = 0; iteration < iterations; ++iteration) {
      for(std::size_t k = 0; k < vertex_order_.size(); ++k) {
        // the mesh is written after the last step: a cancellation leaves it unchanged
        progress_.report_every(Remeshing_stage::RELAXATION, std::size_t(iteration) * vertex_order_.size() + k,
                               std::size_t(iterations) * vertex_order_.size());
        relax_vertex(k);
      }
      keep_faces_unfolded(face_corners, position_, normal_, next_position_);
      position_.swap(next_position_);
      normal_.swap(next_normal_);
    }
    write_back();
  }

  /// The squaring (see `square_quads()`): `iterations` steps, each moving every vertex
  /// inside the surface whose faces are all quads towards where it would make them
  /// squares at its corner (`square_target()`), along the surface. The moves that
  /// make a face's shape worse are taken back, as in `run()`.
  void square_up(int iterations)
  {
    read_vertices();
    find_border();
    prepare_projections();
    const Face_corners face_corners(mesh_, vertex_index_, n_);
    std::vector<Vec3> areas(face_corners.size());
    for(int iteration = 0; iteration < iterations; ++iteration) {
      // each face's vector area, which every corner's move reads
      for(std::size_t f = 0; f < face_corners.size(); ++f)
        areas[f] = vector_area(face_corners, f);
      std::size_t k = 0;
      for(vertex_descriptor v : vertices(mesh_)) {
        progress_.report_every(Remeshing_stage::RELAXATION, std::size_t(iteration) * n_ + k++,
                               std::size_t(iterations) * n_);
        const std::size_t i = index(v);
        next_position_[i] = squared_position(i, face_corners, areas);
      }
      keep_faces_unfolded(face_corners, position_, normal_, next_position_);
      position_.swap(next_position_);
    }
    write_back();
  }

  /// The untangling (see Quad_untangler.h): moves the vertices of the faces that are
  /// folded or non-convex, and where needed those around them, on their tangent planes
  /// (border vertices along their border). The projections are made only for the
  /// vertices it tries to move, the mesh is written only if some face is tangled.
  /// `tried_before`: the vertices tried by earlier runs of the same stage, which count
  /// against its `budget` of tries (see `untangle_tries_per_vertex`).
  /// `start_at` (vertex -> bool): the tangled faces it works on are those not convex in
  /// themselves (seen from their own vector area, folded or not) and those with a corner
  /// where it is true; the counts are of all. With `off_surface`, a vertex may also
  /// leave its tangent planes along its normal by `off_surface_reach` of the mean
  /// length of its edges (border vertices stay on the border; vertices its planes hold
  /// on a crease line or a point may leave it so).
  template <class StartAtMap = CGAL::Constant_property_map<vertex_descriptor, bool>>
  Untangle_statistics untangle(std::size_t tried_before, std::size_t budget, StartAtMap start_at = StartAtMap(true),
                               bool off_surface = false)
  {
    const auto start = std::chrono::steady_clock::now();
    Untangle_statistics stats;
    stats.tries = tried_before;
    read_vertices();
    const Face_corners face_corners(mesh_, vertex_index_, n_);
    auto place = [this](std::size_t i, const Vec3& p) { return placed(i, p); };
    Quad_untangler<decltype(place)> untangler(face_corners, position_, normal_, place);
    std::vector<std::size_t> tangled = untangler.tangled_faces();
    const Face_shape_counts before = untangler.count(tangled);
    stats.folded_before = stats.folded_after = before.folded;
    stats.non_convex_before = stats.non_convex_after = before.non_convex;
    if(!tangled.empty()) {
      vertex_of_index();
      keep_starting_faces(untangler, face_corners, start_at, tangled);
    }
    if(!tangled.empty()) {
      find_border();
      start_projections();
      if(off_surface) {
        find_off_surface_reach();
        untangler.allow_off_surface(off_surface_reach_);
      }
      untangler.run(tangled, stats.moves, stats.rounds, stats.tries, budget, progress_);
      const Face_shape_counts after = untangler.count(untangler.tangled_faces());
      stats.folded_after = after.folded;
      stats.non_convex_after = after.non_convex;
      write_back();
    }
    stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats;
  }

private:
  std::size_t index(vertex_descriptor v) const { return get(vertex_index_, v); }

  // Keeps the faces not convex in themselves or with a corner where `start_at` is true.
  template <class Untangler, class StartAtMap>
  void keep_starting_faces(const Untangler& untangler, const Face_corners& face_corners, StartAtMap start_at,
                           std::vector<std::size_t>& faces) const
  {
    auto starts = [&](std::size_t k) { // the look-ups first: the polygon test costs more
      for(std::size_t c = face_corners.first[k]; c < face_corners.first[k + 1]; ++c)
        if(get(start_at, vertex_of_[face_corners.corners[c]]))
          return true;
      return !untangler.is_convex_in_itself(k);
    };
    faces.erase(std::remove_if(faces.begin(), faces.end(), [&](std::size_t k) { return !starts(k); }), faces.end());
  }

  void vertex_of_index()
  {
    vertex_of_.resize(n_);
    prepared_.assign(n_, 0);
    for(vertex_descriptor v : vertices(mesh_))
      vertex_of_[index(v)] = v;
  }

  // where the untangling puts vertex i sent towards p: as a relaxation step would (on
  // its tangent planes, along its border), the projection made on first use
  Vec3 placed(std::size_t i, const Vec3& p)
  {
    const vertex_descriptor v = vertex_of_[i];
    if(on_border_[i])
      return slide_along_border(i, p, get(tangent_planes_, v));
    if(!prepared_[i]) {
      prepare_projection(v, scratch_);
      prepared_[i] = 1;
    }
    if(on_face_without_area_[i] || projection_[i].constrained_directions() == 0)
      return position_[i];
    const Vec3 on_planes = project(i, p);
    if(off_surface_reach_.empty())
      return on_planes;
    const double reach = off_surface_reach_[i];
    const double off = (std::min)(reach, (std::max)(-reach, dot(difference(p, on_planes), normal_[i])));
    return {{on_planes[0] + off * normal_[i][0], on_planes[1] + off * normal_[i][1], on_planes[2] + off * normal_[i][2]}};
  }

  // how far the untangling off the surface may move each vertex from its planes
  void find_off_surface_reach()
  {
    off_surface_reach_.assign(n_, 0);
    for(vertex_descriptor v : vertices(mesh_)) {
      double lengths = 0;
      std::size_t edges = 0;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh_), mesh_)) {
        const Vec3 d = difference(position_[index(source(h, mesh_))], position_[index(v)]);
        lengths += std::sqrt(dot(d, d));
        ++edges;
      }
      if(edges > 0)
        off_surface_reach_[index(v)] = off_surface_reach * lengths / double(edges);
    }
  }

  void read_vertices()
  {
    position_.resize(n_);
    normal_.resize(n_);
    next_position_.resize(n_);
    next_normal_.resize(n_);
    for(vertex_descriptor v : vertices(mesh_)) {
      const std::size_t i = index(v);
      position_[i] = to_vec3(get(vpm_, v));
      if constexpr(has_normals)
        normal_[i] = normalized(to_vec3(get(normal_map_, v)));
      else
        normal_[i] = normalized(average_normal(get(tangent_planes_, v)));
    }
  }

  // A border vertex slides along the border it samples: the primal border edge between
  // its two tangent planes' points (from `dualize()`), or, for a mesh that came without
  // planes, its own two border edges as they were before the relaxation.
  // `on_border_`: 0 inside, 1 on the border, 2 on the border but staying.
  void find_border()
  {
    on_border_.assign(n_, 0);
    for(vertex_descriptor v : vertices(mesh_))
      on_border_[index(v)] = bool(is_border(v, mesh_));
    border_neighbours_.resize(n_);
    for(vertex_descriptor v : vertices(mesh_)) {
      if(!on_border_[index(v)])
        continue;
      std::size_t found = 0;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh_), mesh_))
        if(is_border(edge(h, mesh_), mesh_) && found < 2)
          border_neighbours_[index(v)][found++] = index(source(h, mesh_));
      if(found < 2) // not a manifold border vertex: it stays
        on_border_[index(v)] = 2;
    }
    original_ = position_;
    if constexpr(!has_planes)
      keep_border_corners();
  }

  // corners of the border, where it turns by more than 30 degrees, stay
  void keep_border_corners()
  {
    const double cos_30 = std::sqrt(3.) / 2;
    for(std::size_t i = 0; i < n_; ++i) {
      if(on_border_[i] != 1)
        continue;
      const Vec3 in = difference(original_[i], original_[border_neighbours_[i][0]]),
                 out = difference(original_[border_neighbours_[i][1]], original_[i]);
      const double lengths = std::sqrt(dot(in, in) * dot(out, out));
      if(!(dot(in, out) >= cos_30 * lengths))
        on_border_[i] = 2;
    }
  }

  Vec3 slide_along_border(std::size_t i, const Vec3& p, const Tangent_planes& planes) const
  {
    if(on_border_[i] != 1)
      return position_[i];
    if constexpr(has_planes) {
      if(planes.size() != 2)
        return position_[i];
      return closest_on_segment(p, planes[0].first, planes[1].first);
    } else {
      (void)planes;
      const Vec3 x = closest_on_segment(p, original_[border_neighbours_[i][0]], original_[i]);
      const Vec3 y = closest_on_segment(p, original_[i], original_[border_neighbours_[i][1]]);
      const Vec3 dx = difference(x, p), dy = difference(y, p);
      return dot(dx, dx) <= dot(dy, dy) ? x : y;
    }
  }

  // Each vertex's quadric, decomposed once: the projection that undoes the shrinking.
  // A vertex placed on a primal face that encloses nothing, on an opened crease, stays there.
  // What each iteration fits a vertex to, made once: its planes with unit normals
  // (flat, by vertex index) and the box of their points (all of space if none), which
  // the averaged position is clamped to: a vertex relaxed on tangent planes stays over
  // the piece of surface they sample (past a crease, say, they no longer describe it).
  void prepare_projections()
  {
    start_projections();
    std::vector<Vec3> scratch;
    std::size_t prepared = 0;
    for(vertex_descriptor v : vertices(mesh_)) {
      progress_.report_at_every(Remeshing_stage::RELAXATION, prepared++, 0.0); // the steps not begun
      prepare_projection(v, scratch);
    }
  }

  void start_projections()
  {
    projection_.resize(n_);
    on_face_without_area_.assign(n_, 0);
    first_unit_plane_.assign(n_, 0);
    end_unit_plane_.assign(n_, 0);
    const double unbounded = std::numeric_limits<double>::infinity();
    planes_box_.assign(n_, {{{-unbounded, -unbounded, -unbounded}}, {{unbounded, unbounded, unbounded}}});
  }

  void prepare_projection(vertex_descriptor v, std::vector<Vec3>& scratch)
  {
    const std::size_t i = index(v);
    if(on_border_[i])
      return;
    const auto& planes = get(tangent_planes_, v);
    on_face_without_area_[i] = planes_of_face_without_area(planes, scratch);
    if(on_face_without_area_[i])
      return; // it stays: no projection needed
    Quadric quadric;
    quadric.add_planes(planes);
    projection_[i] = Quadric_projection(decomposition_of(tangent_planes_, v, quadric), quadric_truncation);
    first_unit_plane_[i] = unit_planes_.size();
    for(const auto& plane : planes)
      unit_planes_.emplace_back(plane.first, normalized(plane.second));
    end_unit_plane_[i] = unit_planes_.size();
    if(!planes.empty())
      planes_box_[i] = points_box(planes);
  }

  // The neighbours each vertex is averaged with, by index, in flat arrays walked at
  // every iteration. A border vertex moves along the border only: its border neighbours.
  void collect_neighbours()
  {
    first_neighbour_.assign(1, 0);
    for(vertex_descriptor v : vertices(mesh_)) {
      const std::size_t i = index(v);
      vertex_order_.push_back(v);
      for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh_), mesh_))
        if(!on_border_[i] || is_border(edge(h, mesh_), mesh_))
          neighbours_.push_back(index(source(h, mesh_)));
      first_neighbour_.push_back(neighbours_.size());
    }
  }

  // smooth: the average position p and unit normal m of the neighbours of vertex k
  void smooth(std::size_t k, Vec3& p, Vec3& m) const
  {
    p = {{0, 0, 0}};
    m = {{0, 0, 0}};
    for(std::size_t c = first_neighbour_[k]; c < first_neighbour_[k + 1]; ++c) {
      const std::size_t j = neighbours_[c];
      for(int d = 0; d < 3; ++d) {
        p[d] += position_[j][d];
        m[d] += normal_[j][d];
      }
    }
    const double count = double(first_neighbour_[k + 1] - first_neighbour_[k]);
    for(int d = 0; d < 3; ++d)
      p[d] /= count;
    m = normalized(m);
  }

  // twice the vector area of face k at the current positions
  Vec3 vector_area(const Face_corners& fc, std::size_t k) const
  {
    const std::size_t* corner = fc.corners.data() + fc.first[k];
    Vec3 area, reference;
    polygon_area_and_reference(
        fc.corner_count(k), [&](std::size_t c) -> const Vec3& { return position_[corner[c]]; },
        [&](std::size_t c) -> const Vec3& { return normal_[corner[c]]; }, area, reference);
    return area;
  }

  // Where vertex i would make each of its quads a square at its corner: the apex of the
  // right isosceles triangle whose hypotenuse joins its two neighbours in the quad, on
  // the side the quad turns (n: the unit sum of the quads' vector areas), averaged
  // over its quads. The mean of the neighbours keeps a sheared grid sheared (each
  // vertex of an affine image of a regular grid is already the mean of its
  // neighbours); squares are what this one converges to. False where a face of i is
  // not a quad or the faces have no area.
  // `areas`: each face's vector area (`vector_area()`).
  bool square_target(std::size_t i, const Face_corners& fc, const std::vector<Vec3>& areas, Vec3& target,
                     Vec3& n) const
  {
    const std::size_t* incident = fc.incident_faces.data();
    const std::size_t begin = fc.first_face[i], end = fc.first_face[i + 1];
    n = {{0, 0, 0}};
    for(std::size_t f = begin; f < end; ++f) {
      const std::size_t k = incident[f];
      if(fc.corner_count(k) != 4)
        return false;
      n = {{n[0] + areas[k][0], n[1] + areas[k][1], n[2] + areas[k][2]}};
    }
    n = normalized(n);
    if(begin == end || n == Vec3{{0, 0, 0}})
      return false;
    target = {{0, 0, 0}};
    for(std::size_t f = begin; f < end; ++f) {
      const std::size_t* corner = fc.corners.data() + fc.first[incident[f]];
      const std::size_t at = std::size_t(std::find(corner, corner + 4, i) - corner);
      const Vec3& a = position_[corner[next_corner(at, 4)]];
      const Vec3& b = position_[corner[previous_corner(at, 4)]];
      const Vec3 half = {{(a[0] - b[0]) / 2, (a[1] - b[1]) / 2, (a[2] - b[2]) / 2}};
      const Vec3 out = cross(n, half); // from the hypotenuse's middle away from the corner
      for(int d = 0; d < 3; ++d)
        target[d] += (a[d] + b[d]) / 2 - out[d];
    }
    const double count = double(end - begin);
    target = {{target[0] / count, target[1] / count, target[2] / count}};
    return true;
  }

  // Vertex i moved to its square target in the plane of its quads (whose normal the
  // move keeps): a move along the surface, a second-order step off it. Not onto its
  // tangent planes: where they bend (held on a line or a point by them, a third of
  // the vertices of a coarse remesh of a limb) they would pin it, and the squares
  // would not form. Vertices its planes do not place (on a face without area) and
  // border vertices stay.
  Vec3 squared_position(std::size_t i, const Face_corners& fc, const std::vector<Vec3>& areas) const
  {
    Vec3 target, n;
    if(on_border_[i] || on_face_without_area_[i] || projection_[i].constrained_directions() == 0 ||
       !square_target(i, fc, areas, target, n))
      return position_[i];
    const Vec3 move = difference(target, position_[i]);
    const double across = dot(move, n);
    return {{position_[i][0] + move[0] - across * n[0], position_[i][1] + move[1] - across * n[1],
             position_[i][2] + move[2] - across * n[2]}};
  }

  // one step for vertex k: smooth, then project back (onto the border it samples, or
  // onto its tangent planes)
  void relax_vertex(std::size_t k)
  {
    const vertex_descriptor v = vertex_order_[k];
    const std::size_t i = index(v);
    Vec3 p, m;
    smooth(k, p, m);
    if(on_border_[i]) {
      next_position_[i] = slide_along_border(i, p, get(tangent_planes_, v));
      next_normal_[i] = m == Vec3{{0, 0, 0}} ? normal_[i] : m;
      return;
    }
    const bool stays = on_face_without_area_[i] && m != Vec3{{0, 0, 0}}; // its normal follows
    if(!stays && (projection_[i].constrained_directions() == 0 || m == Vec3{{0, 0, 0}})) { // nothing to project on
      next_position_[i] = position_[i];
      next_normal_[i] = normal_[i];
      return;
    }
    next_position_[i] = stays ? position_[i] : project(i, p);
    next_normal_[i] = m;
  }

  // project: the nearest minimiser of vertex i's planes to p, clamped to their box
  Vec3 project(std::size_t i, const Vec3& p) const
  {
    const auto planes =
        CGAL::make_range(unit_planes_.cbegin() + first_unit_plane_[i], unit_planes_.cbegin() + end_unit_plane_[i]);
    return projection_[i].fit_nearest_planes(clamped_to_box(p, planes_box_[i]), planes);
  }

  void write_back()
  {
    for(vertex_descriptor v : vertices(mesh_)) {
      const std::size_t i = index(v);
      put(vpm_, v, Point(position_[i][0], position_[i][1], position_[i][2]));
      if constexpr(has_normals)
        put(normal_map_, v, Vector(normal_[i][0], normal_[i][1], normal_[i][2]));
    }
  }

  PolygonMesh& mesh_;
  const Progress& progress_;
  VPM vpm_;
  Normal_map normal_map_;
  Vertex_index vertex_index_;
  std::vector<Tangent_planes> own_planes_; // the planes of the incident faces, without a map
  Planes_map tangent_planes_;
  std::size_t n_;

  std::vector<Vec3> position_, normal_, next_position_, next_normal_, original_; // by vertex index
  std::vector<std::uint8_t> on_border_;
  std::vector<std::array<std::size_t, 2>> border_neighbours_;
  std::vector<Quadric_projection> projection_;
  std::vector<std::uint8_t> on_face_without_area_;
  std::vector<std::pair<Vec3, Vec3>> unit_planes_;
  std::vector<std::size_t> first_unit_plane_, end_unit_plane_;
  std::vector<std::pair<Vec3, Vec3>> planes_box_;
  std::vector<vertex_descriptor> vertex_order_;
  std::vector<std::size_t> first_neighbour_, neighbours_;
  std::vector<vertex_descriptor> vertex_of_; // by index, for the untangling
  std::vector<std::uint8_t> prepared_;
  std::vector<Vec3> scratch_;
  std::vector<double> off_surface_reach_; // by vertex index; empty: on the planes
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_TANGENT_PLANE_RELAXER_H
