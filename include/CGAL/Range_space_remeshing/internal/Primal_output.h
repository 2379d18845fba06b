// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_OUTPUT_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_OUTPUT_H

// Writes the primal complex into a MutableFaceGraph halfedge by halfedge, so that
// no vertex-pair lookup is needed (and parallel edges, which the complex may
// legitimately have, are kept apart). Vertex geometry is sampled from the input
// triangle at the crossing point.

#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Prefetch.h>
#include <CGAL/Range_space_remeshing/internal/Primal_complex.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_attributes.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/Range_space_remeshing/Lazy_vertex_normal_map.h>
#include <CGAL/Range_space_remeshing/internal/Lazily_zeroed_array.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Unit vertex normals of the input (area-weighted), computed on first use only, once
/// each, or all at once by `compute_all()` where most of them are needed.
template <class TriangleMesh, class VPM, class VertexIndexMap>
class Lazy_vertex_normals
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

public:
  Lazy_vertex_normals(const TriangleMesh& tm, VPM vpm, VertexIndexMap vertex_index)
    : tm_(tm), vpm_(vpm), normal_map_(tm, vpm), vertex_index_(vertex_index)
  {}

  std::array<double, 3> operator()(vertex_descriptor v)
  {
    const std::size_t id = get(vertex_index_, v);
    if(known_.empty()) // allocated on first use: no cost when normals are not asked for
      allocate();
    if(!known_[id]) {
      normals_[id] = get(normal_map_, v);
      known_[id] = 1;
    }
    return normals_[id];
  }

  /// Every vertex's normal, in one pass over the faces (`compute_vertex_normals()`):
  /// a star read on its own is scattered in memory, and on refined_elephant one costs
  /// as much as about 40 faces of the pass (200 ns against 5 ns, measured), so the
  /// pass pays as soon as a fortieth of the vertices are asked for.
  void compute_all()
  {
    allocate();
    compute_vertex_normals(tm_, boost::make_iterator_property_map(normals_.data(), vertex_index_),
                           Normal_weighting::AREA, vpm_);
    std::fill(known_.begin(), known_.end(), std::uint8_t(1));
  }

private:
  // lazily: a seeded run on a huge input asks for the normals of a few of its vertices
  // (see Lazily_zeroed_array.h); a normal is written before it is read (known_)
  void allocate()
  {
    normals_ = Uninitialised_array<std::array<double, 3>>(num_vertices(tm_));
    known_ = Zeroed_array<std::uint8_t>(num_vertices(tm_));
  }

  const TriangleMesh& tm_;
  VPM vpm_;
  Lazy_vertex_normal_map<TriangleMesh, VPM> normal_map_; // area-weighted: what the normal maps use
  Uninitialised_array<std::array<double, 3>> normals_;
  Zeroed_array<std::uint8_t> known_;
  VertexIndexMap vertex_index_;
};

/// The normals of the two sides of a crease at a point inside it; `other` is the null
/// vector where the point is on one side only.
struct Normals_at_point
{
  Vec3 own, other;
};

/// The normals at the point of barycentric coordinates `w` in a triangle. In a triangle
/// with two corners at the same point (one that `insert_crease_triangles()` puts along
/// a crease, or at a corner), corners at the same point are copies of one vertex on
/// different sides of the crease: a blend of their normals is the normal of no surface
/// there, and tangent planes built from it make a flat side next to a crease look
/// curved. Such a point takes the normal of the side with the larger weight, and the
/// other side's as `other` (a side: a copy and the corner elsewhere whose normal is
/// nearer its own; at a corner, where all three coincide, each copy is a side).
template <class PointArray>
Normals_at_point normals_on_sides(const PointArray& points, const std::array<Vec3, 3>& normals,
                                  const std::array<double, 3>& w)
{
  auto blend = [&](std::initializer_list<int> corners) {
    Vec3 n = {{0, 0, 0}};
    for(int c : corners)
      for(int d = 0; d < 3; ++d)
        n[d] += w[c] * normals[c][d];
    return n;
  };
  const bool same01 = points[0] == points[1], same12 = points[1] == points[2], same02 = points[0] == points[2];
  if(!same01 && !same12 && !same02)
    return {blend({0, 1, 2}), {{0, 0, 0}}};
  if(same01 && same12) { // the two heaviest copies; of equal weights, the first
    int heaviest = 0;
    for(int c = 1; c < 3; ++c)
      heaviest = w[c] > w[heaviest] ? c : heaviest;
    int second = heaviest == 0 ? 1 : 0;
    for(int c = second + 1; c < 3; ++c)
      second = c != heaviest && w[c] > w[second] ? c : second;
    return {normals[heaviest], normals[second]};
  }
  const int lone = same01 ? 2 : (same12 ? 0 : 1);
  int partner = (lone + 1) % 3, other = (lone + 2) % 3;
  if(dot(normals[other], normals[lone]) > dot(normals[partner], normals[lone]))
    std::swap(partner, other);
  const Vec3 lone_side = normalized(blend({lone, partner}));
  if(w[lone] + w[partner] >= w[other])
    return {lone_side, normals[other]};
  return {normals[other], lone_side};
}

/// Output vertices ahead whose triangle's corners are asked for; the record that says
/// where the corners are is asked for twice as far ahead.
constexpr std::uint32_t output_lookahead = 8;

/// The vertices' triangles lie anywhere in the input: what output vertex v + k reads
/// is asked for ahead, its triangle's record first, then what the record points to
/// (and the given normals, with `normals`, and the attributes).
template <bool normals, class Tracer, class VPM, class NormalMap, class Attributes>
void prefetch_ahead_of(std::uint32_t v, const Tracer& tracer, const VPM& vpm, const NormalMap& given_normals,
                       const Attributes& attributes)
{
  const auto& vertices = tracer.intersection_vertices();
  if(v + 2 * output_lookahead < vertices.size())
    tracer.prefetch_record_of(vertices[v + 2 * output_lookahead]);
  if(v + output_lookahead < vertices.size())
    tracer.prefetch_corners_of(vertices[v + output_lookahead]);
  if(v + output_lookahead / 2 < vertices.size())
    for(auto corner : tracer.corners_of(vertices[v + output_lookahead / 2])) {
      prefetch_value(vpm, corner);
      if constexpr(normals)
        prefetch_value(given_normals, corner);
      if constexpr(!Attributes::empty)
        attributes.prefetch(corner);
    }
}

/// The edges and faces of the complex's kept part in `out`, between the output
/// vertices `vertex_of` (by intersection vertex); border halfedges last, so that a
/// boundary vertex's halfedge is its border one.
template <class PolygonMesh>
void write_primal_connectivity(const Primal_complex& complex,
                               const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vertex_of,
                               PolygonMesh& out, Statistics& stats,
                               std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& halfedge_of)
{
  using out_vertex = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using out_halfedge = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using out_face = typename boost::graph_traits<PolygonMesh>::face_descriptor;
  const std::uint32_t none = Primal_complex::none;
  const auto& halfedges = complex.halfedges();
  halfedge_of.assign(halfedges.size(), out_halfedge());
  std::vector<std::uint8_t> done(halfedges.size(), 0);
  std::size_t number_of_edges = 0;
  for(std::uint32_t h = 0; h < halfedges.size(); ++h) {
    if(done[h] || !complex.is_kept(halfedges[h].target))
      continue;
    const auto e = add_edge(out);
    halfedge_of[h] = halfedge(e, out);
    halfedge_of[halfedges[h].twin] = opposite(halfedge(e, out), out);
    done[h] = done[halfedges[h].twin] = 1;
    ++number_of_edges;
  }
  std::size_t number_of_faces = 0;
  for(std::uint32_t first : complex.face_halfedges()) {
    if(first == none)
      continue;
    const out_face f = add_face(out);
    set_halfedge(f, halfedge_of[first], out);
    std::uint32_t h = first;
    do {
      const out_halfedge oh = halfedge_of[h];
      const out_vertex t = vertex_of[halfedges[h].target];
      set_face(oh, f, out);
      set_target(oh, t, out);
      set_next(oh, halfedge_of[halfedges[h].next], out);
      set_halfedge(t, oh, out);
      h = halfedges[h].next;
    } while(h != first);
    ++number_of_faces;
  }
  for(std::uint32_t h = 0; h < halfedges.size(); ++h) {
    if(halfedges[h].face != none || !complex.is_kept(halfedges[h].target))
      continue;
    const out_halfedge oh = halfedge_of[h];
    const out_vertex t = vertex_of[halfedges[h].target];
    set_face(oh, boost::graph_traits<PolygonMesh>::null_face(), out);
    set_target(oh, t, out);
    set_next(oh, halfedge_of[halfedges[h].next], out);
    set_halfedge(t, oh, out);
  }
  stats.output_edges = number_of_edges;
  stats.output_faces = number_of_faces;
}

/// The point at barycentric coordinates `w` in the triangle of `corner_points`: where
/// the output vertex is placed (the crossing point, sampled on the input).
template <class Point, class Weights>
std::array<double, 3> barycentric_point(const std::array<Point, 3>& corner_points, const Weights& w)
{
  std::array<double, 3> p = {{0, 0, 0}};
  for(int c = 0; c < 3; ++c) {
    p[0] += w[c] * CGAL::to_double(corner_points[c].x());
    p[1] += w[c] * CGAL::to_double(corner_points[c].y());
    p[2] += w[c] * CGAL::to_double(corner_points[c].z());
  }
  return p;
}

/// The input's normals at `corners`: the caller's (`given`, from np_in) or those the
/// remesher computes (`input_normals`).
template <bool given, class Corners, class GivenNormals, class InputNormals>
std::array<Vec3, 3> normals_at_corners(const Corners& corners, const GivenNormals& given_normals,
                                       InputNormals& input_normals)
{
  std::array<Vec3, 3> normals;
  for(int c = 0; c < 3; ++c) {
    if constexpr(given)
      normals[c] = to_vec3(get(given_normals, corners[c]));
    else
      normals[c] = input_normals(corners[c]);
  }
  return normals;
}

/// Writes an output vertex's unit normal (zero-area corners: the zero vector) and the
/// normal of the crease's other side (the null vector off creases).
template <class Out_vector, class NormalMap, class CreaseNormalMap, class OutVertex>
void put_normals(NormalMap& normal_map, CreaseNormalMap& crease_normal_map, OutVertex ov,
                 const Normals_at_point& normals)
{
  const Vec3 unit = normalized(normals.own);
  put(normal_map, ov, Out_vector(unit[0], unit[1], unit[2]));
  put(crease_normal_map, ov, Out_vector(normals.other[0], normals.other[1], normals.other[2]));
}

/// Of the two halfedges of an edge of the complex, one that leaves an inner vertex
/// along its arc (so that a point of the arc can be found), or `none`.
inline std::uint32_t halfedge_along_an_arc(const Primal_complex& complex, std::uint32_t h)
{
  for(std::uint32_t g : {h, complex.halfedges()[h].twin}) {
    const std::uint32_t traced = complex.traced_halfedge(g);
    if(traced != Primal_complex::none && !complex.is_boundary(traced / 4))
      return g;
  }
  return Primal_complex::none;
}

/// Splits one edge of each pair of parallel edges of `out` (see `Primal_complex`) at a
/// point of its arc, near the vertex it leaves (`point_along_arc()`): the new vertex
/// lies on the surface, inside the cell of the faces beside the arc, so the faces
/// still lie in one cell each; it has valence 2. A face-list file then tells the two
/// edges apart. An edge with no arc to sample (a chord, a border edge) is left, and
/// stays counted in `Statistics::parallel_edges`.
template <class Tracer, class PolygonMesh, class Sample>
void split_parallel_edges(const Primal_complex& complex, Tracer& tracer, PolygonMesh& out,
                          const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& halfedge_of,
                          const Sample& sample, Statistics& stats)
{
  const auto& vertices = tracer.intersection_vertices();
  for(const std::uint32_t h : complex.parallel_halfedges()) {
    const std::uint32_t g = halfedge_along_an_arc(complex, h);
    if(g == Primal_complex::none)
      continue;
    const std::uint32_t traced = complex.traced_halfedge(g), v = traced / 4;
    const auto point = tracer.point_along_arc(vertices[v], int(traced % 4));
    // the new halfedge ends at the new vertex, on the side of g's source
    const auto to_new = CGAL::Euler::split_edge(halfedge_of[g], out);
    sample(target(to_new, out), point.face_id, point.w);
    ++stats.split_parallel_edges;
    --stats.parallel_edges;
    ++stats.output_vertices;
    ++stats.output_edges;
  }
}

/// Whether the output keeps the complex's parallel edges (`remesh()`'s primal, which
/// its dual undoes) or splits each at a point of its arc (`primal_remesh()`'s: then
/// `out` can be written to a face-list file).
enum class Parallel_edges { KEEP, SPLIT };

template <class TriangleMesh, class VPM, class VertexIndexMap, class Tracer, class PolygonMesh,
          class NamedParametersIn, class NamedParametersOut>
void write_primal_complex(const TriangleMesh& tm, VPM vpm, VertexIndexMap vertex_index, Tracer& tracer,
                          const Primal_complex& complex, PolygonMesh& out, const NamedParametersIn& np_in,
                          const NamedParametersOut& np_out, Statistics& stats, Parallel_edges parallel_edges)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using out_vertex = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;

  using Out_VPM = typename GetVertexPointMap<PolygonMesh, NamedParametersOut>::type;
  Out_VPM out_vpm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                     get_property_map(CGAL::vertex_point, out));
  using Out_point = typename boost::property_traits<Out_VPM>::value_type;
  using Out_kernel = typename CGAL::Kernel_traits<Out_point>::Kernel;
  using Out_vector = typename Out_kernel::Vector_3;

  constexpr bool wants_normals =
      !CGAL::parameters::is_default_parameter<NamedParametersOut,
                                              CGAL::internal_np::vertex_normal_map_t>::value;
  auto normal_map = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_normal_map),
                                     CGAL::Constant_property_map<out_vertex, Out_vector>(CGAL::NULL_VECTOR));
  constexpr bool wants_crease_normals =
      !is_default_parameter<NamedParametersOut, internal_np::vertex_crease_normal_map_t>::value;
  auto crease_normal_map = choose_parameter(get_parameter(np_out, internal_np::vertex_crease_normal_map),
                                            CGAL::Constant_property_map<out_vertex, Out_vector>(CGAL::NULL_VECTOR));
  constexpr bool needs_corner_normals = wants_normals || wants_crease_normals;
  Lazy_vertex_normals<TriangleMesh, VPM, VertexIndexMap> input_normals(tm, vpm, vertex_index);
  // the caller's input normals, if given (np_in): interpolated instead of computed
  constexpr bool has_input_normals =
      !is_default_parameter<NamedParametersIn, CGAL::internal_np::vertex_normal_map_t>::value;
  using in_vertex = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using In_point = typename boost::property_traits<VPM>::value_type;
  const auto given_normals = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_normal_map),
                                              CGAL::Constant_property_map<in_vertex, Vec3>());
  // colours, texture coordinates, user maps: sampled where the input has them (np_in)
  // and the output wants them (np_out)
  const auto attributes = vertex_attributes_of(np_in, np_out);
  using Attributes = std::decay_t<decltype(attributes)>;
  std::array<std::pair<in_vertex, double>, 3> attribute_sources;

  const auto& vertices = tracer.intersection_vertices();
  reserve_if_possible(out, vertices.size(), complex.halfedges().size() / 2,
                      complex.face_halfedges().size());
  if constexpr(needs_corner_normals && !has_input_normals) // each output vertex reads three corners' normals
    if(3 * 40 * vertices.size() >= num_vertices(tm))
      input_normals.compute_all();
  // the output vertex ov where intersection vertex v's triangle has barycentric
  // coordinates w: position, normals, attributes interpolated there
  auto sample = [&](out_vertex ov, std::uint32_t face_id, const std::array<double, 3>& w) {
    const std::array<in_vertex, 3> corners = tracer.corners_of_face(face_id);
    const std::array<In_point, 3> corner_points = {{get(vpm, corners[0]), get(vpm, corners[1]), get(vpm, corners[2])}};
    const std::array<double, 3> p = barycentric_point(corner_points, w);
    put(out_vpm, ov, Out_point(p[0], p[1], p[2]));
    if constexpr(needs_corner_normals)
      put_normals<Out_vector>(normal_map, crease_normal_map, ov,
                  normals_on_sides(corner_points, normals_at_corners<has_input_normals>(corners, given_normals,
                                                                                         input_normals), w));
    if constexpr(!Attributes::empty) {
      for(int c = 0; c < 3; ++c)
        attribute_sources[c] = {corners[c], w[c]};
      attributes.put_mixed(ov, attribute_sources);
    }
  };
  std::vector<out_vertex> vertex_of(vertices.size());
  std::size_t number_of_vertices = 0;
  for(std::uint32_t v = 0; v < vertices.size(); ++v) {
    prefetch_ahead_of<needs_corner_normals && has_input_normals>(v, tracer, vpm, given_normals, attributes);
    if(!complex.is_kept(v))
      continue;
    const out_vertex ov = add_vertex(out);
    sample(ov, vertices[v].face_id, tracer.barycentric_coordinates(vertices[v]));
    vertex_of[v] = ov;
    ++number_of_vertices;
  }

  stats.output_vertices = number_of_vertices;
  std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> halfedge_of;
  write_primal_connectivity(complex, vertex_of, out, stats, halfedge_of);
  if(parallel_edges == Parallel_edges::SPLIT && stats.parallel_edges > 0)
    split_parallel_edges(complex, tracer, out, halfedge_of, sample, stats);
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_OUTPUT_H
