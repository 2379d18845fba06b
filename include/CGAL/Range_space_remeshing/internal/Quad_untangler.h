// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_UNTANGLER_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_UNTANGLER_H

// The untangling after the relaxation: the relaxation refuses moves that
// fold a face or make it non-convex, but the faces that came so from the dual and the
// collapse stay as they are. Here only the vertices of those faces move (and, where
// that is not enough, the vertices around them), one at a time, each to the best of a
// few places on its tangent planes by the least corner quality of its faces (a local
// max-min step, as in Knupp's untangling or CGAL's angle and area smoothing; ties
// broken by the sum of the poor corners' qualities), and only if that raises it and
// makes no face of it worse in shape. Where faces stay tangled after all that, the
// vertices may leave their tangent planes by a little (`allow_off_surface()`): a quad
// over a fold of the input (a scan's, say) cannot be convex on the planes it samples.

#include <CGAL/Range_space_remeshing/internal/Face_corners.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Counts of the faces that are not fine.
struct Face_shape_counts
{
  std::size_t folded = 0, non_convex = 0;
};

/// Vertices the untangling tries in all, per vertex of the mesh: where a large part of
/// the mesh is tangled (the cause is then upstream: a map much finer than the input's
/// facets) the stage stops at a cost of a few relaxation steps instead of searching on.
constexpr std::size_t untangle_tries_per_vertex = 1;
/// The same for the runs after the collapses and rotations of the last resort, all
/// together. Once they are spent, the operations go on alone: they are few and local.
constexpr std::size_t untangle_again_tries_per_vertex = 1;
/// And for the last run, off the tangent planes.
constexpr std::size_t untangle_off_surface_tries_per_vertex = 1;
/// How far that run may move a vertex off its tangent planes, along its normal: this
/// part of the mean length of its edges.
constexpr double off_surface_reach = 0.1;

/// Moves the vertices of the faces that are folded or non-convex. `Place` is called as
/// `place(i, p)`: where vertex i goes when sent towards p (on its tangent planes, along
/// its border), its own position if it stays.
template <class Place>
class Quad_untangler
{
public:
  // The rounds over the tangled faces, each moving every vertex at most once. A move
  // raises its own vertex's quality but may lower a neighbour's: no global measure
  // rises for sure, so the rounds are bounded. Where vertices are held on crease lines
  // a fold can take tens of rounds of small moves to open.
  static constexpr int maximum_rounds = 200;
  // Rounds without fewer tangled faces than ever before, after which the corners
  // alone count as stuck (the vertices around them move too), and then the stage
  // stops: small moves can go on for a hundred rounds and untangle nothing.
  static constexpr int patience = 8;

  Quad_untangler(const Face_corners& fc, std::vector<Vec3>& position, const std::vector<Vec3>& normal, Place place)
    : fc_(fc), position_(position), normal_(normal), place_(place), stuck_(fc.first_face.size() - 1, 0)
  {}

  /// Lets vertex i also be sent up to `reach[i]` along its normal (`place` keeps it
  /// within that of its tangent planes), and judges the corners from each face's own
  /// vector area alone: where the input folds, the normals do not tell its side.
  void allow_off_surface(const std::vector<double>& reach) { off_surface_ = &reach; }

  Face_shape shape(std::size_t k) const { return shape_of(fc_, k, position_, normal_); }
  bool is_convex_in_itself(std::size_t k) const { return internal::is_convex_in_itself(fc_, k, position_); }

  /// The faces that are not fine, in order.
  std::vector<std::size_t> tangled_faces() const
  {
    std::vector<std::size_t> tangled;
    for(std::size_t k = 0; k < fc_.size(); ++k)
      if(shape(k) != Face_shape::FINE)
        tangled.push_back(k);
    return tangled;
  }

  Face_shape_counts count(const std::vector<std::size_t>& faces) const
  {
    Face_shape_counts counts;
    for(std::size_t k : faces) {
      const Face_shape s = shape(k);
      counts.folded += s == Face_shape::FOLDED;
      counts.non_convex += s == Face_shape::NON_CONVEX;
    }
    return counts;
  }

  /// Rounds over the vertices of the tangled faces, in index order, until none is
  /// left, or the rounds stop reducing their number even with the vertices around
  /// them, or the tries (`tried`, counted on from its value) reach `budget`. Returns the
  /// faces still tangled; `moves`, `rounds` and `tried` count what was done.
  /// The visitor hears from every `Progress::interval`-th vertex tried, and can cancel.
  std::vector<std::size_t> run(std::vector<std::size_t> tangled, std::size_t& moves, std::size_t& rounds,
                               std::size_t& tried, std::size_t budget, const Progress& progress)
  {
    std::size_t fewest = tangled.size(), rounds_since_fewer = 0;
    bool with_ring = false;
    std::vector<std::size_t> touched;
    for(rounds = 0; !tangled.empty() && rounds < std::size_t(maximum_rounds) && tried < budget; ++rounds) {
      touched = tangled;
      const std::size_t moved = move_round(tangled, with_ring, budget, tried, touched, progress);
      moves += moved;
      tangled = still_tangled(touched);
      if(tangled.size() < fewest) {
        fewest = tangled.size();
        rounds_since_fewer = 0;
      } else {
        ++rounds_since_fewer;
      }
      if(moved == 0 || rounds_since_fewer >= std::size_t(patience)) {
        if(with_ring)
          break;
        with_ring = true; // the corners alone are stuck: free them by moving their neighbours
        rounds_since_fewer = 0;
      }
    }
    return tangled;
  }

private:
  // One round: each vertex to move, not stuck, tried once (until the budget is
  // spent); the faces around those that moved join `touched`. Returns the moves.
  std::size_t move_round(const std::vector<std::size_t>& tangled, bool with_ring, std::size_t budget,
                         std::size_t& tried, std::vector<std::size_t>& touched, const Progress& progress)
  {
    std::size_t moved = 0;
    for(std::size_t i : vertices_to_move(tangled, with_ring)) {
      if(stuck_[i])
        continue;
      if(tried >= budget)
        break;
      progress.report_at_every(Remeshing_stage::RELAXATION, tried, double(tried) / double(budget));
      ++tried;
      if(!improve_vertex(i)) {
        stuck_[i] = 1;
        continue;
      }
      ++moved;
      touched.insert(touched.end(), incident(i).begin(), incident(i).end());
      for(std::size_t k : incident(i))
        for(std::size_t j : corners(k))
          stuck_[j] = 0;
    }
    return moved;
  }

  struct Range
  {
    const std::size_t *b, *e;
    const std::size_t* begin() const { return b; }
    const std::size_t* end() const { return e; }
  };
  Range incident(std::size_t i) const
  {
    const std::size_t* data = fc_.incident_faces.data();
    return {data + fc_.first_face[i], data + fc_.first_face[i + 1]};
  }
  Range corners(std::size_t k) const
  {
    const std::size_t* data = fc_.corners.data();
    return {data + fc_.first[k], data + fc_.first[k + 1]};
  }

  // the corners of the tangled faces, and with `with_ring` the corners of the faces
  // around those, sorted: a fixed order
  std::vector<std::size_t> vertices_to_move(const std::vector<std::size_t>& tangled, bool with_ring) const
  {
    std::vector<std::size_t> vertices;
    for(std::size_t k : tangled)
      for(std::size_t i : corners(k))
        vertices.push_back(i);
    if(with_ring) {
      const std::size_t own = vertices.size();
      for(std::size_t c = 0; c < own; ++c)
        for(std::size_t k : incident(vertices[c]))
          for(std::size_t j : corners(k))
            vertices.push_back(j);
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return vertices;
  }

  std::vector<std::size_t> still_tangled(std::vector<std::size_t>& faces) const
  {
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    std::vector<std::size_t> tangled;
    for(std::size_t k : faces)
      if(shape(k) != Face_shape::FINE)
        tangled.push_back(k);
    return tangled;
  }

  // The quality of the faces around a vertex: the least corner quality, then the sum
  // of the corner qualities up to `corner_cap`, which still rises where the least is
  // at a corner the vertex cannot turn (the far corner of a quad, whose own vertex is
  // held by another face).
  struct Local_quality
  {
    double worst, capped_sum;
    bool operator>(const Local_quality& other) const
    {
      return worst > other.worst || (worst == other.worst && capped_sum > other.capped_sum);
    }
  };
  static constexpr double corner_cap = 0.5; // the sine of 30 degrees: better corners do not count

  Local_quality local_quality(std::size_t i) const
  {
    Local_quality quality{1, 0};
    beats(i, Local_quality{-2, 0}, quality); // every quality beats a least corner of -2
    return quality;
  }

  // Whether the local quality of vertex i (into `quality`) beats `bound`; stops at the
  // first face whose least corner is below bound's, which no later face can mend: most
  // of the places a vertex tries are worse, and this is the search's inner loop.
  bool beats(std::size_t i, const Local_quality& bound, Local_quality& quality) const
  {
    quality = Local_quality{1, 0};
    for(std::size_t k : incident(i)) {
      quality.worst =
          (std::min)(quality.worst, corner_quality(fc_, k, position_, normal_, corner_cap, quality.capped_sum,
                                                   off_surface_ != nullptr));
      if(quality.worst < bound.worst)
        return false;
    }
    return quality > bound;
  }

  // Where vertex i might go: the centroid of the other corners of its faces, and for
  // each quad the corner that would make it a parallelogram, and their mean.
  std::vector<Vec3> targets(std::size_t i) const
  {
    std::vector<Vec3> found;
    Vec3 centroid = {{0, 0, 0}}, parallelograms = {{0, 0, 0}};
    std::size_t others = 0, quads = 0;
    for(std::size_t k : incident(i)) {
      const Range c = corners(k);
      const std::size_t n = c.end() - c.begin(), at = std::find(c.begin(), c.end(), i) - c.begin();
      for(std::size_t j : c)
        if(j != i) {
          centroid = sum(centroid, position_[j]);
          ++others;
        }
      if(n != 4)
        continue;
      const Vec3& a = position_[c.begin()[next_corner(at, 4)]];
      const Vec3& b = position_[c.begin()[next_corner(next_corner(at, 4), 4)]];
      const Vec3& d = position_[c.begin()[previous_corner(at, 4)]];
      found.push_back(difference(sum(a, d), b));
      parallelograms = sum(parallelograms, found.back());
      ++quads;
    }
    if(quads > 1)
      found.push_back(scaled(parallelograms, 1. / double(quads)));
    if(others > 0) {
      found.push_back(scaled(centroid, 1. / double(others)));
      add_compass_targets(i, found);
    }
    if(off_surface_ != nullptr) { // straight off the planes: the others' offsets are mostly past the reach
      const double reach = (*off_surface_)[i];
      found.push_back(sum(position_[i], scaled(normal_[i], reach)));
      found.push_back(sum(position_[i], scaled(normal_[i], -reach)));
    }
    return found;
  }

  // Eight points around vertex i in its tangent plane, at the mean distance to the
  // other corners of its faces: where the least corner quality has no smooth gradient
  // (a max-min), a search along fixed directions still finds the way up.
  void add_compass_targets(std::size_t i, std::vector<Vec3>& found) const
  {
    const Vec3& x = position_[i];
    double radius = 0;
    std::size_t others = 0;
    for(std::size_t k : incident(i))
      for(std::size_t j : corners(k))
        if(j != i) {
          const Vec3 d = difference(position_[j], x);
          radius += std::sqrt(dot(d, d));
          ++others;
        }
    radius /= double(others);
    const Vec3 u = normalized(any_orthogonal(normal_[i])), w = cross(normal_[i], u);
    const double diagonal = std::sqrt(0.5);
    const double along[8][2] = {{1, 0}, {diagonal, diagonal}, {0, 1}, {-diagonal, diagonal},
                                {-1, 0}, {-diagonal, -diagonal}, {0, -1}, {diagonal, -diagonal}};
    for(const auto& a : along)
      found.push_back(sum(x, sum(scaled(u, radius * a[0]), scaled(w, radius * a[1]))));
  }

  // A face's shape and whether it is convex seen from its own vector area alone: a
  // folded face may also be a dart, which only the second tells.
  struct Shape_seen
  {
    Face_shape shape;
    bool convex_in_itself;
  };

  // whether some face around vertex i is worse in shape than in `before`, or was
  // convex in itself and is no longer
  bool makes_a_face_worse(std::size_t i, const std::vector<Shape_seen>& before) const
  {
    std::size_t c = 0;
    for(std::size_t k : incident(i)) {
      const Shape_seen& was = before[c++];
      if(shape(k) > was.shape || (was.convex_in_itself && !is_convex_in_itself(k)))
        return true;
    }
    return false;
  }

  // Tries each target, and the points a half, a quarter and an eighth of the way to
  // it, on vertex i's tangent planes; keeps the best if it raises the local quality
  // (the least corner quality, or that and then the capped sum).
  bool improve_vertex(std::size_t i)
  {
    const Vec3 start = position_[i];
    std::vector<Shape_seen> before;
    for(std::size_t k : incident(i))
      before.push_back(Shape_seen{shape(k), is_convex_in_itself(k)});
    Local_quality best_quality = local_quality(i);
    Vec3 best = start;
    for(const Vec3& target : targets(i))
      for(double step = 1; step >= 0.125; step /= 2) {
        position_[i] = place_(i, sum(start, scaled(difference(target, start), step)));
        if(position_[i] == start)
          continue;
        Local_quality quality;
        if(beats(i, best_quality, quality) && !makes_a_face_worse(i, before)) {
          best_quality = quality;
          best = position_[i];
        }
      }
    position_[i] = best;
    return best != start;
  }

  static Vec3 sum(const Vec3& a, const Vec3& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
  static Vec3 scaled(const Vec3& a, double s) { return {{a[0] * s, a[1] * s, a[2] * s}}; }

  const Face_corners& fc_;
  std::vector<Vec3>& position_;
  const std::vector<Vec3>& normal_;
  Place place_;
  const std::vector<double>* off_surface_ = nullptr;
  // A vertex that found no better place stays stuck until a corner of its faces moves:
  // its search depends on those positions only, and would find nothing again.
  std::vector<unsigned char> stuck_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_QUAD_UNTANGLER_H
