// Memory on transparent huge pages (2 MiB) for large structures that queries read at random
// places: the shortest path map's trapezoids, staircases and R-tree. A query touches a dozen
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
#include <memory_resource>
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

// Upstream of a std::pmr::monotonic_buffer_resource that holds many small nodes (an R-tree's):
// its large chunks go on huge pages. Counts the bytes it hands out.
class HugePageResource : public std::pmr::memory_resource {
 public:
  std::size_t bytes() const { return bytes_; }

 private:
  void* do_allocate(std::size_t bytes, std::size_t align) override {
    bytes_ += bytes;
    if (bytes < kHugePage || align > kHugePage) return ::operator new(bytes, std::align_val_t{align});
    return huge_page_alloc(bytes);
  }
  void do_deallocate(void* p, std::size_t bytes, std::size_t align) override {
    bytes_ -= bytes;
    if (bytes < kHugePage || align > kHugePage) ::operator delete(p, bytes, std::align_val_t{align});
    else std::free(p);
  }
  bool do_is_equal(const std::pmr::memory_resource& o) const noexcept override { return this == &o; }
  std::size_t bytes_ = 0;
};

}  // namespace taut::router::detail
