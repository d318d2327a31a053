// Internal: vertex -> incident triangles of a triangle soup, by a counting sort (Algorithm 3 of
// the monograph): linear in the triangles, each star in triangle order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "improvement_region.h"

namespace certimesh::generators::detail {

struct VertexStars {
  std::vector<std::uint32_t> offset, triangle;
  explicit VertexStars(const TriangleSoup& m) : offset(m.points.size() + 1, 0) {
    for (const auto& t : m.triangles)
      for (const std::uint32_t v : t) ++offset[v + 1];
    for (std::size_t v = 0; v < m.points.size(); ++v) offset[v + 1] += offset[v];
    triangle.resize(offset.back());
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
      for (const std::uint32_t v : m.triangles[t]) triangle[fill[v]++] = t;
  }
  std::span<const std::uint32_t> of(std::uint32_t v) const { return {triangle.data() + offset[v], offset[v + 1] - offset[v]}; }
};

}  // namespace certimesh::generators::detail
