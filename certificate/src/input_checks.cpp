// Condition 1: the input is a list of simplices on distinct, finite, used vertices.
#include <algorithm>
#include <cmath>

#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

std::string vname(std::int64_t v) { return "vertex " + std::to_string(v); }
std::string ename(std::size_t e) { return "element " + std::to_string(e); }

// The vertices in coordinate order (ties by index; vertex_order_less): the coordinates are
// copied beside each index first, so the sort compares contiguous keys instead of chasing two
// indices per comparison (it was a tenth of the whole check on the pinwheel).
template <int Dim>
void sort_by_coordinates(const MeshView& m, std::vector<Index>& order) {
  struct Key {
    double c[Dim];
    Index id;
  };
  std::vector<Key> keys(m.vertex_count);
  for (Index v = 0; v < m.vertex_count; ++v) {
    for (int k = 0; k < Dim; ++k) keys[v].c[k] = m.coord(v, Dim == 2 ? 1 - k : k);  // 2D: y first
    keys[v].id = v;
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    for (int k = 0; k < Dim; ++k)
      if (a.c[k] != b.c[k]) return a.c[k] < b.c[k];
    return a.id < b.id;
  });
  order.resize(m.vertex_count);
  for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].id;
}

// Sorting by coordinates puts identical points side by side: O(n log n), no hashing.
Finding check_distinct(const MeshView& m, std::vector<Index>& order) {
  if (m.dim == 2) sort_by_coordinates<2>(m, order);
  else sort_by_coordinates<3>(m, order);
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
