// Meshes and domains with pinches (design decision 8: parts sharing a corner, a hole touching
// the outer loop, solids sharing a vertex or an edge, a cavity touching the outer shell), built
// from integer Kuhn grids by leaving cells or elements out. The domain of such a mesh is read
// off the mesh with plain counting (std::map, independent of the checker): its boundary facets,
// oriented as their elements induce them.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "certimesh/io/mesh_data.h"
#include "unit_meshes.h"

namespace certimesh::certificate::test {

/// Removes the vertices no element uses, renumbering the elements.
inline void drop_unused_vertices(MeshData& m) {
  auto& cells = m.dimension == 2 ? m.triangles : m.tetrahedra;
  const auto d = static_cast<std::size_t>(m.dimension);
  std::vector<Index> id(m.point_count(), Index(-1));
  std::vector<double> kept;
  for (Index& v : cells) {
    if (id[v] == Index(-1)) {
      id[v] = static_cast<Index>(kept.size() / d);
      for (std::size_t k = 0; k < d; ++k) kept.push_back(m.coordinates[v * d + k]);
    }
    v = id[v];
  }
  m.coordinates = kept;
}

/// The facets of element `e` opposite each corner, oriented as a positive element induces them
/// (counterclockwise in 2D, outward in 3D).
inline std::vector<std::vector<Index>> oriented_facets(const MeshData& m, std::size_t e) {
  if (m.dimension == 2) {
    const Index* t = &m.triangles[3 * e];
    return {{t[1], t[2]}, {t[2], t[0]}, {t[0], t[1]}};
  }
  const Index* t = &m.tetrahedra[4 * e];
  return {{t[1], t[2], t[3]}, {t[0], t[3], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[1]}};
}

/// The boundary facets of a mesh (facets of exactly one element), oriented by their element.
inline std::vector<std::vector<Index>> boundary_facets(const MeshData& m) {
  std::map<std::vector<Index>, std::vector<std::vector<Index>>> by_set;
  const std::size_t n = m.dimension == 2 ? m.triangle_count() : m.tetrahedron_count();
  for (std::size_t e = 0; e < n; ++e)
    for (auto f : oriented_facets(m, e)) {
      auto key = f;
      std::sort(key.begin(), key.end());
      by_set[key].push_back(f);
    }
  std::vector<std::vector<Index>> out;
  for (const auto& [key, fs] : by_set)
    if (fs.size() == 1) out.push_back(fs[0]);
  return out;
}

/// The domain whose boundary is exactly the mesh's: its boundary facets as segments (2D) or
/// triangles (3D), on the mesh's own points.
inline MeshData boundary_as_domain(const MeshData& m) {
  MeshData d;
  d.dimension = m.dimension;
  d.coordinates = m.coordinates;
  for (const auto& f : boundary_facets(m)) (m.dimension == 2 ? d.segments : d.triangles).insert(
      (m.dimension == 2 ? d.segments : d.triangles).end(), f.begin(), f.end());
  if (m.dimension == 2) d.segment_labels.assign(d.segment_count(), 0);
  else d.triangle_labels.assign(d.triangle_count(), 0);
  return d;
}

/// Kuhn grid cells kept where `keep(i, j[, k])`, unused vertices dropped.
template <class Keep>
MeshData kept_squares(int n, Keep keep) {
  MeshData m = square_grid(n, [&](int i, int j) { return !keep(i, j); });
  drop_unused_vertices(m);
  return m;
}
template <class Keep>
MeshData kept_cubes(int n, Keep keep) {
  MeshData m = kuhn_grid(n, [&](int i, int j, int k) { return !keep(i, j, k); });
  drop_unused_vertices(m);
  return m;
}

/// Index of the first element whose vertex set is `vertices` (any order), or -1.
inline std::int64_t element_with(const MeshData& m, std::vector<Index> vertices) {
  std::sort(vertices.begin(), vertices.end());
  const std::size_t k = vertices.size(), n = (m.dimension == 2 ? m.triangles : m.tetrahedra).size() / k;
  const auto& cells = m.dimension == 2 ? m.triangles : m.tetrahedra;
  for (std::size_t e = 0; e < n; ++e) {
    std::vector<Index> s(cells.begin() + static_cast<std::ptrdiff_t>(e * k), cells.begin() + static_cast<std::ptrdiff_t>((e + 1) * k));
    std::sort(s.begin(), s.end());
    if (s == vertices) return static_cast<std::int64_t>(e);
  }
  return -1;
}

inline void erase_element(MeshData& m, std::size_t e) {
  auto& cells = m.dimension == 2 ? m.triangles : m.tetrahedra;
  const auto k = static_cast<std::ptrdiff_t>(m.dimension + 1);
  cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(e) * k, cells.begin() + (static_cast<std::ptrdiff_t>(e) + 1) * k);
}

/// The first element of the grid [0, n]^d with exactly `count` vertices on the outer boundary,
/// all of them on one common side / face: removed, it leaves a hole touching the outer boundary
/// at that vertex, or (3D, count 2) a cavity touching it along that edge. SIZE_MAX if none.
inline std::size_t element_touching_boundary(const MeshData& m, int n, int count) {
  const auto d = static_cast<std::size_t>(m.dimension);
  const auto& cells = m.dimension == 2 ? m.triangles : m.tetrahedra;
  auto x = [&](Index v, std::size_t k) { return m.coordinates[v * d + k]; };
  for (std::size_t e = 0; e < cells.size() / (d + 1); ++e) {
    std::vector<Index> on;
    for (std::size_t i = 0; i <= d; ++i) {
      const Index v = cells[e * (d + 1) + i];
      bool b = false;
      for (std::size_t k = 0; k < d; ++k) b = b || x(v, k) == 0 || x(v, k) == n;
      if (b) on.push_back(v);
    }
    if (static_cast<int>(on.size()) != count) continue;
    for (std::size_t k = 0; k < d; ++k)
      if ((x(on[0], k) == 0 || x(on[0], k) == n) && std::all_of(on.begin(), on.end(), [&](Index v) { return x(v, k) == x(on[0], k); }))
        return e;
  }
  return SIZE_MAX;
}

}  // namespace certimesh::certificate::test
