// CGAL reference check (see cgal_mesh_check_peer.h). Orientation conventions match
// certimesh's files: CGAL::orientation(a, b, c) > 0 for a counterclockwise triangle, and
// CGAL::orientation(a, b, c, d) = sign det[b-a, c-a, d-a] > 0 for a positive tetrahedron.
#include "cgal_mesh_check_peer.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace certimesh_bench {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using certimesh::io::Index;
using certimesh::io::MeshData;

bool all_positive_2d(const MeshData& m) {
  std::vector<K::Point_2> p;
  p.reserve(m.point_count());
  for (std::size_t v = 0; v < m.point_count(); ++v) p.emplace_back(m.coordinates[2 * v], m.coordinates[2 * v + 1]);
  const std::vector<Index>& t = m.triangles;
  for (std::size_t i = 0; i < t.size(); i += 3)
    if (CGAL::orientation(p[t[i]], p[t[i + 1]], p[t[i + 2]]) != CGAL::POSITIVE) return false;
  return true;
}

bool all_positive_3d(const MeshData& m) {
  std::vector<K::Point_3> p;
  p.reserve(m.point_count());
  for (std::size_t v = 0; v < m.point_count(); ++v)
    p.emplace_back(m.coordinates[3 * v], m.coordinates[3 * v + 1], m.coordinates[3 * v + 2]);
  const std::vector<Index>& t = m.tetrahedra;
  for (std::size_t i = 0; i < t.size(); i += 4)
    if (CGAL::orientation(p[t[i]], p[t[i + 1]], p[t[i + 2]], p[t[i + 3]]) != CGAL::POSITIVE) return false;
  return true;
}

// A facet as sorted vertex indices (unused slots 0) and the parity of the orientation the
// element induces on it: (-1)^k for the facet opposite vertex k, times the parity of the
// permutation that sorts it. Two elements on opposite sides of a facet induce opposite ones.
struct OrientedFacet {
  std::array<Index, 3> v{0, 0, 0};
  std::uint32_t parity = 0;
  bool operator<(const OrientedFacet& o) const { return v < o.v; }
};

template <std::size_t N>
OrientedFacet oriented_facet(const Index* element, std::size_t opposite) {
  OrientedFacet f;
  std::size_t n = 0;
  for (std::size_t i = 0; i <= N; ++i)
    if (i != opposite) f.v[n++] = element[i];
  std::uint32_t swaps = static_cast<std::uint32_t>(opposite & 1);
  for (std::size_t i = 0; i < N; ++i)  // insertion sort, counting transpositions
    for (std::size_t j = i; j > 0 && f.v[j] < f.v[j - 1]; --j) std::swap(f.v[j], f.v[j - 1]), ++swaps;
  f.parity = swaps & 1;
  return f;
}

template <std::size_t N>  // N = facet size: 2 (triangles) or 3 (tetrahedra)
void pair_facets(const std::vector<Index>& elements, PeerVerdict& verdict) {
  std::vector<OrientedFacet> facets;
  facets.reserve(elements.size());
  for (std::size_t e = 0; e < elements.size(); e += N + 1)
    for (std::size_t k = 0; k <= N; ++k) facets.push_back(oriented_facet<N>(&elements[e], k));
  std::sort(facets.begin(), facets.end());
  verdict.paired = true;
  for (std::size_t i = 0; i < facets.size();) {
    std::size_t j = i + 1;
    while (j < facets.size() && facets[j].v == facets[i].v) ++j;
    if (j - i == 1) {
      ++verdict.boundary_facets;
    } else if (j - i == 2 && facets[i].parity != facets[i + 1].parity) {
      ++verdict.interior_facets;
    } else {
      verdict.paired = false;
    }
    i = j;
  }
}

}  // namespace

PeerVerdict cgal_reference_check(const MeshData& mesh) {
  PeerVerdict verdict;
  if (mesh.dimension == 2) {
    verdict.all_positive = all_positive_2d(mesh);
    pair_facets<2>(mesh.triangles, verdict);
  } else {
    verdict.all_positive = all_positive_3d(mesh);
    pair_facets<3>(mesh.tetrahedra, verdict);
  }
  return verdict;
}

}  // namespace certimesh_bench
