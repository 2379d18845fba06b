// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_LOCAL_MAGNIFICATION_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_LOCAL_MAGNIFICATION_H

// The input's topology kept by a local refinement (refine_around_defects): where the
// topology check locates a defect, the map is magnified around it, and the run repeats
// at the same cell size. The grid stays one grid, so the output stays one valid
// complex; what changes is f. A lens of centre c (the defect's cell) scales the
// distance r to c by s(r): S = 2 in a ball of radius r0, then less through a ring to
// 1 at a radius R. It moves the input vertices of the surface around the defect (its
// faces' corners, and the vertices reached from them by edges inside the ring) to
// c + s(|f(v) - c|) (f(v) - c); every other vertex keeps its value. Cells there are
// then half as large in f, elsewhere as asked, and each face of the output still lies
// in one cell of the magnified map (section 3 of the paper asks nothing more of f).
//
// r s(r) grows with r, so a lens keeps the order of points along each ray from c. A
// magnification that ends must squeeze somewhere: the ring grows radially by only
// ring_stretch per unit, which fixes R, so there cells reach 1 / ring_stretch of a
// cell in f. Each round's lenses apply to the values the rounds before gave: a defect
// left inside a lens gets a lens of its own the next round, and the two multiply.
// Only the surface around a defect moves, not all of the ball: a map that folds the
// surface (the Gauss map) brings far parts of it near c, and they keep their cells.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Cell_size.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/helpers.h>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

// the radial growth of a lens in its ring: cells there reach 4/3 of a cell across
constexpr double ring_stretch = 0.75;
// rounds of magnification at most (a place lensed in each is 2^6 times finer)
constexpr int maximum_local_refinements = 6;
// the magnification stops (its last round undone) where the output would have more
// intersection vertices than this times the unmagnified run's, what one refinement of
// the whole grid costs: past it, defects are everywhere, and a finer grid the remedy.
// Where the rounds end with more defects than an earlier run, that run's lenses are kept.
constexpr double local_refinement_budget = 2;
// a magnified run stops at this many intersection vertices at least: the budget's
// early stop is for large runs, a small one ends before it matters
constexpr double smallest_budget_cap = 100000;
// and where this many rounds in a row bring it no closer to the input's topology
constexpr int maximum_rounds_without_progress = 2;

/// A ball of the range space.
template <int D>
struct Range_ball
{
  std::array<double, D> center{};
  double radius = 0;
};

template <int D>
double range_distance(const std::array<double, D>& a, const std::array<double, D>& b)
{
  double sum = 0;
  for(int q = 0; q < D; ++q)
    sum += (a[q] - b[q]) * (a[q] - b[q]);
  return std::sqrt(sum);
}

/// One magnified region: the scale S in the inner ball, 1 from the outer radius on.
template <int D>
struct Lens
{
  // S: a place lensed in each of k rounds is 2^k times finer
  static constexpr double magnification = 2;
  Range_ball<D> inner;

  /// R, where r s(r) = S r0 + ring_stretch (r - r0) meets r.
  double outer_radius() const
  {
    return inner.radius * (magnification - ring_stretch) / (1 - ring_stretch);
  }
  /// s(r), the scale at distance r from the centre.
  double scale_at(double r) const
  {
    if(r <= inner.radius)
      return magnification;
    if(r >= outer_radius())
      return 1;
    return (magnification * inner.radius + ring_stretch * (r - inner.radius)) / r;
  }
  /// x moved by the lens.
  std::array<double, D> apply(const std::array<double, D>& x) const
  {
    const double s = scale_at(range_distance<D>(x, inner.center));
    std::array<double, D> y;
    for(int q = 0; q < D; ++q)
      y[q] = inner.center[q] + s * (x[q] - inner.center[q]);
    return y;
  }
};

/// f, magnified on the vertices of the lenses (their values in `moved`, by vertex
/// index), the range map itself elsewhere: a readable property map of the same values.
template <class RangeMap, class VertexIndexMap>
struct Magnified_range_map
{
  using key_type = typename boost::property_traits<RangeMap>::key_type;
  using value_type = std::decay_t<typename boost::property_traits<RangeMap>::value_type>;
  using reference = value_type;
  using category = boost::readable_property_map_tag;
  using Moved = std::unordered_map<std::size_t, value_type>;

  RangeMap range_map;
  VertexIndexMap vertex_index;
  const Moved* moved = nullptr; // no lens: none

  friend value_type get(const Magnified_range_map& map, const key_type& v)
  {
    if(map.moved != nullptr && !map.moved->empty()) {
      const auto found = map.moved->find(std::size_t(get(map.vertex_index, v)));
      if(found != map.moved->end())
        return found->second;
    }
    return get(map.range_map, v);
  }
};

/// The lenses of the runs so far, each applied to the values the ones before it gave
/// (a composition of maps that keep the order along rays: no lens undoes another, and
/// two at one place multiply), and the values they give.
template <class TriangleMesh, class RangeMap, class VertexIndexMap, int D>
class Local_magnification
{
public:
  using Map = Magnified_range_map<RangeMap, VertexIndexMap>;
  using Point = typename Map::value_type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

  Local_magnification(const TriangleMesh& tm, const RangeMap& range_map, VertexIndexMap vertex_index)
    : tm_(tm), range_map_(range_map), vertex_index_(vertex_index)
  {}

  /// The map of the next run.
  Map map() const { return Map{range_map_, vertex_index_, &moved_}; }

  /// Magnifies the map of the last run twice around each region, at cell size h: in a
  /// ball of radius h / 2 around the region's cell centre (for a region without a
  /// cell, a lost piece, the ball of its faces, no smaller). `regions` holds pairs of a
  /// cell's centre (empty: none) and input faces. False, and nothing changes, past the
  /// last round, after an undone one, or after rounds without progress.
  template <class Regions>
  bool magnify_around(const Regions& regions, double h)
  {
    if(rounds_ == maximum_local_refinements || undone_ || rounds_without_progress_ == maximum_rounds_without_progress)
      return false;
    before_last_round_ = moved_;
    std::vector<Lens<D>> round;
    for(const auto& [cell_centre, faces] : regions) {
      Lens<D> lens;
      lens.inner = cell_centre.empty() ? ball_of(faces) : Range_ball<D>{to_point(cell_centre), 0};
      if(!(lens.inner.radius >= 0))
        continue;
      lens.inner.radius = (std::max)(lens.inner.radius, h / 2);
      // a region already in a lens of this round is magnified by it: lenses at one
      // place stack from round to round, so that it is at most 2^rounds finer
      if(std::any_of(round.begin(), round.end(), [&](const Lens<D>& earlier) {
           return range_distance<D>(earlier.inner.center, lens.inner.center) < earlier.inner.radius;
         }))
        continue;
      for(const Lens<D>& earlier : round) // where the lenses before it moved its centre
        lens.inner.center = earlier.apply(lens.inner.center);
      apply(lens, corners_of_faces(tm_, faces));
      round.push_back(lens);
    }
    lenses_in_last_round_ = round.size();
    lenses_ += round.size();
    ++rounds_;
    return true;
  }

  int rounds() const { return rounds_; }

  /// The cap on the intersection vertices of the next run: `cap`, and for a magnified
  /// run the budget too (the unmagnified run's count times local_refinement_budget),
  /// so that a round too large for it stops as early as the cap can tell.
  std::size_t cap(std::size_t cap) const
  {
    if(rounds_ == 0 || undone_)
      return cap;
    const double budget = (std::max)(local_refinement_budget * double(unmagnified_vertices_), smallest_budget_cap);
    return (std::min)(cap, std::size_t(budget) + 1);
  }

  /// After a run with `intersection_vertices` and `defects` (its distance to the
  /// input's topology): true, and back to the map before the last round, the last one,
  /// where that round passed the budget. Else records the run: the unmagnified one's
  /// count, and the lenses of the run with the fewest defects so far.
  bool undo_if_over_budget(std::size_t intersection_vertices, std::size_t defects)
  {
    if(rounds_ == 0)
      unmagnified_vertices_ = intersection_vertices;
    else if(!undone_ && double(intersection_vertices) > local_refinement_budget * double(unmagnified_vertices_)) {
      undo_last_round();
      return true;
    }
    if(rounds_ == 0 || defects < best_.defects) {
      best_ = Best{moved_, rounds_, lenses_, defects};
      rounds_without_progress_ = 0;
    } else {
      ++rounds_without_progress_;
    }
    return false;
  }

  /// Where the refinement ends with more defects than a run before it had (a round's
  /// rings can add some): true, and back to that run's lenses, the last.
  bool restore_fewest_defects(std::size_t defects)
  {
    if(rounds_ == 0 || restored_ || !(best_.defects < defects))
      return false;
    moved_ = best_.moved;
    rounds_ = best_.rounds;
    lenses_ = best_.lenses;
    undone_ = restored_ = true;
    return true;
  }

  /// After a run that failed with `error`: true, and back to the map before the last
  /// round, the last one, where that round failed (its output passed the cap or the
  /// budget, or a face of it crossed too many levels) but the run before it did not.
  bool undo_if_failed(const Remeshing_error& error)
  {
    if(error.kind() == Remeshing_error::Kind::CANCELLED || rounds_ == 0 || undone_)
      return false;
    undo_last_round();
    return true;
  }

  /// What the refinement did, in the statistics of the run it gave.
  template <class Statistics>
  void report(Statistics& stats) const
  {
    stats.local_refinements = std::size_t(rounds_);
    stats.magnified_regions = lenses_;
    stats.largest_magnification = std::pow(Lens<D>::magnification, rounds_);
  }

  /// Back to the map before the last round, the last one: its output is too large.
  void undo_last_round()
  {
    moved_ = std::move(before_last_round_);
    before_last_round_.clear();
    --rounds_;
    lenses_ -= lenses_in_last_round_;
    undone_ = true;
  }

  /// Back to f.
  void clear()
  {
    moved_.clear();
    rounds_ = 0;
    lenses_ = 0;
    undone_ = true; // the refinement is global from here
  }

private:
  Point value(vertex_descriptor v) const { return get(map(), v); }

  static Point to_point(const std::vector<double>& x)
  {
    Point p;
    for(int q = 0; q < D; ++q)
      p[q] = x[std::size_t(q)];
    return p;
  }

  /// The ball of the box of the map over the faces' corners (its centre, half its
  /// diagonal); radius -1 if there is none.
  template <class FaceRange>
  Range_ball<D> ball_of(const FaceRange& faces) const
  {
    const auto box = mapped_box_of<D>(map(), corners_of_faces(tm_, faces));
    Range_ball<D> ball;
    ball.radius = -1;
    if(!(box[0][0] <= box[1][0]))
      return ball;
    double sum = 0;
    for(int q = 0; q < D; ++q) {
      ball.center[q] = box[0][q] / 2 + box[1][q] / 2;
      sum += (box[1][q] - box[0][q]) * (box[1][q] - box[0][q]);
    }
    ball.radius = std::sqrt(sum) / 2;
    if(!std::isfinite(ball.radius))
      ball.radius = -1;
    return ball;
  }

  /// Moves the vertices of the surface the lens magnifies: the corners of its region's
  /// faces, and the vertices reached from them through edges inside its outer ball.
  /// The ones not reached keep their values; those next to a moved one are outside
  /// the outer ball, where the lens is the identity, so the map stays continuous.
  void apply(const Lens<D>& lens, const std::vector<vertex_descriptor>& seeds)
  {
    const double outer = lens.outer_radius();
    std::vector<vertex_descriptor> stack;
    std::vector<std::pair<std::size_t, Point>> moves;
    std::unordered_set<std::size_t> seen;
    auto visit = [&](vertex_descriptor v) {
      const std::size_t id = std::size_t(get(vertex_index_, v));
      if(!seen.insert(id).second)
        return;
      moves.emplace_back(id, lens.apply(value(v)));
      stack.push_back(v);
    };
    for(vertex_descriptor v : seeds)
      visit(v);
    while(!stack.empty()) {
      const vertex_descriptor v = stack.back();
      stack.pop_back();
      for(vertex_descriptor w : CGAL::vertices_around_target(v, tm_))
        if(range_distance<D>(value(w), lens.inner.center) < outer)
          visit(w);
    }
    for(auto& [id, y] : moves)
      moved_[id] = y;
  }

  const TriangleMesh& tm_;
  RangeMap range_map_;
  VertexIndexMap vertex_index_;
  typename Map::Moved moved_, before_last_round_;
  int rounds_ = 0;
  bool undone_ = false;
  std::size_t lenses_in_last_round_ = 0;
  std::size_t unmagnified_vertices_ = 0;
  struct Best
  {
    typename Map::Moved moved;
    int rounds = 0;
    std::size_t lenses = 0;
    std::size_t defects = 0;
  } best_; // the run with the fewest defects
  bool restored_ = false;
  int rounds_without_progress_ = 0; // since the run with the fewest defects
  std::size_t lenses_ = 0;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_LOCAL_MAGNIFICATION_H
