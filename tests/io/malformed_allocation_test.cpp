// A hostile header (a billion declared records in a tiny file) must be refused before the
// reader allocates for it. This program replaces the global operator new to record the largest
// single request and checks it stays small for every such input -- and, as a control, that the
// counter does see the allocations of a genuine large file.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>

#include "certimesh/io/format_error.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/triangle_format.h"

namespace {
std::atomic<std::size_t> largest_request{0};

void* allocate(std::size_t size) {
  std::size_t seen = largest_request.load();
  while (size > seen && !largest_request.compare_exchange_weak(seen, size)) {
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace certimesh::io {
namespace {

constexpr std::size_t kSmall = 64 * 1024;  // the inputs are < 200 bytes: nothing needs more

std::size_t largest_allocation_while_parsing(const std::string& name, const std::string& contents) {
  const std::string node = "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";
  largest_request = 0;
  try {
    if (name.ends_with(".mesh")) {
      parse_medit_format(name, contents);
    } else {
      parse_triangle_format(name, contents, [&](const std::filesystem::path& p) -> std::optional<std::string> {
        if (p.extension() == ".node") return node;
        return std::nullopt;
      });
    }
  } catch (const FormatError&) {
    return largest_request;
  }
  ADD_FAILURE() << name << " was accepted";
  return largest_request;
}

TEST(MalformedAllocation, BillionRecordHeadersAllocateNothingLarge) {
  const std::pair<const char*, const char*> cases[] = {
      {"a.node", "1000000000 2 0 0\n1 0 0\n"},
      {"b.node", "1 2 1000000000 0\n1 0 0\n"},
      {"c.ele", "1000000000 3 0\n1 1 2 3\n"},
      {"d.ele", "1 3 1000000000\n1 1 2 3 0\n"},
      {"e.edge", "1000000000 1\n1 1 2 0\n"},
      {"f.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1000000000 0\n1 1 2\n"},
      {"g.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n1000000000\n1 0 0\n"},
      {"h.poly", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1000000000 0\n1\n3 1 2 3\n"},
      {"i.poly", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1000000000\n3 1 2 3\n"},
      {"j.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n1000000000\n0 0 0 0\nEnd\n"},
      {"k.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\n"
                 "Tetrahedra\n1000000000\n1 2 3 1 0\nEnd\n"},
      {"l.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\n"
                 "Triangles\n1000000000\n1 2 3 0\nEnd\n"},
      {"m.mesh", "MeshVersionFormatted 2\nDimension 2\nNormals\n1000000000\n0 0\nEnd\n"},
  };
  for (const auto& [name, contents] : cases) {
    EXPECT_LT(largest_allocation_while_parsing(name, contents), kSmall) << name;
  }
}

TEST(MalformedAllocation, TheCounterSeesAGenuineLargeFile) {
  // Control: 20000 vertices need a coordinate array of 320 kB, so the counter must see it.
  std::string file = "MeshVersionFormatted 2\nDimension 2\nVertices\n20000\n";
  for (int i = 0; i < 20000; ++i) file += std::to_string(i) + " 0 0\n";
  file += "End\n";
  largest_request = 0;
  const MeshData mesh = parse_medit_format("big.mesh", file);
  EXPECT_EQ(mesh.point_count(), 20000u);
  EXPECT_GE(largest_request.load(), 20000u * 2 * sizeof(double));
}

}  // namespace
}  // namespace certimesh::io
