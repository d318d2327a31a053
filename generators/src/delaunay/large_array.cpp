#include "certimesh/generators/delaunay/large_array.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace certimesh::generators::detail {

namespace {
constexpr std::size_t huge_page = std::size_t{2} << 20;
std::size_t rounded(std::size_t bytes) { return (bytes + huge_page - 1) / huge_page * huge_page; }
}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes > std::size_t(-1) - huge_page) throw std::bad_alloc();
  const std::size_t size = rounded(bytes);
  void* p = std::aligned_alloc(huge_page, size);
  if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  (void)madvise(p, size, MADV_HUGEPAGE);  // advice only: a refusal changes nothing but speed
#endif
  return p;
}

void deallocate_large(void* p, std::size_t) noexcept { std::free(p); }

}  // namespace certimesh::generators::detail
