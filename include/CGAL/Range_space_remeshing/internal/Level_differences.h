// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_LEVEL_DIFFERENCES_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_LEVEL_DIFFERENCES_H

// The tracer asks, at every face of the scan and at every step of an arc, in which
// axes the lattice levels of two or three points differ: D integer comparisons.
// Written as a plain loop, GCC keeps the reference levels of an arc in scalar
// registers and compares one axis at a time (about 7 instructions an axis); with
// 4-lane vectors it takes about half as many at D = 9. The scalar loop is the
// definition, the vector one an equivalent for compilers with GCC's vector
// extensions (GCC, Clang); the tests check that they agree.

#include <array>
#include <cstdint>
#include <cstring>

#if(defined(__GNUC__) || defined(__clang__)) && !defined(CGAL_RANGE_SPACE_REMESHING_NO_VECTOR_EXTENSIONS)
#define CGAL_RANGE_SPACE_REMESHING_VECTOR_EXTENSIONS 1
#endif

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// Nonzero if and only if mask[l] != 0 and a[l] != ref[l] or b[l] != ref[l]: the term of
/// one axis, shared by the reduction, the bit masks and the vector version's tail.
template <std::size_t D>
inline std::int32_t masked_difference_in_axis(const std::array<std::int32_t, D>& a,
                                              const std::array<std::int32_t, D>& b,
                                              const std::array<std::int32_t, D>& ref,
                                              const std::array<std::int32_t, D>& mask, std::size_t l)
{
  return ((a[l] ^ ref[l]) | (b[l] ^ ref[l])) & mask[l];
}

/// The axes l, as bits 1 << l, where mask[l] != 0 and a[l] != ref[l] or b[l] != ref[l].
template <std::size_t D>
std::uint32_t masked_level_differences_scalar(const std::array<std::int32_t, D>& a,
                                              const std::array<std::int32_t, D>& b,
                                              const std::array<std::int32_t, D>& ref,
                                              const std::array<std::int32_t, D>& mask)
{
  static_assert(D <= 32, "one bit per axis");
  // The tracer's common answer is none: one reduction tells it, without the shifts.
  std::int32_t differ = 0;
  for(std::size_t l = 0; l < D; ++l)
    differ |= masked_difference_in_axis(a, b, ref, mask, l);
  if(differ == 0)
    return 0;
  std::uint32_t axes = 0;
  for(std::size_t l = 0; l < D; ++l)
    axes |= std::uint32_t(masked_difference_in_axis(a, b, ref, mask, l) != 0) << l;
  return axes;
}

#ifdef CGAL_RANGE_SPACE_REMESHING_VECTOR_EXTENSIONS
typedef std::int32_t Four_levels __attribute__((vector_size(16)));
typedef std::uint32_t Four_bits __attribute__((vector_size(16)));

inline Four_levels load_four_levels(const std::int32_t* p)
{
  Four_levels v;
  std::memcpy(&v, p, sizeof v); // unaligned load
  return v;
}

/// masked_level_differences_scalar(), four axes at a time.
template <std::size_t D>
std::uint32_t masked_level_differences_vector(const std::array<std::int32_t, D>& a,
                                              const std::array<std::int32_t, D>& b,
                                              const std::array<std::int32_t, D>& ref,
                                              const std::array<std::int32_t, D>& mask)
{
  static_assert(D <= 32, "one bit per axis");
  Four_bits lanes = {0, 0, 0, 0};
  Four_bits bits = {1, 2, 4, 8}; // the bits of axes l to l + 3
  std::size_t l = 0;
  for(; l + 4 <= D; l += 4, bits <<= 4) {
    const Four_levels r = load_four_levels(&ref[l]);
    const Four_levels differ =
        ((load_four_levels(&a[l]) ^ r) | (load_four_levels(&b[l]) ^ r)) & load_four_levels(&mask[l]);
    lanes |= Four_bits(differ != 0) & bits; // a comparison gives all ones in the lanes where it holds
  }
  std::uint32_t axes = lanes[0] | lanes[1] | lanes[2] | lanes[3];
  for(; l < D; ++l)
    axes |= std::uint32_t(masked_difference_in_axis(a, b, ref, mask, l) != 0) << l;
  return axes;
}
#endif

/// The axes l, as bits 1 << l, where mask[l] != 0 and a[l] != ref[l] or b[l] != ref[l].
template <std::size_t D>
std::uint32_t masked_level_differences(const std::array<std::int32_t, D>& a,
                                       const std::array<std::int32_t, D>& b,
                                       const std::array<std::int32_t, D>& ref,
                                       const std::array<std::int32_t, D>& mask)
{
#ifdef CGAL_RANGE_SPACE_REMESHING_VECTOR_EXTENSIONS
  if(D >= 4)
    return masked_level_differences_vector(a, b, ref, mask);
#endif
  return masked_level_differences_scalar(a, b, ref, mask);
}

/// The axes l, as bits 1 << l, where a[l] != ref[l] or b[l] != ref[l].
template <std::size_t D>
std::uint32_t level_differences(const std::array<std::int32_t, D>& a, const std::array<std::int32_t, D>& b,
                                const std::array<std::int32_t, D>& ref)
{
  std::array<std::int32_t, D> every_axis{};
  for(std::int32_t& m : every_axis)
    m = -1;
  return masked_level_differences(a, b, ref, every_axis);
}

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_LEVEL_DIFFERENCES_H
