// SPDX-License-Identifier: MIT
// A 64-byte aligned allocator, so population arrays start on cache lines (streaming stores need it); large arrays
// are 2 MiB aligned and advised to use transparent huge pages.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace hs::resolved {

template <typename T>
struct AlignedAllocator {
  using value_type = T;
  static constexpr std::align_val_t alignment{64};
  /// Arrays of at least one x86-64 huge page are aligned to it and advised MADV_HUGEPAGE: the kernels stream 19-38
  /// arrays at once, and 4 KiB pages cost TLB misses on every one (where THP is "madvise", the Debian default, the
  /// advice is what turns huge pages on; where THP is off it is ignored).
  static constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

  AlignedAllocator() = default;
  template <typename U>
  explicit AlignedAllocator(const AlignedAllocator<U>& /*other*/) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_page_bytes) return static_cast<T*>(::operator new(bytes, alignment));
    void* p = ::operator new(bytes, std::align_val_t{huge_page_bytes});
#if defined(__linux__)
    madvise(p, bytes / huge_page_bytes * huge_page_bytes, MADV_HUGEPAGE);   // advisory: failure changes nothing
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    ::operator delete(p, n * sizeof(T) < huge_page_bytes ? alignment : std::align_val_t{huge_page_bytes});
  }
  friend bool operator==(const AlignedAllocator&, const AlignedAllocator&) { return true; }
};

/// Population storage: cache-line aligned.
using AlignedDoubles = std::vector<double, AlignedAllocator<double>>;

}  // namespace hs::resolved
