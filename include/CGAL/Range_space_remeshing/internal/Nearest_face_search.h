// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_NEAREST_FACE_SEARCH_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_NEAREST_FACE_SEARCH_H

// The nearest point of the input surface to a point, and the input face it lies on:
// where remesh() samples the vertex attributes of its output.
//
// Hand-written where CGAL has the AABB tree, which this replaced: the tree bounds each
// face by its box, and on a fan of long thin triangles the boxes of nearly all of them
// hold the fan's middle, so that each query there visited nearly every face (a fan of
// 8,000 slivers took a quarter of a minute for 5,000 queries). Here each face is
// registered in the cubes of a uniform grid that it meets, found by halving the cubes
// of its box and keeping the halves it meets (see meets()): a sliver is in as many
// cubes as it is long, not as many as its box holds. A query scans the cubes
// around it ring by ring, each cube only if it is nearer than the nearest face found,
// until no cube further out can be: the answer is the nearest point of all the faces,
// as the tree's was, whatever the components.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Vec3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/container_hash/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The corner the longest side of the triangle of `corners` starts at (it ends at the next).
inline std::size_t longest_side_start(const std::array<Vec3, 3>& corners)
{
  std::size_t from = 0;
  double longest = -1;
  for(std::size_t i = 0; i < 3; ++i) {
    const Vec3 side = difference(corners[(i + 1) % 3], corners[i]);
    if(dot(side, side) > longest) {
      longest = dot(side, side);
      from = i;
    }
  }
  return from;
}

/// The faces of `tm` at the points of `vpm`, as the search sees them: a face with an
/// area as its triangle; a face without (a crease's copies, a split edge's corners on one
/// line, a part flat at the scale of doubles: a tetrahedron 1e-80 thick) as its longest
/// side: the nearest point on its triangle in doubles is 0 / 0, and leaving it out gave
/// a part made only of such faces the values of another.
template <class TriangleMesh, class PointMap>
struct Searched_faces
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  std::vector<face_descriptor> face;    // those with an area first, then the flat ones
  std::vector<std::array<Vec3, 3>> at;  // their corners; a flat face's longest side, its end twice
  std::size_t number_with_area = 0;
  // each face lies within `reach` of its longest side: for a sliver, a bound on its
  // distance nearly as tight as its nearest point, and several times cheaper
  struct Capsule
  {
    Vec3 start, direction; // the side's start and unit direction
    double length, reach;
    std::size_t from; // the corner the side starts at
    bool well_shaped; // CGAL's face-box test on its triangle is reliable (see meets())
  };
  std::vector<Capsule> capsules;

  Searched_faces(const TriangleMesh& tm, const PointMap& vpm)
  {
    std::vector<std::pair<face_descriptor, std::array<Vec3, 3>>> flat;
    for(face_descriptor f : faces(tm)) {
      const std::array<Vec3, 3> c = corners(f, tm, vpm);
      const Vec3 n = cross(difference(c[1], c[0]), difference(c[2], c[0]));
      if(n[0] != 0 || n[1] != 0 || n[2] != 0) {
        face.push_back(f);
        at.push_back(c);
        capsules.push_back(capsule_of(c, n));
      } else {
        flat.emplace_back(f, c);
      }
    }
    number_with_area = face.size();
    for(const auto& [f, c] : flat) {
      const std::size_t from = longest_side_start(c), to = (from + 1) % 3;
      face.push_back(f);
      at.push_back({{c[from], c[to], c[to]}});
      capsules.push_back(capsule_of(at.back(), Vec3{{0, 0, 0}}));
    }
  }

  /// The capsule of the triangle of corners c and normal n = (c1 - c0) x (c2 - c0).
  static Capsule capsule_of(const std::array<Vec3, 3>& c, const Vec3& n)
  {
    const std::size_t from = longest_side_start(c), to = (from + 1) % 3, other = (from + 2) % 3;
    const Vec3 side = difference(c[to], c[from]);
    const double length = std::sqrt(dot(side, side));
    Capsule capsule{c[from], side, length, 0, from, false};
    if(length > 0)
      for(double& x : capsule.direction)
        x /= length;
    const Vec3 off = difference(c[other], closest_on_segment(c[other], c[from], c[to]));
    capsule.reach = std::sqrt(dot(off, off));
    // CGAL's test starts from the triangle's plane, of normal (c0 - c2) x (c1 - c2): its
    // direction is off by about 2^-52 / sin(angle at c2), far below the margin of
    // meets() if that sine is above 2^-10 (n is that normal, up to rounding)
    const Vec3 a = difference(c[0], c[2]), b = difference(c[1], c[2]);
    capsule.well_shaped = dot(n, n) >= std::ldexp(dot(a, a) * dot(b, b), -20);
    return capsule;
  }

  /// Whether face i may be within `limit` of q: false only if its capsule is farther.
  /// `limit` includes the search's slack, far above the rounding here.
  bool may_be_within(const Vec3& q, std::size_t i, double limit) const
  {
    const Capsule& c = capsules[i];
    const Vec3 off = difference(q, c.start);
    const double t = (std::min)((std::max)(dot(off, c.direction), 0.), c.length);
    const Vec3 away = {{off[0] - t * c.direction[0], off[1] - t * c.direction[1], off[2] - t * c.direction[2]}};
    const double reach = limit + c.reach;
    return dot(away, away) <= reach * reach;
  }

  bool is_flat(std::size_t i) const { return i >= number_with_area; }

  static std::array<Vec3, 3> corners(face_descriptor f, const TriangleMesh& tm, const PointMap& vpm)
  {
    const auto h = halfedge(f, tm);
    return {{to_vec3(get(vpm, source(h, tm))), to_vec3(get(vpm, target(h, tm))),
             to_vec3(get(vpm, target(next(h, tm), tm)))}};
  }
};

/// A uniform grid of cubes over a box, each cube a key: the cubes' sides are the same
/// sums (low + i * side) for the cubes on both sides of them, so the cubes tile the box
/// without gaps, and a point's cube is the one whose sides hold it.
class Cube_grid
{
public:
  using Key = std::array<std::int64_t, 3>; // the cube's index along each axis
  using Key_hash = boost::hash<Key>;

  Cube_grid() = default;
  Cube_grid(const Vec3& low, const Vec3& high, double side) : low_(low), side_(side)
  {
    for(int d = 0; d < 3; ++d) // a cube to spare: the sums' rounding never leaves a point out
      count_[d] = std::int64_t(std::ceil((high[d] - low[d]) / side)) + 1;
  }

  double side() const { return side_; }
  std::int64_t count(int d) const { return count_[d]; }
  double bound(int d, std::int64_t i) const { return low_[d] + double(i) * side_; }

  /// The index along axis d of the cube that holds x (the first or last if beyond).
  std::int64_t index(int d, double x) const
  {
    const double estimate = std::floor((x - low_[d]) / side_);
    std::int64_t i = estimate >= double(count_[d]) ? count_[d] - 1 : estimate < 0 ? 0 : std::int64_t(estimate);
    while(i > 0 && x < bound(d, i)) // the division rounded: the sums decide
      --i;
    while(i + 1 < count_[d] && x >= bound(d, i + 1))
      ++i;
    return i;
  }

  /// The box of the cubes from `first` to `last` (inclusive) along each axis.
  CGAL::Bbox_3 box(const std::array<std::int64_t, 3>& first, const std::array<std::int64_t, 3>& last) const
  {
    return CGAL::Bbox_3(bound(0, first[0]), bound(1, first[1]), bound(2, first[2]), bound(0, last[0] + 1),
                        bound(1, last[1] + 1), bound(2, last[2] + 1));
  }

private:
  Vec3 low_ = {{0, 0, 0}};
  double side_ = 1;
  std::array<std::int64_t, 3> count_ = {{1, 1, 1}};
};

/// The nearest point of the input to a query and the input face it lies on.
template <class TriangleMesh, class PointMap>
class Nearest_face_search
{
  using Kernel = CGAL::Simple_cartesian<double>;
  using Faces = Searched_faces<TriangleMesh, PointMap>;
  using face_descriptor = typename Faces::face_descriptor;
  using Index = Cube_grid::Key;
  using Cube_faces = std::pair<std::uint32_t, std::uint32_t>; // a range of cube_faces_

public:
  struct Hit
  {
    face_descriptor face;
    Vec3 point;
    bool flat;          // the face has no area: weigh along its line
    std::size_t number; // the face's in the search, a hint for the next query
  };

  /// The search over the faces of `tm` at the points of `vpm` (within [-1, 1]: see
  /// scaled_point_map()), for about `number_of_queries` queries near the surface.
  Nearest_face_search(const TriangleMesh& tm, const PointMap& vpm, std::size_t number_of_queries)
      : faces_(tm, vpm),
        budget_((std::min)(8 * (faces_.face.size() + number_of_queries + 1),
                           std::size_t((std::numeric_limits<std::uint32_t>::max)())))
  {
    if(faces_.face.empty())
      return;
    if(faces_.face.size() >= (std::size_t(1) << 29)) // numbered in 32 bits, as the registrations
      throw Remeshing_error("too many input faces (2^29 or more) to sample the vertex attributes",
                            Remeshing_error::Kind::OUTPUT_TOO_LARGE);
    bound_faces();
    // cubes as small as the queries' spacing, unless the faces would then be registered
    // more often than the budget allows (long faces: a fan's slivers): then larger, by
    // what the faces registered before the budget ran out predict
    for(double side = first_cube_side(number_of_queries);;) {
      const std::size_t registered = register_faces(side);
      if(registered == faces_.face.size())
        break;
      side *= (std::max)(1.5, double(faces_.face.size()) / double(registered + 1));
    }
  }

  /// The nearest point to q, and its face; `hint` is the number of a face likely to be
  /// near (the last query's, for a query near the last): it speeds the search up by
  /// giving a bound early, and does not change the answer (a tie goes to the face of
  /// the smaller number).
  Hit nearest(const Vec3& q, std::size_t hint = 0) const
  {
    const double unbounded = std::numeric_limits<double>::infinity();
    // the slack of every comparison of distances: far above their rounding, so that a
    // face as near as the best (a tie) or nearer by rounding is always looked at
    const double slack = std::ldexp(1 + (std::max)({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}), -40);
    Nearest best{unbounded, unbounded, 0, q, slack};
    if(hint < faces_.face.size())
      consider(q, hint, best);
    const Index centre = {{grid_.index(0, q[0]), grid_.index(1, q[1]), grid_.index(2, q[2])}};
    for(std::int64_t ring = 0;; ++ring) {
      const double side = double(2 * ring + 1);
      if(side * side * side > double(cubes_.size())) { // a query far from the faces, in cubes
        scan_all_cubes(q, best);                      // costs no more than a look at each
        break;
      }
      scan_ring(q, centre, ring, best);
      const double beyond = distance_beyond_ring(q, centre, ring);
      if(beyond == unbounded || beyond > best.limit())
        break;
    }
    return {faces_.face[best.face], best.point, faces_.is_flat(best.face), best.face};
  }

private:
  struct Nearest
  {
    double squared_distance, distance;
    std::size_t face; // in faces_
    Vec3 point;
    double slack;

    double limit() const { return distance + slack; } // farther faces need no look
  };

  static double squared(double x) { return x * x; }

  void bound_faces()
  {
    low_.fill(std::numeric_limits<double>::infinity());
    high_.fill(-std::numeric_limits<double>::infinity());
    for(const auto& c : faces_.at)
      for(const Vec3& x : c)
        for(int d = 0; d < 3; ++d) {
          low_[d] = (std::min)(low_[d], x[d]);
          high_[d] = (std::max)(high_[d], x[d]);
        }
    for(int d = 0; d < 3; ++d)
      extent_ = (std::max)(extent_, high_[d] - low_[d]);
  }

  /// The first side tried for the cubes: the spacing of the queries over the faces'
  /// area (a few faces and queries per cube), or larger where the faces would then meet
  /// more cubes than the budget. A face meets about a / side^2 + b / side + 1
  /// cubes, with a its area times the sum of its unit normal's coordinates' sizes and
  /// b half the sum of its sides' coordinates' sizes.
  double first_cube_side(std::size_t number_of_queries) const
  {
    double area = 0, a = 0, b = 0;
    for(const auto& c : faces_.at) {
      const Vec3 n = cross(difference(c[1], c[0]), difference(c[2], c[0]));
      area += std::sqrt(dot(n, n)) / 2;
      a += (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2])) / 2;
      for(int i = 0; i < 3; ++i) {
        const Vec3 e = difference(c[(i + 1) % 3], c[i]);
        b += (std::abs(e[0]) + std::abs(e[1]) + std::abs(e[2])) / 2;
      }
    }
    const double queries = double((std::max)(number_of_queries, std::size_t(1)));
    const double spare = double(budget_) - double(faces_.face.size()); // > 0
    const double within_budget = (b + std::sqrt(b * b + 4 * a * spare)) / (2 * spare);
    const double side = (std::max)({std::sqrt(area / queries), within_budget,
                                    extent_ * std::ldexp(1., -40)}); // at most 2^40 cubes along an axis:
    // a speck far from the rest must not make the rest's cubes large
    return side > 0 && std::isfinite(side) ? side : 1.;
  }

  /// Registers every face in the cubes of side `side` it meets, and returns the number
  /// of faces; if that takes more than the budget, stops, keeps nothing, and returns the
  /// number of faces registered by then.
  std::size_t register_faces(double side)
  {
    std::vector<std::pair<Cube_grid::Key, std::uint32_t>> registered;
    grid_ = Cube_grid(low_, high_, side);
    for(std::size_t i = 0; i < faces_.face.size(); ++i) {
      const auto& c = faces_.at[i];
      Index first, last;
      for(int d = 0; d < 3; ++d) {
        first[d] = grid_.index(d, (std::min)({c[0][d], c[1][d], c[2][d]}));
        last[d] = grid_.index(d, (std::max)({c[0][d], c[1][d], c[2][d]}));
      }
      if(!register_in(std::uint32_t(i), first, last, registered))
        return i;
    }
    std::sort(registered.begin(), registered.end());
    cubes_.clear();
    cube_faces_.resize(registered.size());
    for(std::size_t k = 0; k < registered.size(); ++k) {
      cube_faces_[k] = registered[k].second;
      auto& range = cubes_[registered[k].first];
      if(k == 0 || registered[k - 1].first != registered[k].first)
        range.first = std::uint32_t(k);
      range.second = std::uint32_t(k + 1);
    }
    return faces_.face.size();
  }

  /// Registers face i in the cubes from `first` to `last` that it meets: all of them if
  /// they are one; else each half of them that it meets, as meets() says.
  /// False once the registrations are over the budget.
  bool register_in(std::uint32_t i, const Index& first, const Index& last,
                   std::vector<std::pair<Cube_grid::Key, std::uint32_t>>& registered) const
  {
    int axis = 0;
    for(int d = 1; d < 3; ++d)
      if(last[d] - first[d] > last[axis] - first[axis])
        axis = d;
    if(last[axis] == first[axis]) {
      registered.emplace_back(first, i);
      return registered.size() <= budget_;
    }
    const std::int64_t middle = first[axis] + (last[axis] - first[axis]) / 2;
    Index lower_last = last, upper_first = first;
    lower_last[axis] = middle;
    upper_first[axis] = middle + 1;
    return (!meets(i, grid_.box(first, lower_last)) || register_in(i, first, lower_last, registered)) &&
           (!meets(i, grid_.box(upper_first, last)) || register_in(i, upper_first, last, registered));
  }

  /// Whether face i may meet `box`: false only if it does not. The tests run in doubles
  /// on the box widened by 2^-40, far more than their rounding errors on points within
  /// [-1, 1]: a triangle whose plane CGAL's test cannot trust (a needle, a sliver
  /// seen from its sharp corner) is tested as its capsule, the longest side on the box
  /// widened by the capsule's reach too. Faster than an exact test, and as safe here,
  /// where a face registered in one cube more is only scanned once more.
  bool meets(std::size_t i, const CGAL::Bbox_3& box) const
  {
    const auto& c = faces_.at[i];
    const auto& capsule = faces_.capsules[i];
    const bool as_triangle = !faces_.is_flat(i) && capsule.well_shaped;
    const double margin = std::ldexp(1., -40) + (as_triangle ? 0 : capsule.reach);
    const CGAL::Bbox_3 widened(box.xmin() - margin, box.ymin() - margin, box.zmin() - margin, box.xmax() + margin,
                               box.ymax() + margin, box.zmax() + margin);
    const auto point = [](const Vec3& x) { return Kernel::Point_3(x[0], x[1], x[2]); };
    if(as_triangle)
      return CGAL::do_intersect(Kernel::Triangle_3(point(c[0]), point(c[1]), point(c[2])), widened);
    const Vec3 &start = c[capsule.from], &end = c[(capsule.from + 1) % 3]; // the capsule's side
    return start == end ? CGAL::do_overlap(widened, point(start).bbox())
                        : CGAL::do_intersect(Kernel::Segment_3(point(start), point(end)), widened);
  }

  /// Scans the cubes of the ring at Chebyshev distance `ring` from `centre` that are
  /// nearer to q than the nearest face found.
  void scan_ring(const Vec3& q, const Index& centre, std::int64_t ring, Nearest& best) const
  {
    Index first, last;
    for(int d = 0; d < 3; ++d) {
      first[d] = (std::max)(centre[d] - ring, std::int64_t(0));
      last[d] = (std::min)(centre[d] + ring, grid_.count(d) - 1);
    }
    Index i;
    for(i[0] = first[0]; i[0] <= last[0]; ++i[0])
      for(i[1] = first[1]; i[1] <= last[1]; ++i[1])
        for(i[2] = first[2]; i[2] <= last[2]; ++i[2]) {
          bool on_ring = false;
          for(int d = 0; d < 3; ++d)
            on_ring = on_ring || i[d] == centre[d] - ring || i[d] == centre[d] + ring;
          if(!on_ring) {
            i[2] = (std::max)(i[2], centre[2] + ring - 1); // the inner cubes were scanned
            continue;
          }
          if(squared_distance_to_cube(q, i) <= squared(best.limit()))
            scan_cube(q, i, best);
        }
  }

  void scan_all_cubes(const Vec3& q, Nearest& best) const
  {
    for(const auto& cube : cubes_)
      if(squared_distance_to_cube(q, cube.first) <= squared(best.limit()))
        consider_faces_of(cube.second, q, best);
  }

  double squared_distance_to_cube(const Vec3& q, const Index& i) const
  {
    double sum = 0;
    for(int d = 0; d < 3; ++d) {
      const double below = grid_.bound(d, i[d]) - q[d], above = q[d] - grid_.bound(d, i[d] + 1);
      sum += squared((std::max)({below, above, 0.}));
    }
    return sum;
  }

  void scan_cube(const Vec3& q, const Index& i, Nearest& best) const
  {
    const auto found = cubes_.find(i);
    if(found != cubes_.end())
      consider_faces_of(found->second, q, best);
  }

  void consider_faces_of(const Cube_faces& cube, const Vec3& q, Nearest& best) const
  {
    for(std::uint32_t k = cube.first; k < cube.second; ++k)
      consider(q, cube_faces_[k], best);
  }

  /// Face f's nearest point to q, if nearer than the best (the earlier face on a tie).
  void consider(const Vec3& q, std::size_t f, Nearest& best) const
  {
    if(!faces_.may_be_within(q, f, best.limit()))
      return;
    const auto& c = faces_.at[f];
    const auto point = [](const Vec3& x) { return Kernel::Point_3(x[0], x[1], x[2]); };
    const Kernel::Point_3 p = point(q);
    const Kernel::Point_3 nearest =
        faces_.is_flat(f) ? Kernel().construct_projected_point_3_object()(Kernel::Segment_3(point(c[0]), point(c[1])), p)
                          : Kernel().construct_projected_point_3_object()(
                                Kernel::Triangle_3(point(c[0]), point(c[1]), point(c[2])), p);
    const double d2 = CGAL::squared_distance(p, nearest);
    if(d2 < best.squared_distance || (d2 == best.squared_distance && f < best.face))
      best = {d2, std::sqrt(d2), f, to_vec3(nearest), best.slack};
  }

  /// A lower bound of the distance from q to the cubes beyond the ring: the distance to
  /// the nearest side of the rings' box that has cubes beyond it (infinity if none has).
  double distance_beyond_ring(const Vec3& q, const Index& centre, std::int64_t ring) const
  {
    double nearest = std::numeric_limits<double>::infinity();
    for(int d = 0; d < 3; ++d) {
      if(centre[d] - ring > 0)
        nearest = (std::min)(nearest, q[d] - grid_.bound(d, centre[d] - ring));
      if(centre[d] + ring + 1 < grid_.count(d))
        nearest = (std::min)(nearest, grid_.bound(d, centre[d] + ring + 1) - q[d]);
    }
    return (std::max)(nearest, 0.);
  }

  Faces faces_;
  std::size_t budget_; // registrations: eight per face and query, below 2^32
  Vec3 low_, high_;
  double extent_ = 0;
  Cube_grid grid_;
  std::unordered_map<Cube_grid::Key, Cube_faces, Cube_grid::Key_hash> cubes_;
  std::vector<std::uint32_t> cube_faces_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_NEAREST_FACE_SEARCH_H
