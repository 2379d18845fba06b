// The perturbed predicates against a brute-force reference: exact rationals with
// explicit eps-coefficients. Inputs are snapped to a coarse lattice of halves so
// that ties (which the perturbation decides) are the rule, not the exception.
// Also the tracer's comparisons of lattice levels, scalar and vector, against their
// definition axis by axis.
#include <CGAL/Range_space_remeshing/Range_space_traits.h>
#include <CGAL/Range_space_remeshing/internal/Level_differences.h>
#include <CGAL/Range_space_remeshing/internal/Perturbed_predicates.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>

namespace RSR = CGAL::Range_space_remeshing;

constexpr int D = 5;
using Q = CGAL::Exact_rational;
using Point = std::array<double, D>;

// value + sum_q coefficient[q] * eps_q, eps_0 >> eps_1 >> ...
struct Linear_form
{
  std::array<Q, D + 1> c; // c[0]: value, c[1 + q]: coefficient of eps_q

  static Linear_form constant(const Q& v) { Linear_form f; f.c[0] = v; return f; }
  static Linear_form lattice(double level, int axis)
  {
    Linear_form f = constant(level);
    f.c[1 + axis] = 1;
    return f;
  }
  Linear_form operator+(const Linear_form& o) const { Linear_form f; for(int n = 0; n <= D; ++n) f.c[n] = c[n] + o.c[n]; return f; }
  Linear_form operator-(const Linear_form& o) const { Linear_form f; for(int n = 0; n <= D; ++n) f.c[n] = c[n] - o.c[n]; return f; }
  Linear_form operator*(const Q& s) const { Linear_form f; for(int n = 0; n <= D; ++n) f.c[n] = c[n] * s; return f; }
  int sign() const
  {
    for(const Q& x : c)
      if(x != 0)
        return x > 0 ? 1 : -1;
    return 0;
  }
};

Q cross(const Q& ux, const Q& uy, const Q& vx, const Q& vy) { return ux * vy - uy * vx; }

// (q - p) x (X - p) on axes (a1, a2), X given by linear forms
Linear_form edge_function(const Point& p, const Point& q, int a1, int a2,
                          const Linear_form& x1, const Linear_form& x2)
{
  const Q dx = Q(q[a1]) - Q(p[a1]), dy = Q(q[a2]) - Q(p[a2]);
  return (x2 - Linear_form::constant(p[a2])) * dx - (x1 - Linear_form::constant(p[a1])) * dy;
}

Q projected_area(const Point& a, const Point& b, const Point& c, int a1, int a2)
{
  return cross(Q(b[a1]) - Q(a[a1]), Q(b[a2]) - Q(a[a2]), Q(c[a1]) - Q(a[a1]), Q(c[a2]) - Q(a[a2]));
}

// barycentric coordinates (linear forms) of the point of the triangle's plane whose
// coordinates on (a1, a2) are (x1, x2); requires a non-degenerate projection
std::array<Linear_form, 3> barycentric(const Point& a, const Point& b, const Point& c,
                                       int a1, int a2, const Linear_form& x1, const Linear_form& x2)
{
  const Q o = projected_area(a, b, c, a1, a2);
  return {{edge_function(b, c, a1, a2, x1, x2) * (Q(1) / o),
           edge_function(c, a, a1, a2, x1, x2) * (Q(1) / o),
           edge_function(a, b, a1, a2, x1, x2) * (Q(1) / o)}};
}

Linear_form coordinate(const Point& a, const Point& b, const Point& c,
                       const std::array<Linear_form, 3>& w, int q)
{
  return w[0] * Q(a[q]) + w[1] * Q(b[q]) + w[2] * Q(c[q]);
}

int failures = 0;
std::size_t checks = 0, ties = 0;
#define EXPECT(cond) do { ++checks; if(!(cond)) { ++failures; if(failures < 20) std::cerr << "mismatch at line " << __LINE__ << std::endl; } } while(0)

template <class Traits>
void run(unsigned seed, int rounds)
{
  RSR::internal::Perturbed_predicates<Traits> pred;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate_dist(-3, 3), level_dist(-1, 1), axis_dist(0, D - 1);
  auto random_point = [&] {
    Point p;
    for(double& x : p) x = 0.5 * coordinate_dist(rng);
    return p;
  };
  auto distinct_axes = [&](int n) {
    std::array<int, 3> axes;
    for(int k = 0; k < n; ++k) {
      bool again;
      do {
        axes[k] = axis_dist(rng);
        again = false;
        for(int l = 0; l < k; ++l) again = again || axes[l] == axes[k];
      } while(again);
    }
    return axes;
  };

  for(int round = 0; round < rounds; ++round) {
    const Point a = random_point(), b = random_point(), c = random_point();
    const double k = level_dist(rng), m = level_dist(rng), n = level_dist(rng);

    // grid edge in triangle
    {
      auto axes = distinct_axes(2);
      const int i = std::min(axes[0], axes[1]), j = std::max(axes[0], axes[1]);
      const Q o = projected_area(a, b, c, i, j);
      int expected = 0;
      if(o != 0) {
        auto w = barycentric(a, b, c, i, j, Linear_form::lattice(k, i), Linear_form::lattice(m, j));
        if(w[0].sign() > 0 && w[1].sign() > 0 && w[2].sign() > 0)
          expected = o > 0 ? 1 : -1;
      }
      EXPECT(pred.grid_edge_orientation(a, b, c, i, j, k, m) == expected);

      // the vertex's coordinate on a third axis
      if(expected != 0) {
        int q;
        do q = axis_dist(rng); while(q == i || q == j);
        auto w = barycentric(a, b, c, i, j, Linear_form::lattice(k, i), Linear_form::lattice(m, j));
        const Linear_form diff = coordinate(a, b, c, w, q) - Linear_form::lattice(n, q);
        ties += (diff.c[0] == 0);
        EXPECT(pred.vertex_coordinate_side(a, b, c, expected, i, j, k, m, q, n) == diff.sign());
      }
    }

    // crossing of an edge with a wall, in a plane x_P = level
    {
      auto axes = distinct_axes(2);
      const int P = axes[0], l = axes[1];
      if(RSR::internal::Perturbed_predicates<Traits>::side(a[P], k) !=
         RSR::internal::Perturbed_predicates<Traits>::side(b[P], k)) {
        const Q t_den = Q(b[P]) - Q(a[P]);
        // p_l = a_l + (k + eps_P - a_P) / (b_P - a_P) * (b_l - a_l)
        const Linear_form p_l = Linear_form::constant(a[l]) +
            (Linear_form::lattice(k, P) - Linear_form::constant(a[P])) * ((Q(b[l]) - Q(a[l])) / t_den);
        const Linear_form diff = p_l - Linear_form::lattice(m, l);
        ties += (diff.c[0] == 0);
        EXPECT(pred.crossing_side(a, b, P, k, l, m) == diff.sign());
      }
    }

    // which of two walls an arc meets first
    {
      auto axes = distinct_axes(3);
      const int P = axes[0], l = axes[1], p = axes[2];
      if(projected_area(a, b, c, P, l) != 0) {
        auto w = barycentric(a, b, c, P, l, Linear_form::lattice(k, P), Linear_form::lattice(m, l));
        const Linear_form diff = coordinate(a, b, c, w, p) - Linear_form::lattice(n, p);
        ties += (diff.c[0] == 0);
        for(int up : {-1, 1})
          EXPECT(pred.is_met_first(a, b, c, P, k, l, m, p, n, up) == (diff.sign() == -up));
      }
    }
  }
}

// masked_level_differences() (scalar, vector) and level_differences() against the
// definition written axis by axis, on levels drawn from {-1, 0, 1} so that equal and
// different axes are both common.
template <std::size_t N>
int check_level_differences(std::mt19937& rng)
{
  using Levels = std::array<std::int32_t, N>;
  std::uniform_int_distribution<int> level(-1, 1), coin(0, 1);
  int mismatches = 0;
  for(int trial = 0; trial < 20000; ++trial) {
    Levels a, b, ref, mask;
    for(std::size_t l = 0; l < N; ++l) {
      ref[l] = level(rng);
      // mostly equal to ref, as in the tracer, and sometimes far from it
      a[l] = coin(rng) && coin(rng) ? ref[l] + level(rng) * (1 << 28) : ref[l];
      b[l] = coin(rng) && coin(rng) ? level(rng) : ref[l];
      mask[l] = coin(rng) || coin(rng) ? -1 : 0;
    }
    std::uint32_t expected_masked = 0, expected_all = 0;
    for(std::size_t l = 0; l < N; ++l)
      if(a[l] != ref[l] || b[l] != ref[l]) {
        expected_all |= std::uint32_t(1) << l;
        if(mask[l] != 0)
          expected_masked |= std::uint32_t(1) << l;
      }
    std::array<std::uint32_t, 2> masked{{RSR::internal::masked_level_differences(a, b, ref, mask),
                                         RSR::internal::masked_level_differences_scalar(a, b, ref, mask)}};
#ifdef CGAL_RANGE_SPACE_REMESHING_VECTOR_EXTENSIONS
    masked[0] = RSR::internal::masked_level_differences_vector(a, b, ref, mask);
#endif
    const std::uint32_t all = RSR::internal::level_differences(a, b, ref);
    for(int version = 0; version < 2; ++version)
      if(masked[version] != expected_masked && mismatches++ < 5)
        std::cerr << "masked level differences, " << N << " axes, " << (version == 0 ? "vector" : "scalar")
                  << " version: " << masked[version] << " instead of " << expected_masked << std::endl;
    if(all != expected_all && mismatches++ < 5)
      std::cerr << "level differences, " << N << " axes: " << all << " instead of " << expected_all << std::endl;
  }
  return mismatches;
}

int main()
{
  std::mt19937 level_rng(7);
  const int level_mismatches = check_level_differences<1>(level_rng) + check_level_differences<3>(level_rng) +
                               check_level_differences<4>(level_rng) + check_level_differences<6>(level_rng) +
                               check_level_differences<9>(level_rng) + check_level_differences<32>(level_rng);
  std::cout << "level differences: " << level_mismatches << " mismatches" << std::endl;
  run<RSR::Range_space_traits<D>>(1, 60000);
  run<RSR::Range_space_traits<D, CGAL::Exact_predicates_exact_constructions_kernel>>(2, 5000);
  std::cout << checks << " predicate evaluations compared, " << ties
            << " of them unperturbed ties; " << failures << " mismatches" << std::endl;
  return failures == 0 && ties > 1000 && level_mismatches == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
