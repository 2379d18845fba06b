// What the benchmark programs share: medians, the bounding-box diagonal and
// METRO-style sampled distances between two meshes.
#ifndef RANGE_SPACE_REMESHING_BENCHMARK_SUPPORT_H
#define RANGE_SPACE_REMESHING_BENCHMARK_SUPPORT_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace benchmark_support {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Triangulates every face: with PMP where it can, and the faces it leaves (a non-planar
/// polygon whose projection crosses itself, such as the few larger faces the dual
/// keeps where it joins two faces) as a fan from one corner. A non-planar polygon has
/// no one surface; the fan is one reading of it, and changes the distances on that
/// face only. PMP fills the faces of more than four corners as holes in 3-D, not by a
/// constrained Delaunay triangulation of their projection: where that projection
/// crosses itself, the triangulation's exact intersections cascade, and it ran for
/// minutes on one primal remesh of man (cell size 0.01005 diagonals) without ending.
inline void triangulate_all_faces(Mesh& m)
{
  if(CGAL::Polygon_mesh_processing::triangulate_faces(m, CGAL::parameters::use_delaunay_triangulation(false)))
    return;
  std::vector<Mesh::Face_index> left;
  for(auto f : faces(m))
    if(degree(f, m) > 3)
      left.push_back(f);
  for(auto f : left) {
    const auto into_corner = prev(halfedge(f, m), m); // its target is the fan's corner
    // each split cuts the triangle (corner, next two corners) off the face left
    while(next(next(next(into_corner, m), m), m) != into_corner)
      CGAL::Euler::split_face(into_corner, next(next(into_corner, m), m), m);
  }
}

/// The time of a load from memory the caches do not hold, in ns: a pointer chase
/// through a random cycle over 64 MB. On a shared virtual machine it changes from
/// minute to minute; printed beside timings, it says in which state they were taken.
inline double memory_latency_ns()
{
  struct alignas(64) Line
  {
    std::uint32_t next;
  };
  std::vector<Line> lines(std::size_t(1) << 20);
  std::vector<std::uint32_t> cycle(lines.size());
  std::iota(cycle.begin(), cycle.end(), std::uint32_t(0));
  std::shuffle(cycle.begin() + 1, cycle.end(), std::mt19937(1));
  for(std::size_t k = 0; k < cycle.size(); ++k)
    lines[cycle[k]].next = cycle[(k + 1) % cycle.size()];
  const std::size_t loads = 2000000;
  std::uint32_t at = 0;
  const auto start = std::chrono::steady_clock::now();
  for(std::size_t k = 0; k < loads; ++k)
    at = lines[at].next;
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  volatile std::uint32_t keep = at; // the chase must not be optimised away
  (void)keep;
  return ns / double(loads);
}

/// Reads `file` into the empty `m`; says why on std::cerr, after `program`'s name, if it
/// is not a non-empty triangle mesh.
inline bool read_triangle_mesh(const std::string& file, Mesh& m, const char* program)
{
  if(CGAL::IO::read_polygon_mesh(file, m) && num_faces(m) > 0 && CGAL::is_triangle_mesh(m))
    return true;
  std::cerr << program << ": cannot read '" << file << "' as a triangle mesh" << std::endl;
  return false;
}

/// The file's name without its folder and extension: the model's name in the tables.
inline std::string model_name(const std::string& file)
{
  const std::string name = file.substr(file.find_last_of('/') + 1);
  return name.substr(0, name.find_last_of('.'));
}

inline double bbox_diagonal(const Mesh& m)
{
  const auto box = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

/// The parameter (a cell size, an edge length) at which `run(parameter)` gives
/// `target` output vertices within 3 %: steps h *= sqrt(count / target) from
/// `first_guess` (the count goes as 1 / h^2), then, once a step overshoots, geometric
/// bisection of the bracket, since the count is not smooth in h and the steps can cycle.
/// Returns the closest parameter tried if none is within 3 %.
template <class Run>
double cell_size_for(Run run, double first_guess, std::size_t target)
{
  double h = first_guess, best_h = h, best_error = std::numeric_limits<double>::infinity();
  double too_fine = 0, too_coarse = 0; // bracket: too many vertices / too few
  for(int step = 0; step < 25; ++step) {
    const double ratio = double(run(h)) / double(target);
    if(std::abs(ratio - 1) < best_error) {
      best_error = std::abs(ratio - 1);
      best_h = h;
    }
    if(best_error < 0.03)
      break;
    (ratio > 1 ? too_fine : too_coarse) = h;
    if(too_fine > 0 && too_coarse > 0)
      h = std::sqrt(too_fine * too_coarse);
    else
      h *= std::sqrt(std::clamp(ratio, 0.25, 4.));
  }
  return best_h;
}

/// RMS and maximum of the distances from `samples` points spread uniformly over the
/// triangle mesh `from` (fixed seed) to the triangle mesh `to`.
inline std::pair<double, double> rms_and_max_distance(const Mesh& from, const Mesh& to, std::size_t samples)
{
  std::vector<K::Point_3> points;
  CGAL::Polygon_mesh_processing::sample_triangle_mesh(
      from, std::back_inserter(points),
      CGAL::parameters::number_of_points_per_area_unit(double(samples) / CGAL::Polygon_mesh_processing::area(from))
          .random_seed(1));
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  Tree tree(faces(to).first, faces(to).second, to);
  tree.accelerate_distance_queries();
  double sum = 0, worst = 0;
  for(const auto& p : points) {
    const double d2 = tree.squared_distance(p);
    sum += d2;
    worst = (std::max)(worst, d2);
  }
  return {std::sqrt(sum / double(points.size())), std::sqrt(worst)};
}

} // namespace benchmark_support

#endif // RANGE_SPACE_REMESHING_BENCHMARK_SUPPORT_H
