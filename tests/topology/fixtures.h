// Meshes the topology tests run on, built from their definitions (no library code but the
// mesh's add calls), with orientation decided by integer determinants on integer coordinates,
// an oracle independent of the predicates.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "certimesh/topology/mesh_entities.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology::testing {

using Cell2 = std::array<int, 2>;
using Cell3 = std::array<int, 3>;

/// Structured 2D grid of nx x ny unit squares, each split by its (i,j)-(i+1,j+1) diagonal into
/// two counterclockwise triangles; cells in `removed` are left out (holes). Only used vertices
/// are added.
inline TriangleMesh2 grid2(int nx, int ny, const std::set<Cell2>& removed = {}) {
  TriangleMesh2 mesh;
  std::map<Cell2, VertexId> ids;
  auto vertex = [&](int i, int j) {
    const auto [it, fresh] = ids.try_emplace(Cell2{i, j});
    if (fresh) it->second = mesh.add_vertex({double(i), double(j)});
    return it->second;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (removed.count(Cell2{i, j}) != 0) continue;
      mesh.add_element({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      mesh.add_element({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  return mesh;
}

inline std::int64_t det3(const std::array<std::int64_t, 3>& u, const std::array<std::int64_t, 3>& v,
                         const std::array<std::int64_t, 3>& w) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Adds the tetrahedron on integer points p, positively oriented (det[b-a, c-a, d-a] > 0,
/// swapping two vertices if needed).
template <class VertexOf>
void add_positive_tet(TetrahedralMesh3& mesh, std::array<Cell3, 4> p, VertexOf vertex) {
  auto diff = [&](int k) {
    return std::array<std::int64_t, 3>{p[k][0] - p[0][0], p[k][1] - p[0][1], p[k][2] - p[0][2]};
  };
  if (det3(diff(1), diff(2), diff(3)) < 0) std::swap(p[2], p[3]);
  mesh.add_element({vertex(p[0]), vertex(p[1]), vertex(p[2]), vertex(p[3])});
}

/// Structured 3D grid of n^3 unit cubes, each cut into the 6 Kuhn tetrahedra around its main
/// diagonal; cubes in `removed` are left out.
inline TetrahedralMesh3 kuhn_grid3(int nx, int ny, int nz, const std::set<Cell3>& removed = {}) {
  TetrahedralMesh3 mesh;
  std::map<Cell3, VertexId> ids;
  auto vertex = [&](const Cell3& c) {
    const auto [it, fresh] = ids.try_emplace(c);
    if (fresh) it->second = mesh.add_vertex({double(c[0]), double(c[1]), double(c[2])});
    return it->second;
  };
  const std::array<std::array<int, 3>, 6> permutations{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (removed.count(Cell3{i, j, k}) != 0) continue;
        for (const auto& perm : permutations) {
          std::array<Cell3, 4> p{};
          p[0] = {i, j, k};
          for (int s = 0; s < 3; ++s) {
            p[s + 1] = p[s];
            ++p[s + 1][perm[s]];
          }
          add_positive_tet(mesh, p, vertex);
        }
      }
  return mesh;
}

/// The unit cube cut into 5 tetrahedra: the central one and four corner ones.
inline TetrahedralMesh3 cube_in_five() {
  TetrahedralMesh3 mesh;
  std::map<Cell3, VertexId> ids;
  auto vertex = [&](const Cell3& c) {
    const auto [it, fresh] = ids.try_emplace(c);
    if (fresh) it->second = mesh.add_vertex({double(c[0]), double(c[1]), double(c[2])});
    return it->second;
  };
  const std::array<std::array<Cell3, 4>, 5> tets{{
      {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}}},
      {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
      {{{1, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}},
      {{{1, 0, 1}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}}},
      {{{0, 1, 1}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}}},
  }};
  for (const auto& t : tets) add_positive_tet(mesh, t, vertex);
  return mesh;
}

/// The boundary of a tetrahedral mesh as a surface mesh (its open facets, outward).
inline SurfaceMesh3 boundary_surface(const TetrahedralMesh3& volume) {
  SurfaceMesh3 surface;
  std::map<std::uint32_t, VertexId> ids;
  auto vertex = [&](VertexId v) {
    const auto [it, fresh] = ids.try_emplace(v.value);
    if (fresh) it->second = surface.add_vertex(volume.point(v));
    return it->second;
  };
  for (const FacetRecord& f : extract_facets(volume)) {
    if (!f.boundary()) continue;
    const auto t = volume.facet(f.element, f.local);
    surface.add_element({vertex(t[0]), vertex(t[1]), vertex(t[2])});
  }
  return surface;
}

/// A torus surface: an n x m periodic grid of squares, each cut in two (Nv = nm, Nf = 2nm).
/// Combinatorial only: the coordinates are the flat grid (the counts do not look at them).
inline SurfaceMesh3 torus(int n, int m) {
  SurfaceMesh3 mesh;
  std::vector<VertexId> ids;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) ids.push_back(mesh.add_vertex({double(i), double(j), 0.0}));
  auto v = [&](int i, int j) { return ids[static_cast<std::size_t>((j % m) * n + (i % n))]; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_element({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      mesh.add_element({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  return mesh;
}

}  // namespace certimesh::topology::testing
