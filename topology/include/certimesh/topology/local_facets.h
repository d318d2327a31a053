// Which local vertices make up facet i of a simplex, the facet opposite local vertex i,
// listed so that the facet is oriented outward for a positively oriented element:
//   triangle (v0 v1 v2) counterclockwise: facet i = (v[i+1], v[i+2]) (indices mod 3);
//   tetrahedron with det[v1-v0, v2-v0, v3-v0] > 0: facets (1 2 3), (0 3 2), (0 1 3), (0 2 1),
//   each with its normal (by the right-hand rule) pointing away from the opposite vertex.
// Boundary facets written to files keep this orientation.
#pragma once

#include <array>

namespace certimesh::topology {

template <int SimplexDim>
constexpr std::array<int, SimplexDim> local_facet(int opposite) noexcept {
  static_assert(SimplexDim == 2 || SimplexDim == 3, "triangles and tetrahedra only");
  if constexpr (SimplexDim == 2) {
    return {(opposite + 1) % 3, (opposite + 2) % 3};
  } else {
    constexpr std::array<std::array<int, 3>, 4> facets{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
    return facets[static_cast<unsigned>(opposite)];
  }
}

}  // namespace certimesh::topology
