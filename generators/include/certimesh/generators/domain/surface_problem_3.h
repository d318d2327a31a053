// What can be wrong with a closed triangulated surface (the input of 3D meshing), and where.
// Every refusal names the offending triangles by 0-based index (the file's triangle, or for a
// TetGen facet or OFF polygon the triangle cut from it, with the facet named too) and their
// corner coordinates, printed so that they read back bit for bit (docs/surface_input.md).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace certimesh::generators {

enum class SurfaceProblemKind {
  wrong_dimension,           // not a 3D file
  no_triangles,              // nothing to bound a solid
  non_finite_coordinate,
  vertex_index_out_of_range,
  bad_facet,                 // a polygonal facet certimesh cannot cut into triangles (not planar, not simple, holes)
  duplicate_vertices,        // two vertices with identical coordinates
  degenerate_triangle,       // zero area: a repeated corner or three collinear corners (exact)
  duplicate_triangles,       // the same three vertices twice, whatever the order
  open_edge,                 // an edge of exactly one triangle
  non_manifold_edge,         // an edge of 3 or more triangles that do not pair up (see surface_validation_3.h)
  inconsistent_orientation,  // two triangles traverse their common edge the same way
  self_intersection,         // two triangles meet beyond their shared vertices (touching counts)
  non_orientable,            // an unoriented (.poly/.smesh) shell that no choice of sides makes coherent
};

struct SurfaceProblem {
  SurfaceProblemKind kind{};
  std::vector<std::uint32_t> triangles;  // offending triangle indices (Surface3::triangles)
  std::vector<std::uint32_t> vertices;   // offending vertex indices
  std::string message;                   // the whole sentence, indices and coordinates included
};

/// Thrown when a surface is refused; holds the problems found (capped), first first.
class InvalidSurface : public std::runtime_error {
 public:
  explicit InvalidSurface(std::vector<SurfaceProblem> problems);
  const std::vector<SurfaceProblem>& problems() const noexcept { return problems_; }

 private:
  std::vector<SurfaceProblem> problems_;
};

const char* to_string(SurfaceProblemKind kind) noexcept;

}  // namespace certimesh::generators
