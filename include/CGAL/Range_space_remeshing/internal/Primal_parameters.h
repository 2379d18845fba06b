// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_PARAMETERS_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_PARAMETERS_H

// What `primal_remesh()` (and `remesh()`, which runs it) reads of its named
// parameters, checked: which range map, whether its dimension is usable, the cap on
// the output, the target count, the seeding and topology options, the grid. The run
// itself (internal/Primal_run.h) sees only the values read here.

#include <CGAL/Range_space_remeshing/Identity_range_map.h>
#include <CGAL/Range_space_remeshing/Range_space_traits.h>
#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The cap on the output's vertices: `maximum_number`, or the default.
template <class NamedParameters>
std::size_t maximum_vertices_of(const NamedParameters& np)
{
  return count_parameter(np, CGAL::internal_np::maximum_number, default_maximum_number_of_vertices, "maximum_number",
                         std::numeric_limits<std::size_t>::max());
}

/// `number_of_target_vertices` (0 if not given), refused above the cap on the output: a
/// count the cap forbids would only be searched for in vain.
template <class NamedParameters>
std::size_t target_vertices_of(const NamedParameters& np)
{
  const std::size_t target = count_parameter(np, internal_np::number_of_target_vertices, 0,
                                             "number_of_target_vertices", std::numeric_limits<std::size_t>::max());
  const std::size_t cap = maximum_vertices_of(np);
  if(target > cap)
    throw Remeshing_error("number_of_target_vertices (" + std::to_string(target) + ") is above maximum_number (" +
                              std::to_string(cap) + "), the cap on the output's vertices",
                          Remeshing_error::Kind::BAD_PARAMETER);
  return target;
}

/// The range map of `np` (`range_map`), or the identity of the vertex point map.
template <class TriangleMesh, class NamedParameters>
struct Range_map_of
{
  using VPM = typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  using Default = Identity_range_map<VPM>;
  using type = typename CGAL::internal_np::Lookup_named_param_def<internal_np::range_map_t, NamedParameters,
                                                                  Default>::type;
};

template <class TriangleMesh, class NamedParameters>
typename Range_map_of<TriangleMesh, NamedParameters>::type range_map_of(const TriangleMesh& tm,
                                                                       const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Default = typename Range_map_of<TriangleMesh, NamedParameters>::Default;
  return choose_parameter(get_parameter(np, internal_np::range_map),
                          Default(choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                   get_const_property_map(CGAL::vertex_point, tm))));
}

// The dimension of a range point type: D for `std::array<double, D>`, 0 for anything else.
template <class Value>
struct Range_point_dimension : std::integral_constant<int, 0>
{};
template <std::size_t D>
struct Range_point_dimension<std::array<double, D>> : std::integral_constant<int, int(D)>
{};

template <class RangeMap>
constexpr int range_dimension()
{
  return Range_point_dimension<std::decay_t<typename boost::property_traits<RangeMap>::value_type>>::value;
}

/// Whether the range map of `NamedParameters` is one the remesher can use: its values
/// `std::array<double, D>`, 3 <= D <= 16. The public functions check it first, with one
/// message, and compile nothing else for a map that is not.
template <class TriangleMesh, class NamedParameters>
constexpr bool has_usable_range_map()
{
  constexpr int D = range_dimension<typename Range_map_of<TriangleMesh, NamedParameters>::type>();
  return D >= minimum_range_dimension && D <= maximum_range_dimension;
}

/// The traits of a run: `geom_traits`, or `Range_space_traits` of the range map's
/// dimension.
template <class TriangleMesh, class NamedParameters>
struct Primal_traits_of
{
  static constexpr int D = range_dimension<typename Range_map_of<TriangleMesh, NamedParameters>::type>();
  using type = typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                                  Range_space_traits<D>>::type;
  static_assert(type::dimension == D, "the traits' dimension differs from the range map's dimension");
};

template <class T>
struct Always_false : std::false_type
{};

/// Refuses, with one message, a range map whose values are not `std::array<double, D>`
/// with 3 <= D <= 16 (the instance of `T`, the map, names it in the compiler's output).
template <class T>
void refuse_range_map()
{
  static_assert(Always_false<T>::value,
                "the range_map's value_type must be std::array<double, D> with 3 <= D <= 16 "
                "(convert a Point_3, a std::array<float, D> or a vector in the map's get())");
}

inline void check_cell_size(double cell_size)
{
  if(!(cell_size > 0) || !std::isfinite(cell_size))
    throw Remeshing_error("the cell size must be a positive finite number", Remeshing_error::Kind::BAD_PARAMETER);
}

template <class Point_d>
void check_grid_origin(const Point_d& origin)
{
  for(double x : origin)
    if(!std::isfinite(x))
      throw Remeshing_error("the grid origin must be finite", Remeshing_error::Kind::BAD_PARAMETER);
}

template <class Point_d>
void check_grid(double cell_size, const Point_d& origin)
{
  check_cell_size(cell_size);
  check_grid_origin(origin);
}

// What a run reads of `np_in` besides the maps, checked (and the grid given, which the
// run checks again: refused here before any work, the sizing field's solve included).
struct Primal_run_options
{
  bool seeded, preserve, check, refine_locally;
  std::size_t maximum_vertices;
};

/// Whether `np` asks for the seeded traversal (it maps only the faces it crosses).
template <class NamedParameters>
bool is_seeded(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::seeding_method),
                                            Seeding_method::COMPLETE_SCAN) == Seeding_method::SEEDED;
}

template <class NamedParametersIn>
Primal_run_options primal_run_options(const NamedParametersIn& np_in)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Primal_run_options options;
  options.seeded = is_seeded(np_in);
  options.preserve = choose_parameter(get_parameter(np_in, internal_np::preserve_topology), false);
  options.check = options.preserve || choose_parameter(get_parameter(np_in, internal_np::check_topology), false);
  options.refine_locally =
      options.check && choose_parameter(get_parameter(np_in, internal_np::refine_around_defects), options.preserve);
  options.maximum_vertices = maximum_vertices_of(np_in);
  if(options.preserve && options.seeded)
    throw Remeshing_error("preserve_topology needs the complete scan (Seeding_method::COMPLETE_SCAN)",
                          Remeshing_error::Kind::BAD_PARAMETER);
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParametersIn, CGAL::internal_np::grid_spacing_t>::value)
    check_cell_size(double(get_parameter(np_in, CGAL::internal_np::grid_spacing)));
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParametersIn, internal_np::grid_origin_t>::value)
    check_grid_origin(get_parameter(np_in, internal_np::grid_origin));
  return options;
}

/// `check_named_parameters()` with the parameters `primal_remesh()` reads for its
/// input, and `More...`.
template <class Function, class NamedParameters, class... More>
constexpr bool check_primal_remesh_parameters()
{
  namespace np = internal_np;
  namespace cgal_np = CGAL::internal_np;
  return check_named_parameters<Function, NamedParameters, np::range_map_t, np::sizing_field_t, cgal_np::grid_spacing_t,
                                np::number_of_target_vertices_t, np::grid_origin_t, cgal_np::seeding_method_t,
                                np::seed_faces_t, cgal_np::maximum_number_t, np::check_topology_t,
                                np::preserve_topology_t, np::refine_around_defects_t, np::topology_visitor_t,
                                np::progress_visitor_t,
                                cgal_np::vertex_normal_map_t, cgal_np::vertex_color_map_t, cgal_np::vertex_texture_map_t,
                                np::vertex_attribute_maps_t, cgal_np::vertex_point_t,
                                cgal_np::geom_traits_t, cgal_np::vertex_index_t, cgal_np::face_index_t, More...>();
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_PRIMAL_PARAMETERS_H
