// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_TABLE_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_TABLE_H

// Intersection vertices keyed by (input triangle, grid edge): an open-addressing
// table of vertex ids with linear probing. The keys live in the vertex records,
// so the table holds only 32-bit ids; a slot costs 4 bytes.

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

struct Vertex_key
{
  std::uint32_t face_id;
  std::int8_t i, j;
  std::int32_t k, m;

  Vertex_key(std::uint32_t f, int i_, int j_, std::int32_t k_, std::int32_t m_)
    : face_id(f), i(std::int8_t(i_)), j(std::int8_t(j_)), k(k_), m(m_)
  {}

  friend bool operator==(const Vertex_key& a, const Vertex_key& b)
  {
    return a.face_id == b.face_id && a.i == b.i && a.j == b.j && a.k == b.k && a.m == b.m;
  }

  std::uint64_t hash() const
  {
    std::uint64_t x = (std::uint64_t(face_id) << 8) ^ (std::uint64_t(std::uint8_t(i)) << 4) ^
                      std::uint64_t(std::uint8_t(j));
    x ^= (std::uint64_t(std::uint32_t(k)) << 32) ^ (std::uint64_t(std::uint32_t(m)) * 0x9E3779B1u);
    // splitmix64 finaliser
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  }
};

class Vertex_table
{
  static constexpr std::uint32_t empty = std::uint32_t(-1);

public:
  /// `expected` : an estimate of the number of ids, to avoid rehashing while growing.
  explicit Vertex_table(std::size_t expected = 512)
  {
    std::size_t capacity = 1024;
    while(capacity < 2 * expected)
      capacity *= 2;
    slots_.assign(capacity, empty);
  }

  /// Id stored under `key`, or `empty` (= uint32 max).
  template <class KeyOfId>
  std::uint32_t find(const Vertex_key& key, const KeyOfId& key_of) const
  {
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t s = key.hash() & mask;; s = (s + 1) & mask) {
      const std::uint32_t id = slots_[s];
      if(id == empty || key_of(id) == key)
        return id;
    }
  }

  /// Id stored under `key`; if there is none, stores `new_id` and sets `inserted`.
  template <class KeyOfId>
  std::uint32_t find_or_insert(const Vertex_key& key, std::uint32_t new_id,
                               const KeyOfId& key_of, bool& inserted)
  {
    if(2 * (size_ + 1) > slots_.size())
      grow(key_of);
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t s = key.hash() & mask;; s = (s + 1) & mask) {
      const std::uint32_t id = slots_[s];
      if(id == empty) {
        slots_[s] = new_id;
        ++size_;
        inserted = true;
        return new_id;
      }
      if(key_of(id) == key) {
        inserted = false;
        return id;
      }
    }
  }

private:
  template <class KeyOfId>
  void grow(const KeyOfId& key_of)
  {
    std::vector<std::uint32_t> old(2 * slots_.size(), empty);
    old.swap(slots_);
    const std::size_t mask = slots_.size() - 1;
    for(std::uint32_t id : old) {
      if(id == empty)
        continue;
      std::size_t s = key_of(id).hash() & mask;
      while(slots_[s] != empty)
        s = (s + 1) & mask;
      slots_[s] = id;
    }
  }

  std::vector<std::uint32_t> slots_;
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_VERTEX_TABLE_H
