// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_SIZE_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_SIZE_H

// The cell size of a run: `grid_spacing`, or the default (a fraction of the diagonal
// of the mapped input's bounding box), and the search of the cell size that gives
// `number_of_target_vertices` (shared by `primal_remesh()` and `remesh()`).

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/parameters.h>
#include <CGAL/Range_space_remeshing/internal/Primal_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Iterator_range.h>

#include <boost/iterator/filter_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The corners of `faces`, a vertex once per face it is a corner of.
template <class TriangleMesh, class FaceRange>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> corners_of_faces(const TriangleMesh& tm,
                                                                                           const FaceRange& faces)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> corners;
  for(auto f : faces)
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      corners.push_back(v);
  return corners;
}

/// The bounding box (lowest and highest coordinates) of f over `vertex_range`; empty
/// (infinite, low above high) if there is none.
template <int D, class RangeMap, class VertexRange>
std::array<std::array<double, D>, 2> mapped_box_of(const RangeMap& range_map, const VertexRange& vertex_range)
{
  std::array<double, D> low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for(auto v : vertex_range) {
    const auto& x = get(range_map, v);
    for(int q = 0; q < D; ++q) {
      if(!std::isfinite(double(x[q])))
        throw Remeshing_error("the range map gives a NaN or infinite value");
      low[q] = (std::min)(low[q], double(x[q]));
      high[q] = (std::max)(high[q], double(x[q]));
    }
  }
  return {{low, high}};
}

/// The bounding box of f over the vertices on a face (an isolated vertex is never
/// mapped by the remesh).
template <int D, class TriangleMesh, class RangeMap>
std::array<std::array<double, D>, 2> mapped_bounding_box(const TriangleMesh& tm, const RangeMap& range_map)
{
  auto on_a_face = [&tm](auto v) { return halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge(); };
  const auto all = vertices(tm);
  return mapped_box_of<D>(range_map, CGAL::make_range(boost::make_filter_iterator(on_a_face, all.begin(), all.end()),
                                                      boost::make_filter_iterator(on_a_face, all.end(), all.end())));
}

/// The grid origin where the default one (the origin) is more than 2^29 cells of size
/// h from the mapped input: the lattice point of that grid at or below the lowest
/// corner of its bounding box, so that the cells are (up to rounding) those of the
/// default grid. The origin if that point is not finite.
template <class Point_d, class TriangleMesh, class RangeMap>
Point_d lattice_point_below(const TriangleMesh& tm, const RangeMap& range_map, double h)
{
  constexpr int D = range_dimension<RangeMap>();
  const std::array<double, D> low = mapped_bounding_box<D>(tm, range_map)[0];
  Point_d corner{};
  for(int q = 0; q < D; ++q) {
    const double x = std::floor(low[q] / h) * h;
    if(!std::isfinite(x))
      return Point_d{};
    corner[q] = x;
  }
  return corner;
}

/// `default_relative_cell_size` times the diagonal of the bounding box of f over the
/// vertices on a face.
template <class TriangleMesh, class RangeMap>
double default_cell_size(const TriangleMesh& tm, const RangeMap& range_map)
{
  constexpr int D = range_dimension<RangeMap>();
  const auto box = mapped_bounding_box<D>(tm, range_map);
  const std::array<double, D>& low = box[0];
  const std::array<double, D>& high = box[1];
  // the diagonal, scaled by the longest side: the squares of huge or tiny sides would
  // overflow or underflow; and in halves where a side is beyond doubles (-1e308 to 1e308)
  bool halves = false;
  for(int q = 0; q < D; ++q)
    halves = halves || !std::isfinite(high[q] - low[q]);
  auto side = [&](int q) { return halves ? high[q] / 2 - low[q] / 2 : high[q] - low[q]; };
  double longest = 0, sum = 0;
  for(int q = 0; q < D; ++q)
    longest = (std::max)(longest, side(q));
  if(!(longest > 0))
    throw Remeshing_error("the mapped input has no extent (a single point, or no face): give a grid_spacing",
                          Remeshing_error::Kind::BAD_INPUT);
  for(int q = 0; q < D; ++q)
    sum += (side(q) / longest) * (side(q) / longest);
  const double h = (halves ? 2 : 1) * default_relative_cell_size * longest * std::sqrt(sum);
  if(!std::isfinite(h))
    throw Remeshing_error("the mapped input's extent exceeds the largest double (1.8e308): give a grid_spacing",
                          Remeshing_error::Kind::BAD_INPUT);
  return h;
}

// number_of_target_vertices: the counts accepted, and the runs tried at most
constexpr double target_tolerance = 0.1;
constexpr int maximum_target_runs = 12;

/// Whether a run's vertex count is one that `search_cell_size()` accepts for `target`.
inline bool is_near_target(std::size_t count, std::size_t target)
{
  const double n = double((std::max)(count, std::size_t(1)));
  return std::abs(n - double(target)) <= target_tolerance * double(target);
}

/// The cell sizes known to give too many vertices (up to `too_fine`) and too few (from
/// `too_coarse` on), as far as the runs tell: the count falls with the size, but not
/// strictly, so the two may cross; then they bound nothing.
struct Cell_size_bracket
{
  double too_fine = 0, too_coarse = std::numeric_limits<double>::infinity();

  void add(double h, bool too_many)
  {
    if(too_many)
      too_fine = (std::max)(too_fine, h);
    else
      too_coarse = (std::min)(too_coarse, h);
  }

  /// `h`, or the middle (in log scale) of the bracket where `h` is not inside it.
  double kept_inside(double h) const
  {
    const bool bounded = too_fine > 0 && too_coarse < std::numeric_limits<double>::infinity() && too_fine < too_coarse;
    return !bounded || (h > too_fine && h < too_coarse) ? h : std::sqrt(too_fine * too_coarse);
  }
};

/// Searches a cell size, from `h`, whose run gives `target` output vertices within
/// `target_tolerance`: the count goes roughly as h^-2, refined by secant steps in
/// log-log scale. The count is not smooth in h (a row of cells more or less, pieces
/// dropped or kept): where it jumps across the target, the secant steps go back and
/// forth over the jump. So the steps stay inside the bracket of the largest size that
/// gave too many vertices and the smallest that gave too few, and one that would leave
/// it halves it (in log scale) instead; only where `count_falls_with_size`: not with
/// `keeps_topology`, whose refinements make a coarser size give more vertices, nor with
/// the refinement around defects, whose lenses do the same. `run(h)` does a run and
/// returns its vertex count; the last run is the one found. A cell size refused as too
/// small (the output cap) is doubled, and no later step goes back to it: they land
/// between it and the last size that ran, so a target just below the cap is found.
/// `keeps_topology`: the runs refine the cell size until the topology is kept (said if
/// the count stays above).
template <class Run>
double search_cell_size(double h, std::size_t target, const Run& run, bool keeps_topology,
                        bool count_falls_with_size = true)
{
  double previous_h = 0, previous_log_n = 0, n = 0;
  double capped = 0; // the largest cell size refused by the output cap
  const bool bracketed = count_falls_with_size && !keeps_topology;
  Cell_size_bracket bracket;
  const double log_target = std::log(double(target));
  for(int attempt = 0; attempt < maximum_target_runs; ++attempt) {
    try {
      n = double((std::max)(run(h), std::size_t(1)));
    } catch(const Remeshing_error& error) {
      if(error.kind() != Remeshing_error::Kind::OUTPUT_TOO_LARGE)
        throw;
      capped = (std::max)(capped, h);
      if(bracketed)
        bracket.add(h, true);
      h = bracket.kept_inside(previous_h > capped ? std::sqrt(capped * previous_h) : 2 * h);
      previous_h = 0;
      continue;
    }
    if(is_near_target(std::size_t(n), target))
      return h;
    if(bracketed)
      bracket.add(h, n > double(target));
    double slope = -2; // d log n / d log h
    if(previous_h > 0) {
      const double s = (std::log(n) - previous_log_n) / (std::log(h) - std::log(previous_h));
      if(std::isfinite(s) && s < -0.5 && s > -4)
        slope = s;
    }
    previous_h = h;
    previous_log_n = std::log(n);
    h = std::exp(std::log(h) + (log_target - std::log(n)) / slope);
    if(h <= capped) // back to a size the cap refused: halfway (in log scale) from the last
      h = std::sqrt(capped * (std::max)(previous_h, capped));
    h = bracket.kept_inside(h);
  }
  const bool kept_finer = keeps_topology && n > double(target);
  std::ostringstream capped_note;
  if(capped > 0)
    capped_note << "; cells of " << std::setprecision(3) << capped
                << " and smaller were refused: their output is above the cap on output vertices";
  throw Remeshing_error("no cell size tried gives " + std::to_string(target) + " output vertices within " +
                            std::to_string(int(100 * target_tolerance)) + "% (the last gave " +
                            std::to_string(std::size_t(n)) + ")" + capped_note.str() +
                            (kept_finer ? "; keeping the input's topology (preserve_topology) needs smaller "
                                          "cells than that count: ask for more vertices, or allow the topology "
                                          "to change"
                                        : ""),
                        Remeshing_error::Kind::TARGET_NOT_REACHED);
}

/// `search_cell_size()` with the refinement around defects off (`refine_around_defects`
/// false while it searches; but where the topology must be kept), then one run at the size found with it on, as the caller
/// asked; where that run's count is off the target, the search goes on from there with
/// it on. The refinement adds a few vertices where defects are, and up to six runs to
/// each: not to the runs the search throws away. `had_defects()`: whether the last run
/// found some (else the run found is the one asked for).
template <class Run, class HadDefects>
double search_then_refine_around_defects(double h, std::size_t target, bool& refine_around_defects, const Run& run,
                                         const HadDefects& had_defects, bool keeps_topology)
{
  // keeps_topology (preserve_topology): the search needs each trial's kept topology
  if(!refine_around_defects || keeps_topology)
    return search_cell_size(h, target, run, keeps_topology);
  refine_around_defects = false;
  h = search_cell_size(h, target, run, keeps_topology);
  refine_around_defects = true;
  if(!had_defects())
    return h;
  if(is_near_target((std::max)(run(h), std::size_t(1)), target))
    return h;
  return search_cell_size(h, target, run, keeps_topology, false);
}

/// The cell size whose remesh of `tm` under f has about `count` vertices, as f's
/// triangles tell: a flat piece of the mapped surface meets about S / h^2 cells of size
/// h, where S is the sum of the areas of its projections on the D(D - 1) / 2 coordinate
/// planes (for a plane in R^3, its area times |n_x| + |n_y| + |n_z|), and the remesh
/// has about one vertex a cell it meets. Where the search of `number_of_target_vertices`
/// starts when the size given would be far off: the default cell size, made for the
/// identity, gives ten to twenty times the vertices asked for with the normal maps, and
/// that first run cost more than all the others. 0 if f's triangles have no area.
template <class TriangleMesh, class RangeMap>
double cell_size_for_count(const TriangleMesh& tm, const RangeMap& range_map, std::size_t count)
{
  constexpr int D = range_dimension<RangeMap>();
  auto mapped = [&](auto v) { // copied: a map may hand out a buffer that the next call overwrites
    std::array<double, D> x;
    const auto& value = get(range_map, v);
    for(int q = 0; q < D; ++q)
      x[q] = double(value[q]);
    return x;
  };
  double projected_areas = 0; // twice
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const std::array<double, D> a = mapped(source(h, tm)), b = mapped(target(h, tm)),
                                c = mapped(target(next(h, tm), tm));
    std::array<double, D> u, w;
    for(int q = 0; q < D; ++q) {
      u[q] = b[q] - a[q];
      w[q] = c[q] - a[q];
    }
    for(int i = 0; i < D; ++i)
      for(int j = i + 1; j < D; ++j)
        projected_areas += std::abs(u[i] * w[j] - u[j] * w[i]);
  }
  const double h = std::sqrt(projected_areas / 2 / double((std::max)(count, std::size_t(1))));
  return std::isfinite(h) ? h : 0;
}

/// The cell size of `np`: `grid_spacing`, or the default relative to the mapped input.
template <class TriangleMesh, class NamedParameters>
double cell_size_of(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::grid_spacing_t>::value)
    return default_cell_size(tm, range_map_of(tm, np));
  else
    return double(get_parameter(np, CGAL::internal_np::grid_spacing));
}

/// Where the search of `number_of_target_vertices` starts: the cell size of `np`
/// (`grid_spacing` or the default), unless by `cell_size_for_count()` it would give
/// more than four times or less than a quarter of the count: then the size that
/// function gives. That function evaluates f at the corners of every face: not with the
/// seeded traversal, which maps only the faces the arcs cross.
template <class TriangleMesh, class NamedParameters>
double first_cell_size_for_count(const TriangleMesh& tm, const NamedParameters& np, std::size_t target)
{
  const double h = cell_size_of(tm, np);
  if(is_seeded(np))
    return h;
  const double estimate = cell_size_for_count(tm, range_map_of(tm, np), target);
  return estimate > 0 && (h < estimate / 2 || h > 2 * estimate) ? estimate : h;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_CELL_SIZE_H
