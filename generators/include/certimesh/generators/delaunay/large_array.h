// The allocator of the triangulation's large arrays (points, corners, neighbours): an
// allocation of at least `huge_threshold` bytes is aligned to 2 MiB and, on Linux, advised
// as a candidate for transparent huge pages (madvise MADV_HUGEPAGE, honoured when
// /sys/kernel/mm/transparent_hugepage/enabled is `always` or `madvise`), so that first
// touching it costs one page fault per 2 MiB instead of one per 4 KiB. On the benchmark
// machine (a VM, about 16 us per 4 KiB fault) touching 128 MB took 530 ms with 4 KiB pages
// and 8-16 ms with huge pages, and the 10^6-point triangulation touches about 100 MB
// (bench/RESULTS.md). Smaller allocations, and every allocation elsewhere, go through
// std::allocator. Only where memory comes from changes: never a value, never an order.
#pragma once

#include <cstddef>
#include <memory>

namespace certimesh::generators::detail {

inline constexpr std::size_t huge_threshold = std::size_t{4} << 20;

void* allocate_large(std::size_t bytes);            // bytes >= huge_threshold
void deallocate_large(void* p, std::size_t bytes) noexcept;

template <class T>
struct LargeArrayAllocator {
  using value_type = T;
  LargeArrayAllocator() noexcept = default;
  template <class U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n >= huge_threshold / sizeof(T)) return static_cast<T*>(allocate_large(n * sizeof(T)));
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n >= huge_threshold / sizeof(T)) deallocate_large(p, n * sizeof(T));
    else std::allocator<T>().deallocate(p, n);
  }
  friend bool operator==(const LargeArrayAllocator&, const LargeArrayAllocator&) noexcept { return true; }
};

}  // namespace certimesh::generators::detail
