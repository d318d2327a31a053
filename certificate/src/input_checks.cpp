// Condition 1: the input is a list of simplices on distinct, finite, used vertices.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

std::string vname(std::int64_t v) { return "vertex " + std::to_string(v); }
std::string ename(std::size_t e) { return "element " + std::to_string(e); }

// Sorting by coordinates puts identical points side by side: O(n log n), no hashing.
Finding check_distinct(const MeshView& m, std::vector<Index>& order) {
  order.resize(m.vertex_count);
  std::iota(order.begin(), order.end(), Index{0});
  auto less = [&](Index a, Index b) {
    for (int k = 0; k < m.dim; ++k)
      if (m.coord(a, k) != m.coord(b, k)) return m.coord(a, k) < m.coord(b, k);
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t i = 1; i < order.size(); ++i) {
    bool same = true;
    for (int k = 0; k < m.dim; ++k) same = same && m.coord(order[i - 1], k) == m.coord(order[i], k);
    if (same)
      return finding(Defect::duplicate_vertex, -1, order[i - 1], order[i],
                     vname(order[i]) + " has the same coordinates as vertex " + std::to_string(order[i - 1]));
  }
  return {};
}

}  // namespace

Finding check_input(const MeshView& m, std::vector<Index>& lex_order) {
  const std::size_t k = static_cast<std::size_t>(m.corners()), n = m.element_count * k;
  if (n == 0) return finding(Defect::no_elements, -1, -1, -1, m.dim == 2 ? "the mesh has no triangles" : "the mesh has no tetrahedra");
  for (std::size_t i = 0; i < n; ++i)
    if (m.cells[i] >= m.vertex_count)
      return finding(Defect::index_out_of_range, static_cast<std::int64_t>(i / k), -1, m.cells[i],
                     ename(i / k) + " names vertex " + std::to_string(m.cells[i]) + " of " + std::to_string(m.vertex_count));
  for (std::size_t i = 0; i < m.vertex_count * static_cast<std::size_t>(m.dim); ++i)
    if (!std::isfinite(m.xyz[i]))
      return finding(Defect::non_finite_coordinate, -1, -1, static_cast<std::int64_t>(i / m.dim),
                     vname(static_cast<std::int64_t>(i / m.dim)) + " has a NaN or infinite coordinate");
  Finding f = check_distinct(m, lex_order);
  if (f.defect != Defect::none) return f;
  std::vector<char> used(m.vertex_count, 0);
  for (std::size_t i = 0; i < n; ++i) used[m.cells[i]] = 1;
  for (Index v = 0; v < m.vertex_count; ++v)
    if (!used[v]) return finding(Defect::unused_vertex, -1, -1, v, vname(v) + " is in no element");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < (i / k + 1) * k; ++j)
      if (m.cells[i] == m.cells[j])
        return finding(Defect::repeated_vertex, static_cast<std::int64_t>(i / k), -1, m.cells[i],
                       ename(i / k) + " lists vertex " + std::to_string(m.cells[i]) + " twice");
  return {};
}

}  // namespace certimesh::certificate::detail
