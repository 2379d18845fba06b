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
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
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
is constant, g is s f up to a translation; where s varies, no map has that differential,
and g is the closest one, in the least-squares sense over the input's edges. Each output
face still lies in one cell of g; the bound on f it implies is the cell size divided by
s only as closely as g follows s f, loosely where s changes within a few edges.

The values are computed once, when the map is made (a sparse linear solve over the
input's vertices, linear in their number per iteration), and shared by the copies.
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
    return (*map.values_)[std::size_t(get(map.vertex_index_, v))];
  }

private:
  std::shared_ptr<const std::vector<value_type>> values_;
  VertexIndexMap vertex_index_;
};

/*!
\ingroup PkgRangeSpaceRemeshingMaps

Makes the `Sized_range_map` of `range_map` with the sizing field `sizing_field` on the
vertices of `tm`.

\tparam TriangleMesh a model of `FaceGraph`, `VertexListGraph` and `EdgeListGraph`.
\tparam SizingField a readable property map, vertex -> a positive finite number (a
        double, or convertible to one).

\throws Remeshing_error of kind `BAD_PARAMETER` if a value of `sizing_field` is not
  positive and finite, of kind `BAD_INPUT` if a value of `range_map` is not finite.
*/
template <class TriangleMesh, class RangeMap, class SizingField>
auto make_sized_range_map(const TriangleMesh& tm, const RangeMap& range_map, const SizingField& sizing_field)
{
  using Value = std::decay_t<typename boost::property_traits<RangeMap>::value_type>;
  constexpr int D = int(std::tuple_size<Value>::value);
  static_assert(std::is_same<Value, std::array<double, D>>::value,
                "the range map's value_type must be std::array<double, D>");
  using Vertex_index = decltype(CGAL::get_initialized_vertex_index_map(tm));
  const Vertex_index index = CGAL::get_initialized_vertex_index_map(tm);
  const std::size_t n = internal::index_bound(vertices(tm), index);
  std::vector<std::array<double, D>> f(n, std::array<double, D>{});
  std::vector<double> s(n, 1.);
  for(auto v : vertices(tm)) {
    const std::size_t i = std::size_t(get(index, v));
    const double scale = double(get(sizing_field, v));
    if(!(scale > 0) || !std::isfinite(scale))
      throw Remeshing_error("the sizing field is " + std::to_string(scale) + " at vertex " + std::to_string(i) +
                                ": it must be positive and finite",
                            Remeshing_error::Kind::BAD_PARAMETER);
    s[i] = scale;
    const Value value = get(range_map, v);
    for(int q = 0; q < D; ++q) {
      if(!std::isfinite(double(value[q])))
        throw Remeshing_error("the range map's value at vertex " + std::to_string(i) +
                                  " is not finite: the sizing field cannot scale it",
                              Remeshing_error::Kind::BAD_INPUT);
      f[i][q] = double(value[q]);
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> edge_list;
  edge_list.reserve(num_edges(tm));
  for(auto e : edges(tm))
    edge_list.emplace_back(std::size_t(get(index, source(e, tm))), std::size_t(get(index, target(e, tm))));
  auto values = std::make_shared<const std::vector<Value>>(internal::scaled_differential<D>(f, s, edge_list));
  return Sized_range_map<RangeMap, Vertex_index>(std::move(values), index);
}

namespace internal {

/// `run(np)`; where `np` has a `sizing_field`, `run` of `np` with its range map sized by
/// it (the named parameter `range_map` added last, the one `get_parameter()` finds).
template <class TriangleMesh, class NamedParameters, class Run>
decltype(auto) with_sizing_field(const TriangleMesh& tm, const NamedParameters& np, const Run& run)
{
  using Sizing_field = typename CGAL::internal_np::Lookup_named_param_def<internal_np::sizing_field_t, NamedParameters,
                                                                          CGAL::internal_np::Param_not_found>::type;
  if constexpr(std::is_same<Sizing_field, CGAL::internal_np::Param_not_found>::value) {
    return run(np);
  } else {
    auto sized = make_sized_range_map(tm, range_map_of(tm, np),
                                      CGAL::parameters::get_parameter(np, internal_np::sizing_field));
    return run(parameters::Named_function_parameters<decltype(sized), internal_np::range_map_t, NamedParameters>(
        sized, np));
  }
}

} // namespace internal

} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_SIZED_RANGE_MAP_H
