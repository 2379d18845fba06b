// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_AGGREGATION_MULTIGRID_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_AGGREGATION_MULTIGRID_H

// The preconditioner of the sizing field's solve (Scaled_differential.h): one V-cycle
// of aggregation multigrid on the weighted Laplacian of the input's edge graph.
//
// Preconditioned by its diagonal alone, conjugate gradients on a mesh Laplacian need
// iterations in proportion to the mesh's diameter in edges (about the square root of
// its vertex count), each costing a pass over the edges: the solve then grows as
// n^1.5. A multilevel preconditioner removes the smooth part of the error on coarser
// graphs, where it is no longer smooth, and keeps the iterations about constant.
//
// Coarsening by aggregation: the vertices are grouped into small connected aggregates
// (a vertex with its strongly coupled neighbours), each a vertex of the next graph,
// the weights between two aggregates summed. With the prolongation that copies an
// aggregate's value to its vertices, that coarse graph's Laplacian is exactly P^T L P
// (a Laplacian again: its rows sum to 0), so each level is built like the first and
// the kernel of constants is kept on every level. Smoothing: a Gauss-Seidel sweep
// forward before the coarse correction and one backward after, so the cycle is a
// symmetric positive semi-definite operator, as conjugate gradients need. On the
// coarsest graph (a few hundred vertices) sweeps stand in for an exact solve: the
// cycle only preconditions.
//
// Hand-written, as the solve it serves: the library depends on CGAL, Boost, GMP and
// MPFR only, and the algebraic multigrid packages need more.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// The Laplacian L of a graph with positive edge weights, by adjacency lists
/// (compressed rows): (L x)_i = d_i x_i - sum over the neighbours j of w_ij x_j, d_i
/// the sum of the weights at i.
struct Graph_laplacian
{
  std::vector<std::size_t> first; // neighbours of i: first[i] .. first[i + 1]
  std::vector<std::size_t> neighbour;
  std::vector<double> weight;
  std::vector<double> diagonal;

  std::size_t size() const { return diagonal.size(); }

  /// Whether vertex i has no neighbour (a removed vertex of the mesh): no equation.
  bool isolated(std::size_t i) const { return first[i] == first[i + 1]; }

  /// y = L x
  void multiply(const std::vector<double>& x, std::vector<double>& y) const
  {
    for(std::size_t i = 0; i < size(); ++i) {
      double sum = diagonal[i] * x[i];
      for(std::size_t k = first[i]; k < first[i + 1]; ++k)
        sum -= weight[k] * x[neighbour[k]];
      y[i] = sum;
    }
  }

  /// One Gauss-Seidel step on row i of L x = b.
  void relax_row(std::size_t i, const std::vector<double>& b, std::vector<double>& x) const
  {
    if(!(diagonal[i] > 0))
      return; // an isolated vertex: no equation
    double sum = b[i];
    for(std::size_t k = first[i]; k < first[i + 1]; ++k)
      sum += weight[k] * x[neighbour[k]];
    x[i] = sum / diagonal[i];
  }

  void sweep_forward(const std::vector<double>& b, std::vector<double>& x) const
  {
    for(std::size_t i = 0; i < size(); ++i)
      relax_row(i, b, x);
  }

  void sweep_backward(const std::vector<double>& b, std::vector<double>& x) const
  {
    for(std::size_t i = size(); i-- > 0;)
      relax_row(i, b, x);
  }
};

// no aggregate: a vertex without neighbours (a removed vertex of the mesh, an isolated
// one), whose equation is empty and which must not hold the coarsening back
constexpr std::size_t no_aggregate = (std::numeric_limits<std::size_t>::max)();

/// Groups the vertices of `graph` into connected aggregates: `aggregate[i]` is the
/// aggregate of vertex i, or `no_aggregate` for a vertex without neighbours; returns
/// their number. A neighbour is strong when its weight is at least `strength` times
/// the largest at the vertex (the others would be smoothed apart by the Gauss-Seidel
/// sweeps anyway).
inline std::size_t aggregate_vertices(const Graph_laplacian& graph, std::vector<std::size_t>& aggregate)
{
  constexpr double strength = 0.25;
  constexpr std::size_t none = no_aggregate;
  const std::size_t n = graph.size();
  aggregate.assign(n, none);
  std::vector<double> strongest(n, 0.);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = graph.first[i]; k < graph.first[i + 1]; ++k)
      strongest[i] = (std::max)(strongest[i], graph.weight[k]);
  auto strong = [&](std::size_t i, std::size_t k) { return graph.weight[k] >= strength * strongest[i]; };
  std::size_t count = 0;
  // a vertex whose strong neighbours are all free: it and they
  for(std::size_t i = 0; i < n; ++i) {
    if(aggregate[i] != none || graph.isolated(i))
      continue;
    bool free = true;
    for(std::size_t k = graph.first[i]; k < graph.first[i + 1] && free; ++k)
      free = !strong(i, k) || aggregate[graph.neighbour[k]] == none;
    if(!free)
      continue;
    aggregate[i] = count;
    for(std::size_t k = graph.first[i]; k < graph.first[i + 1]; ++k)
      if(strong(i, k))
        aggregate[graph.neighbour[k]] = count;
    ++count;
  }
  // the rest: into the aggregate of the strongest neighbour that has one, else alone
  std::vector<std::size_t> joined(aggregate);
  for(std::size_t i = 0; i < n; ++i) {
    if(aggregate[i] != none || graph.isolated(i))
      continue;
    double best = 0;
    for(std::size_t k = graph.first[i]; k < graph.first[i + 1]; ++k)
      if(aggregate[graph.neighbour[k]] != none && graph.weight[k] > best) {
        best = graph.weight[k];
        joined[i] = aggregate[graph.neighbour[k]];
      }
    if(joined[i] == none)
      joined[i] = count++;
  }
  aggregate.swap(joined);
  return count;
}

/// P^T L P for the prolongation P that copies each aggregate's value to its vertices:
/// the graph of the aggregates, the weights between two of them summed.
inline Graph_laplacian coarse_laplacian(const Graph_laplacian& graph, const std::vector<std::size_t>& aggregate,
                                        std::size_t count)
{
  std::vector<std::vector<std::size_t>> members(count);
  for(std::size_t i = 0; i < graph.size(); ++i)
    if(aggregate[i] != no_aggregate)
      members[aggregate[i]].push_back(i);
  Graph_laplacian coarse;
  coarse.first.assign(1, 0);
  coarse.diagonal.assign(count, 0.);
  constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> slot(count, none); // where aggregate J is in the row being built
  for(std::size_t a = 0; a < count; ++a) {
    const std::size_t row = coarse.neighbour.size();
    for(std::size_t i : members[a])
      for(std::size_t k = graph.first[i]; k < graph.first[i + 1]; ++k) {
        const std::size_t b = aggregate[graph.neighbour[k]];
        if(b == a)
          continue;
        if(slot[b] == none) {
          slot[b] = coarse.neighbour.size();
          coarse.neighbour.push_back(b);
          coarse.weight.push_back(0.);
        }
        coarse.weight[slot[b]] += graph.weight[k];
        coarse.diagonal[a] += graph.weight[k];
      }
    for(std::size_t k = row; k < coarse.neighbour.size(); ++k)
      slot[coarse.neighbour[k]] = none;
    coarse.first.push_back(coarse.neighbour.size());
  }
  return coarse;
}

/// z = B r, B one V-cycle from z = 0 on the hierarchy of aggregated graphs.
class Aggregation_multigrid
{
public:
  // coarsening stops at this many vertices, or when a level shrinks too little
  static constexpr std::size_t coarsest_size = 200;
  static constexpr double least_shrink = 0.8;
  // sweeps forward and backward standing in for the coarsest solve
  static constexpr int coarsest_sweeps = 20;
  // The coarse correction, scaled: an aggregate's constant value undershoots a smooth
  // error (which bends inside the aggregate), more so the more levels there are, and
  // scaling the correction up makes up most of it: the classic remedy for unsmoothed
  // aggregation, cheaper than smoothing the prolongation (which would fill the coarse
  // graphs). The value is the one that needed the fewest iterations on CGAL's meshes
  // (benchmark/RESULTS.md).
  static constexpr double over_correction = 1.8;

  explicit Aggregation_multigrid(const Graph_laplacian& finest) : finest_(finest)
  {
    const Graph_laplacian* graph = &finest_;
    while(graph->size() > coarsest_size) {
      Level level;
      const std::size_t count = aggregate_vertices(*graph, level.aggregate);
      if(double(count) > least_shrink * double(graph->size() - isolated_vertices(*graph)))
        break;
      level.coarse = coarse_laplacian(*graph, level.aggregate, count);
      levels_.push_back(std::move(level));
      graph = &levels_.back().coarse;
    }
    // the vectors of each coarse level, made once
    for(Level& level : levels_) {
      level.b.assign(level.coarse.size(), 0.);
      level.x.assign(level.coarse.size(), 0.);
    }
  }

  // it keeps a reference to the graph
  explicit Aggregation_multigrid(Graph_laplacian&&) = delete;

  std::size_t levels() const { return levels_.size() + 1; }

  void apply(const std::vector<double>& r, std::vector<double>& z)
  {
    std::fill(z.begin(), z.end(), 0.);
    cycle(0, finest_, r, z);
  }

private:
  struct Level
  {
    std::vector<std::size_t> aggregate; // of the graph above
    Graph_laplacian coarse;
    std::vector<double> b, x;
  };

  static std::size_t isolated_vertices(const Graph_laplacian& graph)
  {
    std::size_t count = 0;
    for(std::size_t i = 0; i < graph.size(); ++i)
      count += graph.isolated(i);
    return count;
  }

  // x from 0 towards the solution of L x = b on the graph of level `depth`
  void cycle(std::size_t depth, const Graph_laplacian& graph, const std::vector<double>& b, std::vector<double>& x)
  {
    if(depth == levels_.size()) {
      for(int sweep = 0; sweep < coarsest_sweeps; ++sweep) {
        graph.sweep_forward(b, x);
        graph.sweep_backward(b, x);
      }
      return;
    }
    Level& level = levels_[depth];
    graph.sweep_forward(b, x);
    residual_.resize(graph.size());
    graph.multiply(x, residual_);
    std::fill(level.b.begin(), level.b.end(), 0.);
    for(std::size_t i = 0; i < graph.size(); ++i)
      if(level.aggregate[i] != no_aggregate)
        level.b[level.aggregate[i]] += b[i] - residual_[i];
    std::fill(level.x.begin(), level.x.end(), 0.);
    cycle(depth + 1, level.coarse, level.b, level.x);
    for(std::size_t i = 0; i < graph.size(); ++i)
      if(level.aggregate[i] != no_aggregate)
        x[i] += over_correction * level.x[level.aggregate[i]];
    graph.sweep_backward(b, x);
  }

  const Graph_laplacian& finest_;
  std::vector<Level> levels_;
  std::vector<double> residual_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_AGGREGATION_MULTIGRID_H
