// Memory on transparent huge pages (2 MiB) for large structures that queries read at random
// places: the shortest path map's trapezoids, staircases, points and point-location nodes. A query touches a dozen
// places in up to a gigabyte; with 4 KiB pages nearly each of them also misses the TLB. Linux
// gives huge pages to memory that asks for them (madvise) when THP is in "madvise" mode, as on
// Debian by default; elsewhere the advice is ignored and the memory is ordinary.
//
// Measured (bench_spm, 10^6 vertices, 100,000 random queries, one run each, same machine):
// see the README's shortest path map table.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>

namespace taut::router::detail {

inline constexpr std::size_t kHugePage = std::size_t{2} << 20;

// At least `bytes` bytes, aligned to and rounded up to huge pages, advised as huge-page backed
// before anything touches them. Free with std::free.
inline void* huge_page_alloc(std::size_t bytes) {
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  (void)madvise(p, rounded, MADV_HUGEPAGE);  // advice only: if refused, the pages stay ordinary
#endif
  return p;
}

// For std::vector: blocks of a huge page or more on huge pages, smaller ones from operator new.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    if (n * sizeof(T) < kHugePage) return std::allocator<T>{}.allocate(n);
    return static_cast<T*>(huge_page_alloc(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePage) std::allocator<T>{}.deallocate(p, n);
    else std::free(p);
  }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
};

}  // namespace taut::router::detail
