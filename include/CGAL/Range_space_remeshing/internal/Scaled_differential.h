// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_SCALED_DIFFERENTIAL_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_SCALED_DIFFERENTIAL_H

// The map behind a sizing field s (Sized_range_map): the map g whose differential is
// s times f's. Where s is constant, g = s f up to a translation, and the grid of g is
// the grid of f with cells 1/s as large. Where s varies, s df is not the differential
// of any map (it is not a closed form), so g is the closest one over the input's edges,
// each edge's error relative to the length asked of it:
//
//   minimise  sum over the edges ij of  |(g_j - g_i) - s_ij (f_j - f_i)|^2 / s_ij^2,
//   s_ij = (s_i + s_j) / 2.
//
// Against the plain sum, the relative one keeps the coarse parts at their size: the
// stretch a closed surface cannot take (a part cannot grow alone) is left short in the
// fine parts, which reach a fraction of s, rather than spread over the rest.
//
// g is linear in s and the minimiser does not change when s is multiplied by a
// constant, so the solve runs with s divided by its median m, and g is m times its
// result: a constant field is then solved exactly, with no iteration. The unknown is
// the displacement d = g / m - f, from 0, with the right-hand side read off the edges,
// b_i = sum over the neighbours j of w_ij (s_ij - 1) (f_i - f_j): where s is m it is 0
// exactly, and no cancellation of large coordinates (a scan in georeferenced units)
// enters the residual. L d = b, L the Laplacian of the edge graph with weights
// w_ij = 1 / s_ij^2, is solved for each coordinate by conjugate gradients
// preconditioned by a multigrid cycle (Aggregation_multigrid.h), whose iterations do
// not grow with the mesh as those of a diagonal preconditioner do. An aggregate's sums
// mix rows whose weights are up to the field's span squared apart, and their rounding
// (1e-16 of the heavy rows) lands on the light ones: beyond a span of
// multigrid_largest_span it could exceed the solve's tolerance, and the cycle then
// stalls or stops on a residual that hides large errors on the light rows. There, and
// wherever the cycle does not reach the tolerance, L's diagonal preconditions instead,
// slower but free of such sums. L is singular (translations of each connected
// component); b sums to zero over each, so the system is consistent. Any g gives a
// valid remesh (each face in one cell of g): the solve's accuracy only sets how
// closely the cells follow s, and it stops at a residual of sizing_solve_tolerance
// times b's, or after maximum_sizing_solve_iterations.
//
// The solver is hand-written: the library depends on CGAL, Boost, GMP and MPFR only,
// and CGAL's sparse solvers need Eigen.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/Remeshing_stage.h>
#include <CGAL/Range_space_remeshing/internal/Aggregation_multigrid.h>
#include <CGAL/Range_space_remeshing/internal/Progress.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

// the conjugate gradients stop when the residual is this small against b's
constexpr double sizing_solve_tolerance = 1e-4;
// the largest span of the field (its largest value over its smallest) for which the
// multigrid cycle is used: its squared span times the doubles' rounding stays below
// the tolerance
constexpr double multigrid_largest_span = 1e6;
// the multigrid's conjugate gradients stop after this many iterations (several times what it needs
// where it works), after which the diagonal takes over
constexpr int maximum_multigrid_iterations = 100;
// and this many with the diagonal: the solve's error only blurs the sizing
constexpr int maximum_sizing_solve_iterations = 5000;

/// L's diagonal as a preconditioner: z = D^-1 r.
struct Diagonal_preconditioner
{
  const Graph_laplacian& graph;

  void apply(const std::vector<double>& r, std::vector<double>& z) const
  {
    for(std::size_t i = 0; i < r.size(); ++i)
      z[i] = graph.diagonal[i] > 0 ? r[i] / graph.diagonal[i] : 0.;
  }
};

/// s_ij, the scale asked of the edge ij.
inline double edge_scale(const std::vector<double>& sizing, std::size_t i, std::size_t j)
{
  return 0.5 * (sizing[i] + sizing[j]);
}

/// The Laplacian of the graph of `edges` (pairs of vertex indices below n; loops
/// skipped, a repeated edge counted as often as it comes) with the weights
/// w_ij = 1 / s_ij^2, s_ij from the per-vertex `sizing`.
inline Graph_laplacian scaled_edge_graph(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                                           const std::vector<double>& sizing)
{
  Graph_laplacian graph;
  graph.first.assign(n + 1, 0);
  for(const auto& [i, j] : edges)
    if(i != j) {
      ++graph.first[i + 1];
      ++graph.first[j + 1];
    }
  for(std::size_t i = 0; i < n; ++i)
    graph.first[i + 1] += graph.first[i];
  graph.neighbour.resize(graph.first[n]);
  graph.weight.resize(graph.first[n]);
  graph.diagonal.assign(n, 0.);
  std::vector<std::size_t> next(graph.first.begin(), graph.first.end() - 1);
  for(const auto& [i, j] : edges)
    if(i != j) {
      const double s = edge_scale(sizing, i, j);
      const double w = 1 / (s * s);
      for(const auto& [from, to] : {std::make_pair(i, j), std::make_pair(j, i)}) {
        graph.neighbour[next[from]] = to;
        graph.weight[next[from]++] = w;
        graph.diagonal[from] += w;
      }
    }
  return graph;
}

inline double dot(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    sum += a[i] * b[i];
  return sum;
}

/// Solves L d = b for one coordinate by conjugate gradients with `preconditioner`, from
/// d, in at most `maximum_iterations`. The visitor hears of each iteration as the start
/// of the scan (the map is made before the grid is met), and may stop it. Returns
/// whether the residual reached its goal; `iterations` counts them.
template <class Preconditioner>
bool solve_scaled_coordinate(const Graph_laplacian& graph, Preconditioner& preconditioner, const std::vector<double>& b,
                             std::vector<double>& d, const Progress& progress, int maximum_iterations, int& iterations)
{
  const std::size_t n = graph.size();
  std::vector<double> r(n), z(n), p(n), lp(n);
  graph.multiply(d, lp);
  for(std::size_t i = 0; i < n; ++i)
    r[i] = b[i] - lp[i];
  const double goal = sizing_solve_tolerance * std::sqrt(dot(b, b));
  preconditioner.apply(r, z);
  p = z;
  double rz = dot(r, z);
  for(iterations = 0; iterations < maximum_iterations; ++iterations) {
    progress.report(Remeshing_stage::SCAN, 0.);
    if(!(std::sqrt(dot(r, r)) > goal))
      return true;
    graph.multiply(p, lp);
    const double curvature = dot(p, lp);
    if(!(curvature > 0))
      return false; // p in L's kernel: no step reduces the residual
    const double alpha = rz / curvature;
    for(std::size_t i = 0; i < n; ++i) {
      d[i] += alpha * p[i];
      r[i] -= alpha * lp[i];
    }
    preconditioner.apply(r, z);
    const double rz_next = dot(r, z);
    const double beta = rz_next / rz;
    rz = rz_next;
    for(std::size_t i = 0; i < n; ++i)
      p[i] = z[i] + beta * p[i];
  }
  return !(std::sqrt(dot(r, r)) > goal);
}

/// The largest value of `sizing` over its smallest, on the vertices with edges (the
/// others, a mesh's removed vertices, have no equation).
inline double span_of_field(const Graph_laplacian& graph, const std::vector<double>& sizing)
{
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for(std::size_t i = 0; i < graph.size(); ++i)
    if(!graph.isolated(i)) {
      smallest = (std::min)(smallest, sizing[i]);
      largest = (std::max)(largest, sizing[i]);
    }
  return largest > 0 ? largest / smallest : 1.;
}

/// g for the values `f` and the scales `sizing` (already divided by their median) of n
/// vertices joined by `edges`, divided by that median.
template <int D>
std::vector<std::array<double, D>> scaled_differential(const std::vector<std::array<double, D>>& f,
                                                       const std::vector<double>& sizing,
                                                       const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                                                       const Progress& progress)
{
  const std::size_t n = f.size();
  const Graph_laplacian graph = scaled_edge_graph(n, edges, sizing);
  std::optional<Aggregation_multigrid> multigrid;
  if(span_of_field(graph, sizing) <= multigrid_largest_span)
    multigrid.emplace(graph);
  std::vector<std::array<double, D>> g(f);
  std::vector<double> b(n), displacement(n);
  for(int q = 0; q < D; ++q) {
    for(std::size_t i = 0; i < n; ++i) {
      double sum = 0;
      for(std::size_t k = graph.first[i]; k < graph.first[i + 1]; ++k) {
        const std::size_t j = graph.neighbour[k];
        sum += graph.weight[k] * (edge_scale(sizing, i, j) - 1) * (f[i][q] - f[j][q]);
      }
      b[i] = sum;
    }
    std::fill(displacement.begin(), displacement.end(), 0.);
    int iterations = 0;
    if(!multigrid || !solve_scaled_coordinate(graph, *multigrid, b, displacement, progress,
                                              maximum_multigrid_iterations, iterations)) {
      std::fill(displacement.begin(), displacement.end(), 0.);
      Diagonal_preconditioner diagonal{graph};
      solve_scaled_coordinate(graph, diagonal, b, displacement, progress, maximum_sizing_solve_iterations, iterations);
    }
    for(std::size_t i = 0; i < n; ++i)
      g[i][q] += displacement[i];
  }
  return g;
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_SCALED_DIFFERENTIAL_H
