// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_PARAMETERS_H
#define CGAL_RANGE_SPACE_REMESHING_PARAMETERS_H

// Named parameters of the package.
//
// CGAL's list of named-parameter tags is closed: a package outside CGAL cannot add a
// member `.range_map()` to CGAL's packs. The package therefore has its own pack,
// `parameters::Named_function_parameters`, derived from CGAL's (so that CGAL's
// functions and `get_parameter()` read it unchanged), whose members add any parameter
// the package reads, its own tags and CGAL's, in any order. Each public function checks
// at compile time that it reads every parameter it is given.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>

#include <CGAL/Named_function_parameters.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Range_space_remeshing {

/// How intersection vertices are found before tracing.
enum class Seeding_method
{
  /// Scan every input triangle for grid edges: finds every piece of the
  /// intersection, linear in the input size. The default.
  COMPLETE_SCAN,
  /// Start from one seed per input connected component (or from the faces given
  /// by `seed_faces()`) and trace from there: only the triangles the arcs cross are
  /// mapped, so the cost is sublinear in the input. May miss output pieces that are
  /// not connected to a seed.
  SEEDED
};

/// Where `dualize()` puts the dual vertex of a primal face.
enum class Dual_placement
{
  /// the average of the face's vertices, with the normalised average normal
  AVERAGE,
  /// the minimiser of the squared distances to the tangent planes of the face's
  /// vertices (dual contouring's quadric error, solved robustly). The default.
  QEM,
  /// the same minimiser, but keeping the corners and crease lines that the tangent
  /// planes pin even weakly (as those of a mesh prepared by `insert_crease_triangles()`
  /// do, where creases meet), and moved into the kernel of the face's polygon (where it
  /// sees every corner of the face): the dual quads then follow creases around corners
  /// instead of bridging the notches between them. A face whose polygon encloses nothing
  /// (inside an opened crease) gets the point of its sides nearest to the minimiser; a
  /// face whose polygon turns against its vertices' normals (around a concave corner,
  /// where that polygon is the notch) gets its corner nearest to it. On smooth inputs it
  /// scatters vertices more than `QEM` and leaves fewer quads for the collapse to
  /// regularise.
  SHARP_FEATURES
};

namespace internal_np {
enum range_map_t { range_map };
enum sizing_field_t { sizing_field };
enum grid_origin_t { grid_origin };
enum seed_faces_t { seed_faces };
enum dual_placement_t { dual_placement };
enum vertex_tangent_planes_map_t { vertex_tangent_planes_map };
enum vertex_crease_normal_map_t { vertex_crease_normal_map };
enum vertex_attribute_maps_t { vertex_attribute_maps };
enum quad_collapse_t { quad_collapse };
enum number_of_collapse_passes_t { number_of_collapse_passes };
enum number_of_target_vertices_t { number_of_target_vertices };
enum check_topology_t { check_topology };
enum preserve_topology_t { preserve_topology };
enum refine_around_defects_t { refine_around_defects };
enum topology_visitor_t { topology_visitor };
enum progress_visitor_t { progress_visitor };
} // namespace internal_np

// The parameters the package reads, its own and CGAL's: the tag's namespace, the tag,
// the name. One list, expanded into the chain's member functions and the free
// functions that start a chain.
#define CGAL_RANGE_SPACE_REMESHING_EACH_PARAMETER(P)                                   \
  P(internal_np, range_map_t, range_map)                                                 \
  P(internal_np, sizing_field_t, sizing_field)                                           \
  P(internal_np, grid_origin_t, grid_origin)                                             \
  P(internal_np, seed_faces_t, seed_faces)                                               \
  P(internal_np, dual_placement_t, dual_placement)                                       \
  P(internal_np, vertex_tangent_planes_map_t, vertex_tangent_planes_map)                 \
  P(internal_np, vertex_crease_normal_map_t, vertex_crease_normal_map)                   \
  P(internal_np, vertex_attribute_maps_t, vertex_attribute_maps)                         \
  P(internal_np, quad_collapse_t, quad_collapse)                                         \
  P(internal_np, number_of_collapse_passes_t, number_of_collapse_passes)                 \
  P(internal_np, number_of_target_vertices_t, number_of_target_vertices)                 \
  P(internal_np, check_topology_t, check_topology)                                       \
  P(internal_np, preserve_topology_t, preserve_topology)                                 \
  P(internal_np, refine_around_defects_t, refine_around_defects)                         \
  P(internal_np, topology_visitor_t, topology_visitor)                                   \
  P(internal_np, progress_visitor_t, progress_visitor)                                   \
  P(CGAL::internal_np, grid_spacing_t, grid_spacing)                                     \
  P(CGAL::internal_np, seeding_method_t, seeding_method)                                 \
  P(CGAL::internal_np, maximum_number_t, maximum_number)                                 \
  P(CGAL::internal_np, geom_traits_t, geom_traits)                                       \
  P(CGAL::internal_np, do_flip_t, do_flip)                                               \
  P(CGAL::internal_np, number_of_relaxation_steps_t, number_of_relaxation_steps)         \
  P(CGAL::internal_np, number_of_iterations_t, number_of_iterations)                     \
  P(CGAL::internal_np, vertex_is_constrained_t, vertex_is_constrained_map)               \
  P(CGAL::internal_np, edge_is_constrained_t, edge_is_constrained_map)                   \
  P(CGAL::internal_np, vertex_color_map_t, vertex_color_map)                             \
  P(CGAL::internal_np, vertex_texture_map_t, vertex_texture_map)                         \
  P(CGAL::internal_np, vertex_normal_map_t, vertex_normal_map)                           \
  P(CGAL::internal_np, vertex_index_t, vertex_index_map)                                 \
  P(CGAL::internal_np, face_index_t, face_index_map)                                     \
  P(CGAL::internal_np, halfedge_index_t, halfedge_index_map)                             \
  P(CGAL::internal_np, vertex_point_t, vertex_point_map)                                 \
  P(CGAL::internal_np, vertex_to_vertex_map_t, vertex_to_vertex_map)                     \
  P(CGAL::internal_np, face_to_face_map_t, face_to_face_map)

namespace parameters {

/*!
\ingroup PkgRangeSpaceRemeshingRef

A pack of named parameters: CGAL's `Named_function_parameters` (every function of CGAL
reads it), whose member functions add any parameter the package reads, its own and
CGAL's, in any order. A chain starts with one of the free functions of this namespace:
`parameters::grid_spacing(h).range_map(f).vertex_point_map(vpm)`.
*/
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// \cond SKIP_IN_MANUAL
  using CGAL_parameters = CGAL::Named_function_parameters<T, Tag, Base>;
  using CGAL_parameters::CGAL_parameters;
  using self = Named_function_parameters<T, Tag, Base>;

#define CGAL_RANGE_SPACE_REMESHING_MEMBER(NS, TAG, NAME)                               \
  template <class K>                                                                   \
  Named_function_parameters<K, NS::TAG, self> NAME(const K& value) const               \
  {                                                                                    \
    return Named_function_parameters<K, NS::TAG, self>(value, *this);                  \
  }
  CGAL_RANGE_SPACE_REMESHING_EACH_PARAMETER(CGAL_RANGE_SPACE_REMESHING_MEMBER)
#undef CGAL_RANGE_SPACE_REMESHING_MEMBER
  /// \endcond
};

/// \cond SKIP_IN_MANUAL
#define CGAL_RANGE_SPACE_REMESHING_FREE_FUNCTION(NS, TAG, NAME)                        \
  template <class K>                                                                   \
  Named_function_parameters<K, NS::TAG> NAME(const K& value)                           \
  {                                                                                    \
    return Named_function_parameters<K, NS::TAG>(value);                               \
  }
CGAL_RANGE_SPACE_REMESHING_EACH_PARAMETER(CGAL_RANGE_SPACE_REMESHING_FREE_FUNCTION)
#undef CGAL_RANGE_SPACE_REMESHING_FREE_FUNCTION
#undef CGAL_RANGE_SPACE_REMESHING_EACH_PARAMETER
/// \endcond

} // namespace parameters

/*!
\ingroup PkgRangeSpaceRemeshingRef
The default cap on the intersection vertices of a remesh (named parameter
`maximum_number`). A cell size far too small for the input is refused with a
`Remeshing_error` rather than exhausting the memory: at about 1.3 KB per vertex for the
whole pipeline (`remesh()`, measured on CGAL's refined_elephant), this cap keeps a run
within about 13 GB.
*/
constexpr std::size_t default_maximum_number_of_vertices = 10000000;

/*!
\ingroup PkgRangeSpaceRemeshingRef
The cell size used when none is given (named parameters `grid_spacing` and
`number_of_target_vertices` absent), as a fraction of the diagonal of the bounding box of
the mapped input (of f(v) over the input vertices on a face).
*/
constexpr double default_relative_cell_size = 0.01;

namespace internal {

// The tags of a pack, from the last added to the first.
template <class... Tags>
struct Tag_list
{};

template <class Impl>
struct Tags_of_impl;
template <class T, class Tag>
struct Tags_of_impl<CGAL::internal_np::Named_params_impl<T, Tag, CGAL::internal_np::No_property>>
{
  using type = Tag_list<Tag>;
};
template <class T, class Tag, class Base>
struct Tags_of_impl<CGAL::internal_np::Named_params_impl<T, Tag, Base>>
{
  template <class List>
  struct prepend;
  template <class... Tags>
  struct prepend<Tag_list<Tags...>>
  {
    using type = Tag_list<Tag, Tags...>;
  };
  using type = typename prepend<typename Tags_of_impl<typename Base::base>::type>::type;
};

template <class Tag, class... Accepted>
struct Is_accepted : std::disjunction<std::is_same<Tag, CGAL::internal_np::all_default_t>,
                                      std::is_same<Tag, Accepted>...>
{};

// One instance per given tag: the compiler's message names the tag and the function.
template <class Function, class Tag, bool accepted>
struct Check_named_parameter
{
  static_assert(accepted, "a named parameter is given that this function does not read "
                          "(see the list of its named parameters in its documentation)");
  static constexpr bool value = accepted;
};

template <class Function, class List, class... Accepted>
struct Check_named_parameters;
template <class Function, class... Tags, class... Accepted>
struct Check_named_parameters<Function, Tag_list<Tags...>, Accepted...>
{
  static constexpr bool value =
      (true && ... && Check_named_parameter<Function, Tags, Is_accepted<Tags, Accepted...>::value>::value);
};

/// Refuses, at compile time, a pack with a parameter that the function named by the
/// tag type `Function` would ignore. `Accepted...` are the tags it reads.
template <class Function, class NamedParameters, class... Accepted>
constexpr bool check_named_parameters()
{
  using Tags = typename Tags_of_impl<typename NamedParameters::base>::type;
  return Check_named_parameters<Function, Tags, Accepted...>::value;
}

/// The value of the count parameter `tag` of `np` (`default_value` if not given), refused
/// (`BAD_PARAMETER`) if it is negative, not whole, or above `maximum`: converted as it
/// stands, `number_of_target_vertices(-5)` would ask for 2^64 - 5 vertices and
/// `number_of_relaxation_steps(-1)` would run no step without a word.
template <class NamedParameters, class Tag>
std::size_t count_parameter(const NamedParameters& np, Tag tag, std::size_t default_value, const char* name,
                            std::size_t maximum = std::size_t(std::numeric_limits<int>::max()))
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto value = choose_parameter(get_parameter(np, tag), default_value);
  using Value = std::decay_t<decltype(value)>;
  static_assert(std::is_arithmetic<Value>::value, "a count parameter takes a number");
  bool in_range;
  if constexpr(std::is_floating_point<Value>::value)
    in_range = value >= 0 && value == std::floor(value) && value <= double(maximum);
  else if constexpr(std::is_signed<Value>::value)
    in_range = value >= 0 && std::make_unsigned_t<Value>(value) <= maximum;
  else
    in_range = value <= maximum;
  if(!in_range)
    throw Remeshing_error(std::string(name) + " must be a whole number from 0 to " + std::to_string(maximum),
                          Remeshing_error::Kind::BAD_PARAMETER);
  return std::size_t(value);
}

/// Refuses an output mesh that is the input: it is emptied before the input is read.
template <class InputMesh, class OutputMesh>
void refuse_same_mesh(const InputMesh& in, const OutputMesh& out, const char* function)
{
  if(static_cast<const void*>(&in) == static_cast<const void*>(&out))
    throw Remeshing_error(std::string(function) + ": the output mesh must not be the input mesh",
                          Remeshing_error::Kind::BAD_PARAMETER);
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_PARAMETERS_H
