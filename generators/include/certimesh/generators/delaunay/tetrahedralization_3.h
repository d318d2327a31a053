// A tetrahedral mesh of a solid in plain arrays: what the 3D stages hand each other
// (boundary recovery -> refinement -> the pipeline's io::MeshData).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "certimesh/io/mesh_data.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

struct Tetrahedralization3 {
  std::vector<predicates::Point3> points;
  /// Positive tetrahedra (Medit convention, design decision 4) over `points`.
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  /// One label per tetrahedron (empty: all 0).
  std::vector<io::Label> labels;
  /// Interior faces that must stay faces although both sides carry one label.
  std::vector<std::array<std::uint32_t, 3>> constrained_faces;
};

}  // namespace certimesh::generators
