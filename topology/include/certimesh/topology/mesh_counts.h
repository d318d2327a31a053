// The counts of §2.2 of the monograph, computed from a mesh, for the Euler relations:
//   2D:       Nf + Nh = Ne - Nv + 1, 2Nei + Neb = 3Nf, Nf = 2Nv - Neb + 2Nh - 2
//   surfaces: Nf = 2Nv + 4g - 4 (closed, connected, genus g)
//   3D:       Ne = Nt + Nv + 3/4 Nfb - 1/2 Nvb, 4Nt = 2Nfi + Nfb, chi = 1/2 Nvb - 1/4 Nfb
// The relations themselves are not assumed here: the tests check them against these counts.
#pragma once

#include <cstddef>
#include <cstdint>

namespace certimesh::topology {

struct MeshCounts {
  std::size_t vertices = 0;         // Nv: live vertices used by at least one element
  std::size_t unused_vertices = 0;  // live vertices no element uses (not in Nv)
  std::size_t edges = 0;            // Ne
  std::size_t interior_edges = 0;   // Nei
  std::size_t boundary_edges = 0;   // Neb: edges on a boundary facet
  std::size_t triangles = 0;        // Nf: triangular faces (all of them, for a tetrahedral mesh)
  std::size_t interior_faces = 0;   // Nfi (tetrahedral meshes)
  std::size_t boundary_faces = 0;   // Nfb (tetrahedral meshes)
  std::size_t tetrahedra = 0;       // Nt
  std::size_t boundary_vertices = 0;  // Nvb: vertices on a boundary facet
  std::size_t components = 0;         // connected components of elements joined through facets
  std::size_t boundary_components = 0;  // connected components of the boundary (joined at vertices)
  // Holes: 2D, boundary loops beyond one outer loop per component; 3D, cavities (boundary
  // surfaces beyond one per component); surfaces, the boundary loops. Exact when no vertex is
  // shared by two boundary loops or surfaces (a pinch merges them).
  std::size_t holes = 0;
  /// Nv - Ne + Nf - Nt.
  std::int64_t euler_characteristic() const noexcept {
    return static_cast<std::int64_t>(vertices) - static_cast<std::int64_t>(edges) +
           static_cast<std::int64_t>(triangles) - static_cast<std::int64_t>(tetrahedra);
  }
};

template <class Mesh>
MeshCounts count_mesh(const Mesh& mesh);

}  // namespace certimesh::topology
