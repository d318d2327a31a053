// Shared by the Gmsh and VTU tests: a RapidCheck generator of arbitrary MeshData (extreme
// doubles, every cell kind, labels at the int32 extremes, with and without point labels), the
// form a mesh must read back in after a write (derived from the documented conventions, not
// from the code), and a bit-for-bit comparison of coordinates.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include "certimesh/fuzz/rc_generators.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::testing {

inline rc::Gen<double> extreme_double() {
  using fuzz::DoubleClass;
  using fuzz::rcgen::double_of_class;
  return rc::gen::oneOf(double_of_class(DoubleClass::normal), double_of_class(DoubleClass::subnormal),
                        double_of_class(DoubleClass::huge), double_of_class(DoubleClass::tiny),
                        rc::gen::element(0.0, -0.0, 1.0, 0.1, std::numeric_limits<double>::max(),
                                         std::numeric_limits<double>::lowest(),
                                         std::numeric_limits<double>::denorm_min(),
                                         std::numeric_limits<double>::min()));
}

inline rc::Gen<io::Label> any_label() {
  return rc::gen::oneOf(rc::gen::element<io::Label>(0, 1, -1, 7, std::numeric_limits<io::Label>::min(),
                                                    std::numeric_limits<io::Label>::max()),
                        rc::gen::arbitrary<io::Label>());
}

/// Cells of `arity` vertices among `points`, with labels (or none, "all 0").
inline void draw_cells(std::size_t points, std::size_t arity, std::vector<io::Index>& cells,
                       std::vector<io::Label>& labels) {
  if (points == 0) return;
  const auto count = fuzz::rcgen::pick<std::size_t>(0, 12);  // whatever RapidCheck's size
  for (std::size_t i = 0; i < count * arity; ++i) {
    cells.push_back(fuzz::rcgen::pick<io::Index>(0, static_cast<io::Index>(points)));
  }
  if (*rc::gen::arbitrary<bool>()) {
    for (std::size_t i = 0; i < count; ++i) labels.push_back(*any_label());
  }
}

/// Any MeshData the writers accept: 2D without tetrahedra, or 3D.
inline rc::Gen<io::MeshData> arbitrary_mesh() {
  return rc::gen::exec([] {
    io::MeshData mesh;
    mesh.dimension = *rc::gen::element(2, 3);
    const auto points = fuzz::rcgen::pick<std::size_t>(0, 24);
    for (std::size_t i = 0; i < points * static_cast<std::size_t>(mesh.dimension); ++i) {
      mesh.coordinates.push_back(*extreme_double());
    }
    if (*rc::gen::arbitrary<bool>()) {
      for (std::size_t i = 0; i < points; ++i) mesh.point_labels.push_back(*any_label());
    }
    draw_cells(points, 2, mesh.segments, mesh.segment_labels);
    draw_cells(points, 3, mesh.triangles, mesh.triangle_labels);
    if (mesh.dimension == 3) draw_cells(points, 4, mesh.tetrahedra, mesh.tetrahedron_labels);
    return mesh;
  });
}

/// MeshData's convention "empty = all 0": readers return an empty label vector for a cell
/// kind whose labels are all 0 (gmsh_format.h, vtu_format.h).
inline io::MeshData with_zero_labels_dropped(io::MeshData mesh) {
  for (auto* labels : {&mesh.segment_labels, &mesh.triangle_labels, &mesh.tetrahedron_labels}) {
    if (std::all_of(labels->begin(), labels->end(), [](io::Label l) { return l == 0; })) labels->clear();
  }
  return mesh;
}

/// The Gmsh dimension rule: 3 when there is a tetrahedron or a point with z != 0, else 2.
inline io::MeshData with_gmsh_dimension_rule(io::MeshData mesh) {
  if (mesh.dimension != 3 || !mesh.tetrahedra.empty()) return mesh;
  for (std::size_t i = 2; i < mesh.coordinates.size(); i += 3) {
    if (mesh.coordinates[i] != 0.0) return mesh;
  }
  std::vector<double> planar;
  for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) {
    if (i % 3 != 2) planar.push_back(mesh.coordinates[i]);
  }
  mesh.coordinates = planar;
  mesh.dimension = 2;
  return mesh;
}

/// Bit-for-bit equality (MeshData's == says 0.0 == -0.0).
inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

}  // namespace certimesh::testing
