// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_ATTRIBUTES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_ATTRIBUTES_H

// The one seam through which per-vertex properties of the input (colours, texture
// coordinates, any user map) reach the output. Each output vertex is a weighted mix of
// input vertices: a primal vertex of the corners of the input triangle it lies in
// (barycentric weights), a dual vertex of the corners of its primal face (equal
// weights) or of the ends of a primal border edge (linear weights); in remesh(), each
// output vertex of the nearest point of the input where it ended (barycentric weights,
// Attribute_resampling.h). A property is mixed as numbers: each value type says how it
// becomes N numbers and back.

#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Color.h>
#include <CGAL/Range_space_remeshing/internal/Prefetch.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_2.h>
#include <CGAL/Point_3.h>
#include <CGAL/Vector_2.h>
#include <CGAL/Vector_3.h>
#include <CGAL/property_map.h>

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// How values of type `T` become numbers that weights can mix, and back. Specialised
/// below for colours, numbers, arrays of numbers and CGAL's 2-D and 3-D points and
/// vectors.
template <class T, class = void>
struct Attribute_numbers
{
  static_assert(sizeof(T) == 0, "a vertex attribute's value type must be a number, a std::array of numbers, "
                                "CGAL::IO::Color, or a CGAL Point_2, Vector_2, Point_3 or Vector_3");
};

/// A colour as red, green and blue in [0, 1], rounded back to 0..255 channels: mixing
/// the channels' bytes would round at every stage.
template <>
struct Attribute_numbers<CGAL::IO::Color>
{
  static constexpr std::size_t size = 3;
  static std::array<double, 3> to_numbers(const CGAL::IO::Color& c) { return to_rgb(c); }
  static CGAL::IO::Color from_numbers(const std::array<double, 3>& x) { return from_rgb<CGAL::IO::Color>(x); }
};

template <class T>
struct Attribute_numbers<T, std::enable_if_t<std::is_arithmetic<T>::value>>
{
  static constexpr std::size_t size = 1;
  static std::array<double, 1> to_numbers(T x) { return {{double(x)}}; }
  static T from_numbers(const std::array<double, 1>& x) { return static_cast<T>(x[0]); }
};

template <class T, std::size_t N>
struct Attribute_numbers<std::array<T, N>, std::enable_if_t<std::is_arithmetic<T>::value>>
{
  static constexpr std::size_t size = N;
  static std::array<double, N> to_numbers(const std::array<T, N>& a)
  {
    std::array<double, N> x;
    for(std::size_t d = 0; d < N; ++d)
      x[d] = double(a[d]);
    return x;
  }
  static std::array<T, N> from_numbers(const std::array<double, N>& x)
  {
    std::array<T, N> a;
    for(std::size_t d = 0; d < N; ++d)
      a[d] = static_cast<T>(x[d]);
    return a;
  }
};

/// CGAL's points and vectors by their Cartesian coordinates: `Object` is built from
/// `N` numbers.
template <class Object, std::size_t N>
struct Cartesian_attribute_numbers
{
  static constexpr std::size_t size = N;
  static std::array<double, N> to_numbers(const Object& p)
  {
    std::array<double, N> x;
    for(std::size_t d = 0; d < N; ++d)
      x[d] = CGAL::to_double(p.cartesian(int(d)));
    return x;
  }
  static Object from_numbers(const std::array<double, N>& x)
  {
    if constexpr(N == 2)
      return Object(x[0], x[1]);
    else
      return Object(x[0], x[1], x[2]);
  }
};

template <class K>
struct Attribute_numbers<CGAL::Point_2<K>> : Cartesian_attribute_numbers<CGAL::Point_2<K>, 2>
{};
template <class K>
struct Attribute_numbers<CGAL::Vector_2<K>> : Cartesian_attribute_numbers<CGAL::Vector_2<K>, 2>
{};
template <class K>
struct Attribute_numbers<CGAL::Point_3<K>> : Cartesian_attribute_numbers<CGAL::Point_3<K>, 3>
{};
template <class K>
struct Attribute_numbers<CGAL::Vector_3<K>> : Cartesian_attribute_numbers<CGAL::Vector_3<K>, 3>
{};

template <class Map>
using Attribute_value = std::decay_t<typename boost::property_traits<Map>::value_type>;

/// The numbers of the values of `Map`.
template <class Map>
using Numbers_of = std::array<double, Attribute_numbers<Attribute_value<Map>>::size>;

/// A property carried from `source`'s vertices to `destination`'s.
template <class SourceMap, class DestinationMap>
struct Attribute_pair
{
  static_assert(Attribute_numbers<Attribute_value<SourceMap>>::size ==
                    Attribute_numbers<Attribute_value<DestinationMap>>::size,
                "a vertex attribute's input and output values must have as many numbers");
  SourceMap source;
  DestinationMap destination;
};

template <class SourceMap, class DestinationMap>
Attribute_pair<SourceMap, DestinationMap> make_attribute_pair(const SourceMap& source,
                                                             const DestinationMap& destination)
{
  return {source, destination};
}

/// The weighted sum of the numbers of `map`'s values at the `sources`, a range of
/// (vertex, weight) pairs, summed in their order (the output is deterministic).
template <class Map, class Sources>
Numbers_of<Map> mix(const Map& map, const Sources& sources)
{
  Numbers_of<Map> sum;
  sum.fill(0);
  for(const auto& [v, weight] : sources) {
    const auto x = Attribute_numbers<Attribute_value<Map>>::to_numbers(get(map, v));
    for(std::size_t d = 0; d < sum.size(); ++d)
      sum[d] += weight * x[d];
  }
  return sum;
}

/// The attribute pairs of one stage: mixes the sources' values into an output vertex.
template <class... Pairs>
class Vertex_attributes
{
public:
  static constexpr bool empty = sizeof...(Pairs) == 0;

  explicit Vertex_attributes(const std::tuple<Pairs...>& pairs = {}) : pairs_(pairs) {}

  const std::tuple<Pairs...>& pairs() const { return pairs_; }

  /// Asks for the values of input vertex `v` ahead of their use.
  template <class Vertex>
  void prefetch(Vertex v) const
  {
    std::apply([&](const auto&... pair) { (prefetch_value(pair.source, v), ...); }, pairs_);
  }

  /// Puts at `out_vertex` of each destination the mix of its source at `sources`, a
  /// range of (input vertex, weight) pairs whose weights sum to 1.
  template <class OutVertex, class Sources>
  void put_mixed(OutVertex out_vertex, const Sources& sources) const
  {
    std::apply([&](const auto&... pair) { (put_mixed_one(pair, out_vertex, sources), ...); }, pairs_);
  }

private:
  template <class Pair, class OutVertex, class Sources>
  static void put_mixed_one(const Pair& pair, OutVertex out_vertex, const Sources& sources)
  {
    using Out = Attribute_value<decltype(pair.destination)>;
    put(pair.destination, out_vertex, Attribute_numbers<Out>::from_numbers(mix(pair.source, sources)));
  }

  std::tuple<Pairs...> pairs_;
};

template <class... Pairs>
Vertex_attributes<Pairs...> make_vertex_attributes(const std::tuple<Pairs...>& pairs)
{
  return Vertex_attributes<Pairs...>(pairs);
}

/// A tuple of maps: `vertex_attribute_maps` takes one map or a `std::tuple` of them.
template <class Map>
std::tuple<Map> as_tuple_of_maps(const Map& map)
{
  return std::tuple<Map>(map);
}
template <class... Maps>
std::tuple<Maps...> as_tuple_of_maps(const std::tuple<Maps...>& maps)
{
  return maps;
}

/// The pair of the maps of `tag` in `np_in` and `np_out`, if both give one: a property
/// goes along where the input has it and the output wants it.
template <class NamedParametersIn, class NamedParametersOut, class Tag>
auto pair_of_parameter(const NamedParametersIn& np_in, const NamedParametersOut& np_out, Tag tag)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  if constexpr(is_default_parameter<NamedParametersIn, Tag>::value ||
               is_default_parameter<NamedParametersOut, Tag>::value)
    return std::tuple<>();
  else
    return std::make_tuple(make_attribute_pair(get_parameter(np_in, tag), get_parameter(np_out, tag)));
}

template <class Sources, class Destinations, std::size_t... I>
auto zip_pairs(const Sources& sources, const Destinations& destinations, std::index_sequence<I...>)
{
  return std::make_tuple(make_attribute_pair(std::get<I>(sources), std::get<I>(destinations))...);
}

/// The pairs of `vertex_attribute_maps`: the input's and the output's maps, in order.
template <class NamedParametersIn, class NamedParametersOut>
auto pairs_of_attribute_maps(const NamedParametersIn& np_in, const NamedParametersOut& np_out)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using Tag = internal_np::vertex_attribute_maps_t;
  if constexpr(is_default_parameter<NamedParametersIn, Tag>::value ||
               is_default_parameter<NamedParametersOut, Tag>::value)
    return std::tuple<>();
  else {
    // copies: get_parameter() returns the maps by value
    const auto sources = as_tuple_of_maps(get_parameter(np_in, internal_np::vertex_attribute_maps));
    const auto destinations = as_tuple_of_maps(get_parameter(np_out, internal_np::vertex_attribute_maps));
    constexpr std::size_t n = std::tuple_size<std::decay_t<decltype(sources)>>::value;
    static_assert(n == std::tuple_size<std::decay_t<decltype(destinations)>>::value,
                  "vertex_attribute_maps: the input and the output must give as many maps");
    return zip_pairs(sources, destinations, std::make_index_sequence<n>());
  }
}

/// The properties a stage carries from `np_in`'s vertices to `np_out`'s: the colours
/// (`vertex_color_map`), the texture coordinates (`vertex_texture_map`) and
/// `vertex_attribute_maps`, each where both packs give it.
template <class NamedParametersIn, class NamedParametersOut>
auto vertex_attributes_of(const NamedParametersIn& np_in, const NamedParametersOut& np_out)
{
  return make_vertex_attributes(std::tuple_cat(pair_of_parameter(np_in, np_out, CGAL::internal_np::vertex_color_map),
                                               pair_of_parameter(np_in, np_out, CGAL::internal_np::vertex_texture_map),
                                               pairs_of_attribute_maps(np_in, np_out)));
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_ATTRIBUTES_H
