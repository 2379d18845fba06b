// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_BUILDER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_BUILDER_H

// The body of `dualize()`, in named stages: primal vertex data, border chains, dual
// vertices (placement), dual edges and faces, joins into quads, repairs.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Remeshing_stage.h>
#include <CGAL/Range_space_remeshing/Statistics.h>
#include <CGAL/Range_space_remeshing/Tangent_planes.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Dual_joins.h>
#include <CGAL/Range_space_remeshing/internal/Dual_repairs.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Pooled_tangent_planes_map.h>
#include <CGAL/Range_space_remeshing/internal/Polygon_kernel.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Quadric.h>
#include <CGAL/Range_space_remeshing/internal/Vertex_attributes.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The quadric of a dual vertex's planes and its decomposition, which the relaxation
/// can reuse (see `remember_decomposition()`).
struct Decomposed_quadric
{
  Quadric quadric;
  Quadric_eigen eigen;
};

/// Position and normal of the dual vertex of a primal face with tangent planes `planes`;
/// with the QEM placement, `decomposed` receives the quadric it solved.
inline std::pair<Vec3, Vec3> place_dual_vertex(const Tangent_planes& planes, Dual_placement placement,
                                               std::optional<Decomposed_quadric>& decomposed)
{
  decomposed.reset();
  Vec3 mass = {{0, 0, 0}}, normal = {{0, 0, 0}};
  for(const auto& plane : planes)
    for(int d = 0; d < 3; ++d) {
      mass[d] += plane.first[d] / double(planes.size());
      normal[d] += plane.second[d];
    }
  const Vec3 unit_normal = normalized(normal);
  if(placement == Dual_placement::AVERAGE)
    return {mass, unit_normal};
  if(placement == Dual_placement::QEM) {
    Quadric quadric;
    quadric.add_planes(planes);
    decomposed = Decomposed_quadric{quadric, Quadric_eigen(quadric)};
    return {Quadric_projection(decomposed->eigen, quadric_truncation)(mass), unit_normal};
  }
  std::vector<Vec3> polygon;
  polygon.reserve(planes.size());
  for(const auto& plane : planes)
    polygon.push_back(plane.first);
  return {into_face(polygon, normal, sharp_feature_minimiser(planes, mass)), unit_normal};
}

/// Marks in `ends_chain` the valence-2 vertices where the border cycle `cycle` (its
/// vertices in order, the last with a dual face) is cut so that it has at least three
/// chains: those of a cycle with one or two vertices with a dual face, taken evenly
/// along the longest chains.
template <class Vertex, class HasDualFace, class VertexIndexMap>
void split_short_border_cycle(const std::vector<Vertex>& cycle, const HasDualFace& has_dual_face,
                              std::vector<std::uint8_t>& ends_chain, VertexIndexMap vertex_index)
{
  std::vector<std::vector<Vertex>> insides(1); // of each chain, the vertices without dual face
  for(Vertex v : cycle) {
    if(has_dual_face(v))
      insides.emplace_back();
    else
      insides.back().push_back(v);
  }
  insides.pop_back(); // after the last vertex: empty
  if(insides.size() >= 3)
    return;
  auto cut = [&](const std::vector<Vertex>& inside, std::size_t parts) {
    for(std::size_t k = 1; k < parts && inside.size() >= parts - 1; ++k)
      ends_chain[get(vertex_index, inside[k * inside.size() / parts])] = 1;
  };
  if(insides.size() == 1)
    cut(insides[0], 3);
  else
    cut(insides[0].size() >= insides[1].size() ? insides[0] : insides[1], 2);
}

/// Builds the dual of `primal` into `quads` (see `dualize()`): `run()` calls the stages
/// in order, each named after its step.
template <class PolygonMesh, class QuadMesh, class NamedParametersIn, class NamedParametersOut>
class Dual_builder
{
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using dual_vertex = typename boost::graph_traits<QuadMesh>::vertex_descriptor;
  using dual_halfedge = typename boost::graph_traits<QuadMesh>::halfedge_descriptor;
  using dual_face = typename boost::graph_traits<QuadMesh>::face_descriptor;

  template <class NP, class Tag>
  static constexpr bool given = !CGAL::parameters::is_default_parameter<NP, Tag>::value;
  static constexpr bool has_normals = given<NamedParametersIn, CGAL::internal_np::vertex_normal_map_t>;
  static constexpr bool has_crease_normals = given<NamedParametersIn, internal_np::vertex_crease_normal_map_t>;
  static constexpr bool wants_normals = given<NamedParametersOut, CGAL::internal_np::vertex_normal_map_t>;
  static constexpr bool wants_planes = given<NamedParametersOut, internal_np::vertex_tangent_planes_map_t>;

  // the type of a named parameter, or of its default
  template <class NP, class Tag, class Default>
  using Chosen = std::decay_t<decltype(CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(std::declval<const NP&>(), Tag()), std::declval<const Default&>()))>;
  using VPM = Chosen<NamedParametersIn, CGAL::internal_np::vertex_point_t,
                     typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type>;
  using Normal_map = Chosen<NamedParametersIn, CGAL::internal_np::vertex_normal_map_t,
                            CGAL::Constant_property_map<vertex_descriptor, int>>;
  using Crease_normal_map = Chosen<NamedParametersIn, internal_np::vertex_crease_normal_map_t,
                                   CGAL::Constant_property_map<vertex_descriptor, int>>;
  using Out_VPM = typename GetVertexPointMap<QuadMesh, NamedParametersOut>::type;
  using Out_point = typename boost::property_traits<Out_VPM>::value_type;
  using Out_vector = typename CGAL::Kernel_traits<Out_point>::Kernel::Vector_3;
  using Out_normals = Chosen<NamedParametersOut, CGAL::internal_np::vertex_normal_map_t,
                             CGAL::Constant_property_map<dual_vertex, Out_vector>>;
  using Out_planes = Chosen<NamedParametersOut, internal_np::vertex_tangent_planes_map_t,
                            CGAL::Constant_property_map<dual_vertex, Tangent_planes>>;
  // colours, texture coordinates, user maps: where the primal has them (np_in) and the
  // dual wants them (np_out)
  using Attributes = decltype(vertex_attributes_of(std::declval<const NamedParametersIn&>(),
                                                   std::declval<const NamedParametersOut&>()));
  using Face_index = decltype(CGAL::get_initialized_face_index_map(std::declval<const PolygonMesh&>(),
                                                                   std::declval<const NamedParametersIn&>()));
  using Vertex_index = decltype(CGAL::get_initialized_vertex_index_map(std::declval<const PolygonMesh&>(),
                                                                       std::declval<const NamedParametersIn&>()));
  using Halfedge_index = decltype(CGAL::get_initialized_halfedge_index_map(
      std::declval<const PolygonMesh&>(), std::declval<const NamedParametersIn&>()));

  static constexpr std::size_t no_chain = std::size_t(-1);
  static constexpr std::size_t no_corner = std::size_t(-1);
  struct Border_chain {
    halfedge_descriptor first, last; // border halfedges (null face), in border order
  };
  // the halfedges closing a border vertex's dual face: the same one but at a corner
  struct Closing {
    dual_halfedge from_leaving_chain, to_arriving_chain;
  };

public:
  Dual_builder(const PolygonMesh& primal, QuadMesh& quads, const NamedParametersIn& np_in,
               const NamedParametersOut& np_out, const Progress& progress)
    : primal_(primal), quads_(quads), progress_(progress),
      vpm_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_in, CGAL::internal_np::vertex_point),
                            get_const_property_map(CGAL::vertex_point, primal))),
      normal_map_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_in, CGAL::internal_np::vertex_normal_map),
                                   CGAL::Constant_property_map<vertex_descriptor, int>(0))),
      crease_normal_map_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_in, internal_np::vertex_crease_normal_map),
                                          CGAL::Constant_property_map<vertex_descriptor, int>(0))),
      placement_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_in, internal_np::dual_placement), Dual_placement::QEM)),
      out_vpm_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_out, CGAL::internal_np::vertex_point),
                                get_property_map(CGAL::vertex_point, quads))),
      out_normals_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_out, CGAL::internal_np::vertex_normal_map),
                                    CGAL::Constant_property_map<dual_vertex, Out_vector>(CGAL::NULL_VECTOR))),
      out_planes_(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np_out, internal_np::vertex_tangent_planes_map),
                                   CGAL::Constant_property_map<dual_vertex, Tangent_planes>())),
      attributes_(vertex_attributes_of(np_in, np_out)),
      face_index_(CGAL::get_initialized_face_index_map(primal, np_in)),
      vertex_index_(CGAL::get_initialized_vertex_index_map(primal, np_in)),
      halfedge_index_(CGAL::get_initialized_halfedge_index_map(primal, np_in))
  {}

  Dual_statistics run()
  {
    const auto start = std::chrono::steady_clock::now();
    read_primal_vertices();
    find_border_chains();
    // at most: a vertex per primal face, chain and corner, an edge per primal edge,
    // chain and corner (the closing edges), a face per primal vertex
    reserve_if_possible(quads_, num_faces(primal_) + chains_.size() + corners_.size(),
                        num_edges(primal_) + chains_.size() + corners_.size(), num_vertices(primal_));
    place_face_vertices();
    place_chain_vertices();
    place_corner_vertices();
    stats_.dual_vertices = num_faces(primal_) + chains_.size() + corners_.size();
    add_dual_edges();
    progress_.report(Remeshing_stage::DUAL, 0.6);
    add_dual_faces();
    remove_faces_without_dual();
    link_dual_border();
    progress_.report(Remeshing_stage::DUAL, 0.8);
    join_into_quads();
    progress_.report(Remeshing_stage::DUAL, 0.85);
    repair();
    progress_.report(Remeshing_stage::DUAL, 0.97);
    collect_garbage_if_any(quads_);
    for(auto f : faces(quads_))
      (degree(f, quads_) == 4 ? stats_.quads : stats_.non_quads) += 1;
    stats_.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats_;
  }

private:
  std::size_t index(vertex_descriptor v) const { return get(vertex_index_, v); }
  std::size_t index(halfedge_descriptor h) const { return get(halfedge_index_, h); }
  bool has_dual_face(vertex_descriptor v) const { return bool(has_dual_face_[index(v)]); }
  bool ends_chain(vertex_descriptor v) const { return bool(ends_chains_[index(v)]); }
  bool is_corner(vertex_descriptor v) const { return corner_of_vertex_[index(v)] != no_corner; }

  Vec3 primal_normal(vertex_descriptor v) const
  {
    if constexpr(has_normals)
      return to_vec3(get(normal_map_, v));
    else
      return area_weighted_vertex_normal(v, primal_, vpm_);
  }

  // Positions and unit normals of the primal vertices, once; a vertex inside an opened
  // crease also has the other side's normal, a second tangent plane.
  void read_primal_vertices()
  {
    point_of_.resize(num_vertices(primal_));
    normal_of_.resize(num_vertices(primal_));
    for(vertex_descriptor v : vertices(primal_)) {
      point_of_[index(v)] = to_vec3(get(vpm_, v));
      normal_of_[index(v)] = normalized(primal_normal(v));
    }
    if constexpr(has_crease_normals) {
      crease_normal_of_.resize(num_vertices(primal_));
      for(vertex_descriptor v : vertices(primal_))
        crease_normal_of_[index(v)] = normalized(to_vec3(get(crease_normal_map_, v)));
    }
  }

  // The border (paper, section 7, here with a dual that keeps the primal's topology):
  // a border vertex of valence 3 or more has a dual face too, closed on the outside by
  // dual vertices on the primal border. Those sit one per border chain, the primal
  // border between two consecutive such vertices (the vertices of valence 2 inside a
  // chain, ends of merged digons and corners, have no dual face). A chain's dual
  // vertex lies on the primal border and is placed from primal border data only, so
  // the dual border cannot shrink away from it. The valence-2 vertices where a short
  // border cycle is cut (`split_short_border_cycles()`) have a dual face, a quad whose
  // fourth corner is a dual vertex at the primal vertex itself.
  void find_border_chains()
  {
    std::vector<std::uint8_t> on_border;
    count_corners_of_dual_faces(primal_, vertex_index_, on_border, corners_of_dual_face_);
    has_dual_face_.assign(num_vertices(primal_), 0);
    for(std::size_t i = 0; i < has_dual_face_.size(); ++i) // on the border: valence 3 or more
      has_dual_face_[i] = !on_border[i] || corners_of_dual_face_[i] >= 4;
    ends_chains_ = has_dual_face_;
    split_short_border_cycles();
    make_cuts_corners();
    chain_of_.assign(num_halfedges(primal_), no_chain); // of border halfedges
    for(halfedge_descriptor h : halfedges(primal_)) {
      if(!is_border(h, primal_) || chain_of_[index(h)] != no_chain || !ends_chain(source(h, primal_)))
        continue;
      halfedge_descriptor last = h;
      for(;;) {
        chain_of_[index(last)] = chains_.size();
        if(ends_chain(target(last, primal_)))
          break;
        last = next(last, primal_);
      }
      chains_.push_back({h, last});
    }
  }

  // Chains end at the vertices with a dual face, and also at a few valence-2 vertices,
  // where a border cycle would otherwise have fewer than three chains (a dual border
  // cycle of one or two edges); `make_cuts_corners()` gives them a dual face.
  void split_short_border_cycles()
  {
    auto has_face = [this](vertex_descriptor v) { return has_dual_face(v); };
    std::vector<std::uint8_t> walked(num_halfedges(primal_), 0);
    std::vector<vertex_descriptor> cycle; // starting after a vertex with a dual face
    for(halfedge_descriptor h : halfedges(primal_)) {
      if(!is_border(h, primal_) || walked[index(h)] || !has_dual_face(source(h, primal_)))
        continue;
      cycle.clear();
      for(halfedge_descriptor g : CGAL::halfedges_around_face(h, primal_)) {
        walked[index(g)] = 1;
        cycle.push_back(target(g, primal_));
      }
      split_short_border_cycle(cycle, has_face, ends_chains_, vertex_index_);
    }
  }

  // A vertex of valence 2 where a short border cycle is cut gets a dual face: the dual
  // vertices of its two chains, of its face, and one at the vertex, on the primal
  // border. (Without it, the dual border would pass through the dual vertex of its
  // face, which would be on the border twice where the face has two such cuts: a
  // pinched vertex, two fans that a face-list file cannot tell from a non-manifold
  // vertex.)
  void make_cuts_corners()
  {
    corner_of_vertex_.assign(num_vertices(primal_), no_corner);
    for(vertex_descriptor v : vertices(primal_)) {
      const std::size_t i = index(v);
      if(ends_chains_[i] && !has_dual_face_[i]) {
        has_dual_face_[i] = 1;
        corners_of_dual_face_[i] = 4;
        corner_of_vertex_[i] = corners_.size();
        corners_.push_back(v);
      }
    }
  }

  // a dual vertex with its position, normal, the current `planes_` and the attributes
  // mixed from the current `attribute_sources_`
  dual_vertex add_dual_vertex(const Vec3& position, const Vec3& normal)
  {
    const dual_vertex dv = add_vertex(quads_);
    put(out_vpm_, dv, Out_point(position[0], position[1], position[2]));
    if constexpr(wants_normals)
      put(out_normals_, dv, Out_vector(normal[0], normal[1], normal[2]));
    if constexpr(wants_planes)
      put(out_planes_, dv, planes_);
    if constexpr(!Attributes::empty)
      attributes_.put_mixed(dv, attribute_sources_);
    return dv;
  }

  // the tangent planes (and attribute sources) of the corners of primal face f
  void gather_planes_of_face(typename boost::graph_traits<PolygonMesh>::face_descriptor f)
  {
    planes_.clear();
    attribute_sources_.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, primal_), primal_)) {
      const std::size_t i = index(v);
      planes_.emplace_back(point_of_[i], normal_of_[i]);
      if constexpr(has_crease_normals)
        if(crease_normal_of_[i] != Vec3{{0, 0, 0}})
          planes_.emplace_back(point_of_[i], crease_normal_of_[i]);
      if constexpr(!Attributes::empty)
        attribute_sources_.emplace_back(v, 1.); // weighted equally: the face's mean
    }
    if constexpr(!Attributes::empty)
      for(auto& source : attribute_sources_)
        source.second /= double(attribute_sources_.size());
  }

  // the dual vertex of each primal face, placed from its corners' tangent planes
  void place_face_vertices()
  {
    dual_of_face_.resize(num_faces(primal_));
    std::optional<Decomposed_quadric> decomposed;
    std::size_t placed_faces = 0;
    for(auto f : faces(primal_)) {
      progress_.report_every(Remeshing_stage::DUAL, placed_faces++, 2 * num_faces(primal_)); // half the work
      gather_planes_of_face(f);
      const auto placed = place_dual_vertex(planes_, placement_, decomposed);
      const dual_vertex dv = add_dual_vertex(placed.first, placed.second);
      if constexpr(wants_planes)
        if(decomposed)
          remember_decomposition(out_planes_, dv, decomposed->quadric, decomposed->eigen);
      dual_of_face_[get(face_index_, f)] = dv;
    }
  }

  double length(halfedge_descriptor h) const
  {
    const Vec3 edge = difference(point_of_[index(target(h, primal_))], point_of_[index(source(h, primal_))]);
    return std::sqrt(dot(edge, edge));
  }

  // a chain's dual vertex: half-way along it, with the tangent planes of the ends of
  // the primal border edge it lies on (along which the relaxation lets it slide)
  dual_vertex add_dual_vertex_on_chain(const Border_chain& chain)
  {
    double half = 0;
    for(halfedge_descriptor h = chain.first;; h = next(h, primal_)) {
      half += length(h) / 2;
      if(h == chain.last)
        break;
    }
    halfedge_descriptor h = chain.first;
    while(h != chain.last && length(h) < half) {
      half -= length(h);
      h = next(h, primal_);
    }
    const vertex_descriptor a = source(h, primal_), b = target(h, primal_);
    const double t = length(h) > 0 ? (std::min)(half / length(h), 1.) : 0.5;
    const std::size_t ia = index(a), ib = index(b);
    Vec3 position, normal;
    for(int d = 0; d < 3; ++d) {
      position[d] = (1 - t) * point_of_[ia][d] + t * point_of_[ib][d];
      normal[d] = (1 - t) * normal_of_[ia][d] + t * normal_of_[ib][d];
    }
    planes_.assign({{point_of_[ia], normal_of_[ia]}, {point_of_[ib], normal_of_[ib]}});
    attribute_sources_.assign({{a, 1 - t}, {b, t}});
    return add_dual_vertex(position, normalized(normal));
  }

  void place_chain_vertices()
  {
    for(const Border_chain& chain : chains_)
      dual_of_chain_.push_back(add_dual_vertex_on_chain(chain));
  }

  // the dual vertex of a cut vertex's corner: at it, with its tangent plane
  void place_corner_vertices()
  {
    for(vertex_descriptor v : corners_) {
      const std::size_t i = index(v);
      planes_.assign({{point_of_[i], normal_of_[i]}});
      attribute_sources_.assign({{v, 1.}});
      dual_of_corner_.push_back(add_dual_vertex(point_of_[i], normal_of_[i]));
    }
  }

  // the dual vertex on the side of face(h) of the primal edge of h
  dual_vertex dual_on_side(halfedge_descriptor h) const
  {
    return is_border(h, primal_) ? dual_of_chain_[chain_of_[index(h)]]
                                 : dual_of_face_[get(face_index_, face(h, primal_))];
  }

  dual_halfedge dual(halfedge_descriptor h) const { return dual_of_halfedge_[index(h)]; }

  dual_halfedge add_dual_edge(halfedge_descriptor h)
  {
    const dual_halfedge dh = halfedge(add_edge(quads_), quads_);
    set_target(dh, dual_on_side(opposite(h, primal_)), quads_);
    set_target(opposite(dh, quads_), dual_on_side(h), quads_);
    return dh;
  }

  // A dual halfedge d(h) per primal halfedge h, from the dual vertex on the side of h
  // to the one on the side of opposite(h), in the dual face of target(h); the border
  // halfedges of a chain share one dual edge. next(d(h)) = d(prev(opposite(h))) turns
  // counter-clockwise around target(h), so the dual has the primal's orientation.
  void add_dual_edges()
  {
    dual_of_halfedge_.resize(num_halfedges(primal_));
    for(auto e : edges(primal_)) {
      halfedge_descriptor h = halfedge(e, primal_);
      if(is_border(opposite(h, primal_), primal_))
        h = opposite(h, primal_);
      const std::size_t chain = is_border(h, primal_) ? chain_of_[index(h)] : no_chain;
      if(is_border(h, primal_) && (chain == no_chain || h != chains_[chain].last))
        continue; // inside a chain (done with its last edge), or a face without a dual
      const dual_halfedge dh = add_dual_edge(h);
      for(halfedge_descriptor g = h;; g = prev(g, primal_)) {
        dual_of_halfedge_[index(g)] = dh;
        dual_of_halfedge_[index(opposite(g, primal_))] = opposite(dh, quads_);
        if(!is_border(g, primal_) || g == chains_[chain].first)
          break;
      }
    }
  }

  // The dual faces; a border vertex's is closed by a dual edge from the dual vertex
  // of the chain leaving it to that of the chain arriving, whose opposite is on the
  // dual border; a corner's, by two, through the dual vertex at the corner.
  void add_dual_faces()
  {
    closing_of_vertex_.resize(num_vertices(primal_)); // dual face's border side
    for(vertex_descriptor v : vertices(primal_))
      if(has_dual_face(v))
        add_dual_face(v);
  }

  void add_dual_face(vertex_descriptor v)
  {
    const dual_face df = add_face(quads_);
    halfedge_descriptor first = halfedge(v, primal_);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, primal_), primal_))
      if(is_border(h, primal_))
        first = h;
    set_halfedge(df, dual(first), quads_);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(first, primal_)) {
      set_face(dual(h), df, quads_);
      set_halfedge(target(dual(h), quads_), dual(h), quads_);
      if(!is_border(opposite(h, primal_), primal_)) {
        set_next(dual(h), dual(prev(opposite(h, primal_), primal_)), quads_);
        continue;
      }
      closing_of_vertex_[index(v)] = close_dual_face(v, dual(h), dual(first), df);
    }
    ++stats_.dual_faces;
  }

  dual_halfedge add_border_edge(dual_vertex from, dual_vertex to, dual_face df)
  {
    const dual_halfedge dh = halfedge(add_edge(quads_), quads_);
    set_target(dh, to, quads_);
    set_target(opposite(dh, quads_), from, quads_);
    set_face(dh, df, quads_);
    set_face(opposite(dh, quads_), boost::graph_traits<QuadMesh>::null_face(), quads_);
    return dh;
  }

  // Closes the dual face `df` of border vertex v from `last` (into the dual vertex of
  // the chain leaving v) to `first` (out of that of the chain arriving).
  Closing close_dual_face(vertex_descriptor v, dual_halfedge last, dual_halfedge first, dual_face df)
  {
    const dual_vertex leaving_chain = target(last, quads_), arriving_chain = source(first, quads_);
    if(!is_corner(v)) {
      const dual_halfedge closing = add_border_edge(leaving_chain, arriving_chain, df);
      set_next(last, closing, quads_);
      set_next(closing, first, quads_);
      return {closing, closing};
    }
    const dual_vertex corner = dual_of_corner_[corner_of_vertex_[index(v)]];
    const dual_halfedge to_corner = add_border_edge(leaving_chain, corner, df);
    const dual_halfedge from_corner = add_border_edge(corner, arriving_chain, df);
    set_next(last, to_corner, quads_);
    set_next(to_corner, from_corner, quads_);
    set_next(from_corner, first, quads_);
    set_next(opposite(from_corner, quads_), opposite(to_corner, quads_), quads_);
    set_halfedge(corner, opposite(from_corner, quads_), quads_);
    return {to_corner, from_corner};
  }

  // A face whose corners have no dual face is a whole component bounded by one border
  // cycle of valence-2 vertices: it has no dual.
  void remove_faces_without_dual()
  {
    for(auto f : faces(primal_)) {
      const auto corners = CGAL::vertices_around_face(halfedge(f, primal_), primal_);
      if(std::none_of(corners.begin(), corners.end(), [this](vertex_descriptor v) { return has_dual_face(v); })) {
        remove_vertex(dual_of_face_[get(face_index_, f)], quads_);
        ++faces_without_dual_;
      }
    }
    stats_.dual_vertices -= faces_without_dual_;
  }

  // The dual border, in the primal border's direction: a chain's dual vertex is
  // between the closings of its ends (every end of a chain has a dual face).
  void link_dual_border()
  {
    for(const Border_chain& chain : chains_) {
      const vertex_descriptor from = source(chain.first, primal_), to = target(chain.last, primal_);
      const dual_halfedge arriving = opposite(closing_of_vertex_[index(from)].from_leaving_chain, quads_);
      const dual_halfedge leaving = opposite(closing_of_vertex_[index(to)].to_arriving_chain, quads_);
      set_next(arriving, leaving, quads_);
      set_halfedge(target(arriving, quads_), arriving, quads_);
    }
  }

  // Where the primal has vertices of valence 3 and 2 (the ends of merged digons),
  // join the dual faces across the primal edges chosen by `edges_to_join()`: each
  // group of joined faces then has exactly four corners.
  void join_into_quads()
  {
    auto has_face = [this](vertex_descriptor v) { return has_dual_face(v); };
    const auto to_join = edges_to_join(primal_, vertex_index_, has_face, corners_of_dual_face_, progress_);
    progress_.report(Remeshing_stage::DUAL, 0.82);
    Work_meter meter(progress_, Remeshing_stage::DUAL);
    for(halfedge_descriptor h : to_join) {
      meter.add(1, 0.82);
      const dual_halfedge dh = dual(h);
      if(!join_keeps_face_simple(dh, quads_))
        continue; // left as two faces: counted in non_quads
      CGAL::Euler::join_face(dh, quads_);
      ++stats_.joined_triangle_pairs;
      --stats_.dual_faces;
    }
  }

  // non-simple faces, pinches and parallel edges (internal/Dual_repairs.h)
  void repair()
  {
    stats_.dropped_pieces = faces_without_dual_ + remove_pieces_with_non_simple_faces(quads_, stats_.dual_faces);
    progress_.report(Remeshing_stage::DUAL, 0.9);
    stats_.removed_pinches = remove_pinches(quads_, stats_.dual_vertices, stats_.dual_faces);
    progress_.report(Remeshing_stage::DUAL, 0.95);
    stats_.parallel_edges = rotate_parallel_edges(quads_, out_vpm_);
    if(stats_.parallel_edges > 0) {
      stats_.joined_parallel_edges = join_across_parallel_edges(quads_, stats_.dual_faces);
      stats_.parallel_edges = number_of_parallel_edges(quads_);
    }
  }

  const PolygonMesh& primal_;
  QuadMesh& quads_;
  const Progress& progress_;
  VPM vpm_;
  Normal_map normal_map_;
  Crease_normal_map crease_normal_map_;
  Dual_placement placement_;
  Out_VPM out_vpm_;
  Out_normals out_normals_;
  Out_planes out_planes_;
  Attributes attributes_;
  Face_index face_index_;
  Vertex_index vertex_index_;
  Halfedge_index halfedge_index_;

  std::vector<Vec3> point_of_, normal_of_, crease_normal_of_; // by primal vertex index
  std::vector<std::size_t> corners_of_dual_face_;             // by primal vertex index
  std::vector<std::uint8_t> has_dual_face_, ends_chains_;     // by primal vertex index
  std::vector<Border_chain> chains_;
  std::vector<std::size_t> chain_of_; // by border halfedge index, or no_chain
  Tangent_planes planes_;             // of the dual vertex being added
  std::vector<std::pair<vertex_descriptor, double>> attribute_sources_; // with weights
  std::vector<dual_vertex> dual_of_face_, dual_of_chain_;
  std::vector<dual_halfedge> dual_of_halfedge_;
  std::vector<Closing> closing_of_vertex_;
  std::vector<vertex_descriptor> corners_;     // the cut vertices of short border cycles
  std::vector<std::size_t> corner_of_vertex_;  // by primal vertex index, or no_corner
  std::vector<dual_vertex> dual_of_corner_;
  Dual_statistics stats_;
  std::size_t faces_without_dual_ = 0;
};

/// The body of `dualize()`.
template <class PolygonMesh, class QuadMesh, class NamedParametersIn, class NamedParametersOut>
Dual_statistics build_dual(const PolygonMesh& primal, QuadMesh& quads, const NamedParametersIn& np_in,
                           const NamedParametersOut& np_out, const Progress& progress)
{
  if(num_faces(primal) == 0)
    throw Remeshing_error("dualize: the primal mesh has no face");
  return Dual_builder<PolygonMesh, QuadMesh, NamedParametersIn, NamedParametersOut>(primal, quads, np_in, np_out,
                                                                                      progress)
      .run();
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_DUAL_BUILDER_H
