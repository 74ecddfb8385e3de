// SPDX-License-Identifier: MIT
// A 64-byte aligned allocator, so population arrays start on cache lines (streaming stores need it).
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace hs::resolved {

template <typename T>
struct AlignedAllocator {
  using value_type = T;
  static constexpr std::align_val_t alignment{64};

  AlignedAllocator() = default;
  template <typename U>
  explicit AlignedAllocator(const AlignedAllocator<U>& /*other*/) {}

  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), alignment)); }
  void deallocate(T* p, std::size_t /*n*/) { ::operator delete(p, alignment); }
  friend bool operator==(const AlignedAllocator&, const AlignedAllocator&) { return true; }
};

/// Population storage: cache-line aligned.
using AlignedDoubles = std::vector<double, AlignedAllocator<double>>;

}  // namespace hs::resolved
