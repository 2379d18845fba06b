// Copyright (c) 2026 Range_space_remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : Range_space_remeshing team

#ifndef CGAL_RANGE_SPACE_REMESHING_INTERNAL_LAZILY_ZEROED_ARRAY_H
#define CGAL_RANGE_SPACE_REMESHING_INTERNAL_LAZILY_ZEROED_ARRAY_H

// Arrays by input vertex or face, which a seeded traversal touches only in part. A
// std::vector<T>(n) writes all n entries, which makes every run linear in the input
// however few of its faces the arcs cross. Memory fresh from the system is zero and
// costs nothing until a page of it is touched; but the traversal's entries are spread
// over the whole index range, so that a small share of the faces touches nearly
// every 4 KB page of the face records, each a page fault. Large arrays are therefore
// mapped with transparent huge pages where Linux offers them (2 MB, zeroed by the
// kernel at about memset speed). Smaller ones stay with malloc / calloc. (The
// measurements behind this: benchmark/RESULTS.md.)

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Range_space_remeshing {
namespace internal {

/// n entries of a trivially copyable T that a run writes before it reads them, or,
/// if `zeroed`, whose bytes are all zero until written (0, false, a null handle).
template <class T, bool zeroed = true>
class Lazily_zeroed_array
{
  static_assert(std::is_trivially_copyable<T>::value, "Lazily_zeroed_array: T must be trivially copyable");
  // Below this, malloc or calloc. glibc maps blocks above its own threshold (at most
  // 32 MB) afresh on every call, and serves smaller ones from its heap, where repeated
  // runs (an animation, a benchmark) find the memory the last run freed, unless glibc
  // gave it back to the system meanwhile, which depends on the program's other
  // allocations (see the manual's paragraph on repeated runs).
  static constexpr std::size_t huge_page = std::size_t(2) << 20, mapped_from = std::size_t(32) << 20;

  struct Release
  {
    std::size_t mapped_bytes = 0; // 0: from malloc or calloc
    void operator()(T* p) const
    {
#if defined(__linux__)
      if(mapped_bytes > 0) {
        munmap(p, mapped_bytes);
        return;
      }
#endif
      std::free(p);
    }
  };

public:
  Lazily_zeroed_array() = default;
  explicit Lazily_zeroed_array(std::size_t n) : size_(n)
  {
    const std::size_t bytes = (n == 0 ? 1 : n) * sizeof(T);
    void* p = nullptr;
#if defined(__linux__)
    if(bytes >= mapped_from) {
      const std::size_t mapped_bytes = (bytes + huge_page - 1) / huge_page * huge_page;
      p = mmap(nullptr, mapped_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if(p == MAP_FAILED)
        throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
      madvise(p, mapped_bytes, MADV_HUGEPAGE); // a hint: without it, 4 KB pages
#endif
      data_ = std::unique_ptr<T, Release>(static_cast<T*>(p), Release{mapped_bytes});
      return;
    }
#endif
    p = zeroed ? std::calloc(1, bytes) : std::malloc(bytes);
    if(p == nullptr)
      throw std::bad_alloc();
    data_ = std::unique_ptr<T, Release>(static_cast<T*>(p), Release{});
  }

  Lazily_zeroed_array(Lazily_zeroed_array&& other) noexcept
    : data_(std::move(other.data_)), size_(other.size_)
  {
    other.size_ = 0;
  }
  Lazily_zeroed_array& operator=(Lazily_zeroed_array&& other) noexcept
  {
    data_ = std::move(other.data_);
    size_ = other.size_;
    other.size_ = 0;
    return *this;
  }

  T& operator[](std::size_t i) { return data_.get()[i]; }
  const T& operator[](std::size_t i) const { return data_.get()[i]; }
  T* data() { return data_.get(); }
  T* begin() { return data_.get(); }
  T* end() { return data_.get() + size_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

private:
  std::unique_ptr<T, Release> data_;
  std::size_t size_ = 0;
};

/// Arrays of n entries, zero until written / written before they are read (not
/// zeroed below the size where the pages come from the system); a std::vector<T>(n)
/// for types that are not trivially copyable (exact points, a graph's own handles).
template <class T>
using Zeroed_array = std::conditional_t<std::is_trivially_copyable<T>::value, Lazily_zeroed_array<T, true>,
                                        std::vector<T>>;
template <class T>
using Uninitialised_array = std::conditional_t<std::is_trivially_copyable<T>::value,
                                               Lazily_zeroed_array<T, false>, std::vector<T>>;

} // namespace internal
} // namespace Range_space_remeshing
} // namespace CGAL

#endif // CGAL_RANGE_SPACE_REMESHING_INTERNAL_LAZILY_ZEROED_ARRAY_H
