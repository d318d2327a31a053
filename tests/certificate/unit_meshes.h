// Small hand-built meshes for the certificate's unit tests. Coordinates are small integers,
// so the orientation fix-up below (a plain double determinant) is exact: it is an independent
// oracle, not the checker's predicates.
#pragma once

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <type_traits>
#include <utility>
#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::certificate::test {

using io::Index;
using io::MeshData;

// push_back instead of insert(end, {...}): GCC 12 warns falsely (-Wstringop-overflow) on the latter.
template <class T>
void append(std::vector<T>& v, std::initializer_list<std::type_identity_t<T>> xs) {
  for (const T& x : xs) v.push_back(x);
}

inline double det3(const MeshData& m, const Index* t) {
  auto d = [&](int v, int k) { return m.coordinates[3 * t[v] + k] - m.coordinates[3 * t[0] + k]; };
  return d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1)) - d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0)) +
         d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0));
}

inline double det2(const MeshData& m, const Index* t) {
  auto d = [&](int v, int k) { return m.coordinates[2 * t[v] + k] - m.coordinates[2 * t[0] + k]; };
  return d(1, 0) * d(2, 1) - d(1, 1) * d(2, 0);
}

/// Vertex index of grid point (i, j[, k]) in an (n+1)^dim grid.
inline Index grid_vertex(int n, int i, int j, int k = 0) {
  return static_cast<Index>((k * (n + 1) + j) * (n + 1) + i);
}

/// n x n unit squares, each cut along its (i,j)-(i+1,j+1) diagonal; squares for which
/// `skip(i, j)` holds are left out (their vertices stay, so callers skip only inner ones).
template <class Skip>
MeshData square_grid(int n, Skip skip) {
  MeshData m;
  m.dimension = 2;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) append(m.coordinates, {double(i), double(j)});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (skip(i, j)) continue;
      const Index a = grid_vertex(n, i, j), b = grid_vertex(n, i + 1, j), c = grid_vertex(n, i + 1, j + 1),
                  d = grid_vertex(n, i, j + 1);
      append(m.triangles, {a, b, c, a, c, d});
    }
  return m;
}
inline MeshData square_grid(int n) { return square_grid(n, [](int, int) { return false; }); }

/// n^3 unit cubes, each cut into the six Kuhn tetrahedra along its main diagonal (a conforming
/// triangulation), every tetrahedron made positive; cubes where skip(i,j,k) are left out.
template <class Skip>
MeshData kuhn_grid(int n, Skip skip) {
  MeshData m;
  m.dimension = 3;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) append(m.coordinates, {double(i), double(j), double(k)});
  int axes[3] = {0, 1, 2};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (skip(i, j, k)) continue;
        std::sort(axes, axes + 3);
        do {
          int at[3] = {i, j, k};
          Index t[4];
          t[0] = grid_vertex(n, at[0], at[1], at[2]);
          for (int s = 0; s < 3; ++s) {
            ++at[axes[s]];
            t[s + 1] = grid_vertex(n, at[0], at[1], at[2]);
          }
          if (det3(m, t) < 0) std::swap(t[2], t[3]);
          m.tetrahedra.insert(m.tetrahedra.end(), t, t + 4);
        } while (std::next_permutation(axes, axes + 3));
      }
  return m;
}
inline MeshData kuhn_grid(int n) { return kuhn_grid(n, [](int, int, int) { return false; }); }

/// Separate simplices given by their coordinates (dim + 1 points each), in the given order.
inline MeshData simplices(int dim, const std::vector<std::vector<double>>& elements) {
  MeshData m;
  m.dimension = dim;
  for (const auto& e : elements) {
    const auto first = static_cast<Index>(m.coordinates.size() / static_cast<std::size_t>(dim));
    m.coordinates.insert(m.coordinates.end(), e.begin(), e.end());
    for (Index v = 0; v <= static_cast<Index>(dim); ++v) (dim == 2 ? m.triangles : m.tetrahedra).push_back(first + v);
  }
  return m;
}

}  // namespace certimesh::certificate::test
