// The measures of a remesh that the benchmark programs share (quality, table1): the
// issue-39 corner criterion for folded or non-convex quads, corner angles, valences,
// and the topology (Euler characteristic, components, border cycles). Computed from
// the output mesh's connectivity and points alone, never from the library's
// statistics: the numbers must judge the library, not repeat it.
#ifndef RANGE_SPACE_REMESHING_BENCHMARK_OUTPUT_MEASURES_H
#define RANGE_SPACE_REMESHING_BENCHMARK_OUTPUT_MEASURES_H

#include "benchmark_support.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace output_measures {

namespace PMP = CGAL::Polygon_mesh_processing;

using benchmark_support::K;
using benchmark_support::Mesh;
using Point = K::Point_3;
using Vector = K::Vector_3;

// ---------------------------------------------------------------------------------
// Corner quality: the one formula every quad is judged by

/// The quad's unit vector-area normal: the vector area of a quadrilateral, (1/2) sum of
/// p_i x p_(i+1), is (1/2) (p2 - p0) x (p3 - p1), here normalised (the difference form
/// does not lose digits to the distance from the origin); the zero vector when the
/// vector area vanishes (a symmetric bow-tie, a quad flat as a segment).
inline Vector unit_vector_area_normal(const std::array<Point, 4>& quad)
{
  const Vector area = CGAL::cross_product(quad[2] - quad[0], quad[3] - quad[1]);
  const double length = std::sqrt(area.squared_length());
  return length > 0 ? area / length : CGAL::NULL_VECTOR;
}

/// (e_next x e_prev) . n / (|e_next| |e_prev|) at corner i: the sine of the corner's
/// angle, signed by the side of n it turns to; 0 where an edge has length 0.
inline double corner_quality(const std::array<Point, 4>& quad, int i, const Vector& n)
{
  const Vector e_next = quad[(i + 1) % 4] - quad[i], e_prev = quad[(i + 3) % 4] - quad[i];
  const double lengths = std::sqrt(e_next.squared_length() * e_prev.squared_length());
  return lengths > 0 ? CGAL::cross_product(e_next, e_prev) * n / lengths : 0.;
}

inline double min_corner_quality(const std::array<Point, 4>& quad)
{
  const Vector n = unit_vector_area_normal(quad);
  double worst = 1;
  for(int i = 0; i < 4; ++i)
    worst = (std::min)(worst, corner_quality(quad, i, n));
  return worst;
}

inline bool is_folded_or_non_convex(const std::array<Point, 4>& quad) { return min_corner_quality(quad) <= 0; }

/// The score of a square and a 60° rhombus, and the classifier on quads whose answer
/// is known, each also tilted out of the xy plane
/// and with its corners in the opposite order (its normal then points down): the normal
/// must come from the quad, not from an axis. The program must not measure with a
/// broken instrument, so a wrong answer aborts it.
inline void check_classifier_on_hand_made_quads()
{
  const std::array<Point, 4> convex{{{0, 0, 0}, {2, 0, 0}, {2.5, 1, 0}, {0, 1.5, 0}}};
  const std::array<Point, 4> dart{{{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}}}; // reflex at (0.5, 0.5)
  const std::array<Point, 4> bow_tie{{{0, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 0}}};  // edges 1-2 and 3-0 cross
  const auto tilted = [](std::array<Point, 4> q) {
    for(Point& p : q)
      p = Point(p.x(), 0.6 * p.y() - 0.8 * p.z(), 0.8 * p.y() + 0.6 * p.z());
    return q;
  };
  const auto reversed = [](std::array<Point, 4> q) {
    std::reverse(q.begin(), q.end());
    return q;
  };
  // the score itself: the sine of the smallest corner angle, 1 on a square
  const std::array<Point, 4> square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  const std::array<Point, 4> rhombus_60{{{0, 0, 0}, {2, 0, 0}, {3, std::sqrt(3.), 0}, {1, std::sqrt(3.), 0}}}; // side 2
  bool right = std::abs(min_corner_quality(square) - 1) < 1e-12 &&
               std::abs(min_corner_quality(tilted(rhombus_60)) - std::sqrt(0.75)) < 1e-12;
  for(const auto& [quad, bad] : {std::pair(convex, false), std::pair(dart, true), std::pair(bow_tie, true)})
    for(const auto& seen : {quad, tilted(quad), reversed(quad), reversed(tilted(quad))})
      right = right && is_folded_or_non_convex(seen) == bad;
  if(!right) {
    std::cerr << "quality: the corner-quality check misclassifies a hand-made quad" << std::endl;
    std::abort();
  }
}

// ---------------------------------------------------------------------------------
// Measures of the output mesh

inline std::array<Point, 4> quad_points(const Mesh& m, Mesh::Face_index f)
{
  std::array<Point, 4> quad;
  int i = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
    quad[i++] = m.point(v);
  return quad;
}

/// The nearest-rank percentile: the smallest value with at least `percent` % of the
/// values at or below it.
inline double percentile(std::vector<double> values, double percent)
{
  if(values.empty())
    return NAN;
  std::sort(values.begin(), values.end());
  const std::size_t rank = std::size_t(std::ceil(percent / 100 * double(values.size())));
  return values[rank > 0 ? rank - 1 : 0];
}

/// What a remesh is worth as a quad mesh (or, for the peers' outputs, as a triangle
/// mesh): valences, bad faces, corner angles.
struct Shape
{
  std::size_t interior_vertices = 0, interior_valence_4 = 0, interior_valence_6 = 0;
  std::size_t interior_valence_2 = 0; // doublets: two faces sharing two edges
  std::size_t border_vertices = 0, border_valence_3 = 0;
  std::size_t quads = 0, bad_quads = 0, non_quads = 0;
  std::size_t triangles = 0, folded_triangles = 0;
  // of the quads' corners; of the triangles' in a mesh without quads
  double angle_p1 = NAN, angle_min = NAN;
};

inline void count_valences(const Mesh& m, Shape& s)
{
  for(auto v : vertices(m)) {
    if(is_border(v, m)) {
      ++s.border_vertices;
      s.border_valence_3 += degree(v, m) == 3;
    } else {
      ++s.interior_vertices;
      s.interior_valence_2 += degree(v, m) == 2;
      s.interior_valence_4 += degree(v, m) == 4;
      s.interior_valence_6 += degree(v, m) == 6;
    }
  }
}

/// The unit normal of triangle f (the null vector if it has no area).
inline Vector unit_triangle_normal(const Mesh& m, Mesh::Face_index f)
{
  const auto h = halfedge(f, m);
  const Point &p = m.point(source(h, m)), &q = m.point(target(h, m)), &r = m.point(target(next(h, m), m));
  const Vector n = CGAL::cross_product(q - p, r - p);
  const double length = std::sqrt(n.squared_length());
  return length > 0 ? n / length : CGAL::NULL_VECTOR;
}

/// A triangle folded over its neighbours: its unit normal against the sum of its edge
/// neighbours' is <= 0 (a triangle cannot be non-convex; this is the counterpart of
/// the corner criterion for the peers' triangle meshes). One without area counts.
inline bool is_folded_triangle(const Mesh& m, Mesh::Face_index f)
{
  Vector around = CGAL::NULL_VECTOR;
  for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
    if(!is_border(opposite(h, m), m) && degree(face(opposite(h, m), m), m) == 3)
      around = around + unit_triangle_normal(m, face(opposite(h, m), m));
  return around != CGAL::NULL_VECTOR && unit_triangle_normal(m, f) * around <= 0;
}

/// The unsigned corner angles of any face, in degrees.
inline void add_corner_angles(const Mesh& m, Mesh::Face_index f, std::vector<double>& angles)
{
  for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) {
    const Point& corner = m.point(target(h, m));
    const Vector e_prev = m.point(source(h, m)) - corner, e_next = m.point(target(next(h, m), m)) - corner;
    const double lengths = std::sqrt(e_next.squared_length() * e_prev.squared_length());
    angles.push_back(lengths > 0 ? std::acos(std::clamp(e_next * e_prev / lengths, -1., 1.)) * 180 / M_PI : 0.);
  }
}

inline void measure_faces(const Mesh& m, Shape& s)
{
  std::vector<double> quad_angles, triangle_angles;
  for(auto f : faces(m)) {
    if(degree(f, m) == 3) {
      ++s.triangles;
      s.folded_triangles += is_folded_triangle(m, f);
      add_corner_angles(m, f, triangle_angles);
    }
    if(degree(f, m) != 4) {
      ++s.non_quads;
      continue;
    }
    ++s.quads;
    s.bad_quads += is_folded_or_non_convex(quad_points(m, f));
    add_corner_angles(m, f, quad_angles);
  }
  const std::vector<double>& angles = s.quads > 0 ? quad_angles : triangle_angles;
  s.angle_p1 = percentile(angles, 1);
  s.angle_min = angles.empty() ? NAN : *std::min_element(angles.begin(), angles.end());
}

inline Shape shape_of(const Mesh& m)
{
  Shape s;
  count_valences(m, s);
  measure_faces(m, s);
  return s;
}

struct Topology
{
  long euler = 0;
  std::size_t components = 0, border_cycles = 0;
  bool operator==(const Topology& o) const
  {
    return euler == o.euler && components == o.components && border_cycles == o.border_cycles;
  }
};

inline std::size_t count_border_cycles(const Mesh& m)
{
  std::vector<bool> seen(m.num_halfedges(), false); // by index, removed halfedges included
  std::size_t cycles = 0;
  for(auto h : halfedges(m)) {
    if(!is_border(h, m) || seen[h.idx()])
      continue;
    ++cycles;
    // a border cycle: the halfedges of the "hole" face, followed by next()
    for(auto g : CGAL::halfedges_around_face(h, m))
      seen[g.idx()] = true;
  }
  return cycles;
}

inline Topology topology_of(const Mesh& m)
{
  Topology t;
  t.euler = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  t.components = PMP::connected_components(m, component);
  t.border_cycles = count_border_cycles(m);
  return t;
}

inline std::string describe(const Topology& t)
{
  std::ostringstream out;
  out << "χ " << t.euler << ", " << t.components << " comp., " << t.border_cycles << " border cycles";
  return out.str();
}

/// "kept", or each of χ, components and border cycles that changed, as "before → after".
inline std::string topology_change(const Topology& in, const Topology& out)
{
  if(in == out)
    return "kept";
  std::ostringstream s;
  const char* separator = "";
  const auto changed = [&](const char* name, long before, long after) {
    if(before != after) {
      s << separator << name << " " << before << " → " << after;
      separator = ", ";
    }
  };
  changed("χ", in.euler, out.euler);
  changed("components", long(in.components), long(out.components));
  changed("border cycles", long(in.border_cycles), long(out.border_cycles));
  return s.str();
}

} // namespace output_measures

#endif // RANGE_SPACE_REMESHING_BENCHMARK_OUTPUT_MEASURES_H
