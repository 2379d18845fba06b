// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_OUTPUT_SIZE_CAP_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_OUTPUT_SIZE_CAP_H

// The cap on the number of output vertices. A too small cell size is refused as early
// as possible: before anything is built, by an estimate of the output size (the
// number of lattice points in a projected triangle is about its area); before a face
// is scanned, if it alone crosses more levels than the cap; and, at the latest, when
// the intersection vertices reach the cap.

#include <CGAL/Range_space_remeshing/Remeshing_error.h>
#include <CGAL/Range_space_remeshing/internal/Mapped_input.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

// The sequential complete scan estimates the output size (a pass over all faces)
// only once a bound of the vertices it builds reaches this many: below, building them
// costs less than the estimate would on every run.
constexpr double vertices_built_before_estimate = 1 << 20;

class Output_size_cap
{
public:
  explicit Output_size_cap(std::size_t maximum_vertices) : maximum_(maximum_vertices) {}

  double maximum() const { return double(maximum_); }

  /// Throws once the intersection vertices reach the cap.
  void refuse_if_reached(std::size_t number_of_vertices) const
  {
    if(number_of_vertices >= maximum_)
      throw Remeshing_error("the output would exceed the cap of " + std::to_string(maximum_) +
                            " vertices: the cell size is too small for this input",
                            Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  }

  /// A face crossing more levels than the output may have vertices: its scan alone would
  /// take a loop per crossed level, and a needle of a face across the whole lattice
  /// (2^30 levels per axis, nearly no area, so no large estimate) would run for minutes.
  void refuse_if_too_many_crossings(std::int64_t hyperplanes, std::uint32_t face_id) const
  {
    if(hyperplanes > std::int64_t(maximum_))
      throw_error<Remeshing_error>([&] {
        return "face " + std::to_string(face_id) + " crosses " + std::to_string(hyperplanes) +
               " grid hyperplanes, more than the cap of " + std::to_string(maximum_) +
               " vertices: the cell size is too small for this input";
      }, Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  }

  /// Refuses an output whose `expected_number_of_vertices()` exceeds the cap, before
  /// it is built. The estimate is made only when the sum of `expected_vertices_bound()`
  /// may reach the cap.
  template <class Input>
  void refuse_too_large_output(Input& input) const
  {
    double bound = 0;
    for(auto f : faces(input.mesh()))
      bound += expected_vertices_bound<Input::D>(input.load_face(f));
    if(bound_may_reach(bound, maximum()))
      refuse_if_expected_above(input, maximum());
  }

  /// Throws the error that says the output would exceed `cap` if
  /// `expected_number_of_vertices()` does.
  template <class Input>
  static void refuse_if_expected_above(Input& input, double cap)
  {
    const double expected = expected_number_of_vertices(input);
    if(expected > cap)
      throw Remeshing_error("the output would have about " + std::to_string(std::llround(expected)) +
                            " vertices, more than the cap of " + std::to_string(std::llround(cap)) +
                            ": the cell size is too small for this input",
                            Remeshing_error::Kind::OUTPUT_TOO_LARGE);
  }

  /// Expected number of intersection vertices: the sum of the projected areas of the
  /// faces over all axis pairs.
  template <class Input>
  static double expected_number_of_vertices(Input& input)
  {
    constexpr int D = Input::D;
    double expected = 0;
    for(auto f : faces(input.mesh())) {
      const auto t = input.load_face(f);
      const auto &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
      for(int i = 0; i < D; ++i)
        for(int j = i + 1; j < D; ++j)
          expected += 0.5 * std::abs((b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]));
    }
    return expected;
  }

  /// An upper bound of the face's term of `expected_number_of_vertices()`, in O(D)
  /// instead of O(D^2): with B = b - a, C = c - a, each term |B_i C_j - B_j C_i| <=
  /// |B_i| |C_j| + |B_j| |C_i|, so the sum over i < j is at most (sum |B_i|) (sum |C_j|).
  template <int D, class Triangle>
  static double expected_vertices_bound(const Triangle& t)
  {
    const auto &a = *t.p[0], &b = *t.p[1], &c = *t.p[2];
    double sum_b = 0, sum_c = 0;
    for(int q = 0; q < D; ++q) {
      sum_b += std::abs(b[q] - a[q]);
      sum_c += std::abs(c[q] - a[q]);
    }
    return 0.5 * sum_b * sum_c;
  }

  /// An upper bound of the vertices the scan of a triangle creates: one per grid edge
  /// {x_i = k, x_j = m} of crossed levels, at most (sum of the crossed levels)^2 / 2.
  static double vertices_bound(std::int64_t hyperplanes) { return 0.5 * double(hyperplanes) * double(hyperplanes); }

  /// Whether a sum of bounds (`expected_vertices_bound()`, `vertices_bound()`) may
  /// reach `level`, with a wide margin for the rounding of the sum and of the estimate.
  static bool bound_may_reach(double bound, double level) { return 1.01 * bound >= level; }

private:
  std::size_t maximum_;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_OUTPUT_SIZE_CAP_H
