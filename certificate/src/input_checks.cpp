// Condition 1: the input is a list of simplices on distinct, finite, used vertices.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

std::string vname(Index v) { return "vertex " + std::to_string(v); }
std::string ename(std::size_t e) { return "element " + std::to_string(e); }

Finding check_indices(const MeshView& m) {
  for (std::size_t e = 0; e < m.element_count; ++e)
    for (int i = 0; i < m.corners(); ++i)
      if (m.cell(e)[i] >= m.vertex_count)
        return finding(Defect::index_out_of_range, static_cast<std::int64_t>(e), -1, m.cell(e)[i],
                       ename(e) + " names vertex " + std::to_string(m.cell(e)[i]) + " of " +
                           std::to_string(m.vertex_count));
  return {};
}

Finding check_finite(const MeshView& m) {
  for (Index v = 0; v < m.vertex_count; ++v)
    for (int a = 0; a < m.dim; ++a)
      if (!std::isfinite(m.coord(v, a)))
        return finding(Defect::non_finite_coordinate, -1, -1, v, vname(v) + " has a NaN or infinite coordinate");
  return {};
}

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

Finding check_used(const MeshView& m) {
  std::vector<char> used(m.vertex_count, 0);
  for (std::size_t i = 0; i < m.element_count * static_cast<std::size_t>(m.corners()); ++i) used[m.cells[i]] = 1;
  for (Index v = 0; v < m.vertex_count; ++v)
    if (!used[v]) return finding(Defect::unused_vertex, -1, -1, v, vname(v) + " is in no element");
  return {};
}

Finding check_repeated(const MeshView& m) {
  for (std::size_t e = 0; e < m.element_count; ++e)
    for (int i = 0; i < m.corners(); ++i)
      for (int j = i + 1; j < m.corners(); ++j)
        if (m.cell(e)[i] == m.cell(e)[j])
          return finding(Defect::repeated_vertex, static_cast<std::int64_t>(e), -1, m.cell(e)[i],
                         ename(e) + " lists vertex " + std::to_string(m.cell(e)[i]) + " twice");
  return {};
}

}  // namespace

Finding check_input(const MeshView& m, std::vector<Index>& lex_order) {
  if (m.element_count == 0)
    return finding(Defect::no_elements, -1, -1, -1,
                   m.dim == 2 ? "the mesh has no triangles" : "the mesh has no tetrahedra");
  for (auto stage : {check_indices, check_finite}) {
    Finding f = stage(m);
    if (f.defect != Defect::none) return f;
  }
  Finding f = check_distinct(m, lex_order);
  if (f.defect != Defect::none) return f;
  f = check_used(m);
  if (f.defect != Defect::none) return f;
  return check_repeated(m);
}

}  // namespace certimesh::certificate::detail
