// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_SIZED_RANGE_MAP_H
#define CGAL_RANGE_SPACE_REMESHING_SIZED_RANGE_MAP_H

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Mesh_helpers.h>
#include <CGAL/Range_space_remeshing/internal/Primal_parameters.h>
#include <CGAL/Range_space_remeshing/internal/Scaled_differential.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {

/*!
\ingroup PkgRangeSpaceRemeshingMaps

A range map f with a sizing field s: the map g whose differential is s times f's, so
that around a vertex where s is 2 the cells of the grid are half as large in f, and the
remesh there about twice as fine in each direction (four times as many faces). Where s
is constant, g is s f; where s varies, no map has that differential, and g is the
closest one, in the least-squares sense over the input's edges, each edge's error
relative to the length asked of it. The parts where s is near its median then get the
cells asked; a fine region among coarse ones reaches a scale somewhat below s (a
closed surface cannot grow in one part alone). Each output face still lies in one cell
of g: the bound on f it implies is the cell size divided by g's local scale.

The values are computed once, when the map is made (a sparse linear solve over the
input's vertices, in time linear in their number), and shared by the copies;
the map reads them by vertex index, for the vertices of the mesh it was made of.
Named parameter `sizing_field` of `primal_remesh()` and `remesh()` makes this map of
their range map.

\tparam RangeMap a readable property map, vertex -> `std::array<double, D>`.
\tparam VertexIndexMap a readable property map, vertex -> index below the number of
        vertices.

\cgalModels `ReadablePropertyMap`
*/
template <class RangeMap, class VertexIndexMap>
class Sized_range_map
{
public:
  using key_type = typename boost::property_traits<RangeMap>::key_type;
  using value_type = std::decay_t<typename boost::property_traits<RangeMap>::value_type>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;

  /// The map of `values`, given by vertex index.
  Sized_range_map(std::shared_ptr<const std::vector<value_type>> values, VertexIndexMap vertex_index)
    : values_(std::move(values)), vertex_index_(vertex_index)
  {}

  friend value_type get(const Sized_range_map& map, const key_type& v)
  {
    const std::size_t i = std::size_t(get(map.vertex_index_, v));
    CGAL_precondition(i < map.values_->size()); // a vertex of the mesh the map was made of
    return (*map.values_)[i];
  }

private:
  std::shared_ptr<const std::vector<value_type>> values_;
  VertexIndexMap vertex_index_;
};

namespace internal {

// the largest ratio of a sizing field's values: past it the weights 1 / s^2 leave the
// doubles' range (and no grid could hold cells that different)
constexpr double largest_sizing_ratio = 1e12;

inline std::string number_text(double x)
{
  std::ostringstream text;
  text << x;
  return text.str();
}

/// The median of `values` (not empty), which it reorders.
inline double median_of(std::vector<double>& values)
{
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

} // namespace internal

/*!
\ingroup PkgRangeSpaceRemeshingMaps

Makes the `Sized_range_map` of `range_map` with the sizing field `sizing_field` on the
vertices of `tm`.

\tparam TriangleMesh a model of `FaceGraph`, `VertexListGraph` and `EdgeListGraph`.
\tparam SizingField a readable property map, vertex -> a positive finite number (a
        double, or convertible to one).

\param tm the input mesh the remesh will read.
\param range_map the map f, vertex -> `std::array<double, D>`.
\param sizing_field the scale s of f at each vertex of `tm`.
\param np optional named parameters: `vertex_index_map` (default: the mesh's, made if
  it has none); `progress_visitor` (as for `primal_remesh()`: called during the solve
  with `Remeshing_stage::SCAN` and 0, it may stop it).

\throws Remeshing_error of kind `BAD_PARAMETER` if a value of `sizing_field` is not
  positive and finite, if its largest value is more than 10^12 times its smallest, or
  if it scales f out of the doubles' range; of kind `BAD_INPUT` if a value of
  `range_map` is not finite; `Remeshing_cancelled` when the visitor asks to stop.
*/
template <class TriangleMesh, class RangeMap, class SizingField,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
auto make_sized_range_map(const TriangleMesh& tm, const RangeMap& range_map, const SizingField& sizing_field,
                          const NamedParameters& np = CGAL::parameters::default_values())
{
  using Value = std::decay_t<typename boost::property_traits<RangeMap>::value_type>;
  constexpr int D = int(std::tuple_size<Value>::value);
  static_assert(std::is_same<Value, std::array<double, D>>::value,
                "the range map's value_type must be std::array<double, D>");
  using Vertex_index = decltype(CGAL::get_initialized_vertex_index_map(tm, np));
  const Vertex_index index = CGAL::get_initialized_vertex_index_map(tm, np);
  const std::size_t n = internal::index_bound(vertices(tm), index);
  std::vector<std::array<double, D>> f(n, std::array<double, D>{});
  std::vector<double> s(n, 1.), present;
  present.reserve(n);
  for(auto v : vertices(tm)) {
    const std::size_t i = std::size_t(get(index, v));
    const double scale = double(get(sizing_field, v));
    if(!(scale > 0) || !std::isfinite(scale))
      throw Remeshing_error("the sizing field is " + internal::number_text(scale) + " at vertex " +
                                std::to_string(i) + ": it must be positive and finite",
                            Remeshing_error::Kind::BAD_PARAMETER);
    s[i] = scale;
    present.push_back(scale);
    const Value value = get(range_map, v);
    for(int q = 0; q < D; ++q) {
      if(!std::isfinite(double(value[q])))
        throw Remeshing_error("the range map's value at vertex " + std::to_string(i) +
                                  " is not finite: the sizing field cannot scale it",
                              Remeshing_error::Kind::BAD_INPUT);
      f[i][q] = double(value[q]);
    }
  }
  if(present.empty())
    return Sized_range_map<RangeMap, Vertex_index>(
        std::make_shared<const std::vector<Value>>(std::move(f)), index);
  const auto extremes = std::minmax_element(present.begin(), present.end());
  const double smallest = *extremes.first, largest = *extremes.second;
  if(largest / smallest > internal::largest_sizing_ratio)
    throw Remeshing_error("the sizing field goes from " + internal::number_text(smallest) + " to " +
                              internal::number_text(largest) + ": more than 10^12 times",
                          Remeshing_error::Kind::BAD_PARAMETER);
  const double median = internal::median_of(present);
  for(double& scale : s)
    scale /= median;
  std::vector<std::pair<std::size_t, std::size_t>> edge_list;
  edge_list.reserve(num_edges(tm));
  for(auto e : edges(tm))
    edge_list.emplace_back(std::size_t(get(index, source(e, tm))), std::size_t(get(index, target(e, tm))));
  std::vector<Value> g = internal::scaled_differential<D>(f, s, edge_list, internal::progress_of(np));
  for(auto& value : g)
    for(double& x : value) {
      x *= median;
      if(!std::isfinite(x))
        throw Remeshing_error("the sizing field (up to " + internal::number_text(largest) +
                                  ") scales f out of the doubles' range",
                              Remeshing_error::Kind::BAD_PARAMETER);
    }
  return Sized_range_map<RangeMap, Vertex_index>(std::make_shared<const std::vector<Value>>(std::move(g)), index);
}

namespace internal {

/// The value of `sizing_field` in a pack whose range map is already sized by it.
struct Sizing_field_applied
{};

/// `run(np)`; where `np` has a `sizing_field`, `run` of `np` with its range map sized by
/// it (the named parameters `range_map`, then `sizing_field` as `Sizing_field_applied`,
/// added last: the ones `get_parameter()` finds), so that a stage that runs another
/// public function's body with the pack (remesh() runs primal_remesh()'s) solves once.
template <class TriangleMesh, class NamedParameters, class Run>
decltype(auto) with_sizing_field(const TriangleMesh& tm, const NamedParameters& np, const Run& run)
{
  using Sizing_field = typename CGAL::internal_np::Lookup_named_param_def<internal_np::sizing_field_t, NamedParameters,
                                                                          CGAL::internal_np::Param_not_found>::type;
  if constexpr(std::is_same<Sizing_field, CGAL::internal_np::Param_not_found>::value ||
               std::is_same<Sizing_field, Sizing_field_applied>::value) {
    return run(np);
  } else {
    const auto sized = make_sized_range_map(tm, range_map_of(tm, np),
                                            CGAL::parameters::get_parameter(np, internal_np::sizing_field), np);
    using With_map = parameters::Named_function_parameters<decltype(sized), internal_np::range_map_t, NamedParameters>;
    return run(parameters::Named_function_parameters<Sizing_field_applied, internal_np::sizing_field_t, With_map>(
        Sizing_field_applied(), With_map(sized, np)));
  }
}

} // namespace internal

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_SIZED_RANGE_MAP_H
