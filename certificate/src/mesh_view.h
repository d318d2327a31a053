// Internal: read-only access to the simplices of a MeshData, the same code for 2D and 3D.
// The checker works on this view and on FacetSet; neither owns geometry.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/predicates/point.h"

namespace certimesh::certificate::detail {

using io::Index;

struct MeshView {
  int dim = 2;  // 2: triangles, 3: tetrahedra
  const double* xyz = nullptr;
  std::size_t vertex_count = 0;
  const Index* cells = nullptr;  // dim + 1 vertex indices per element
  std::size_t element_count = 0;
  const io::Label* labels = nullptr;  // one per element, or null (all 0)

  int corners() const { return dim + 1; }
  const Index* cell(std::size_t e) const { return cells + e * static_cast<std::size_t>(dim + 1); }
  double coord(Index v, int axis) const { return xyz[static_cast<std::size_t>(v) * dim + axis]; }
  predicates::Point2 p2(Index v) const { return {coord(v, 0), coord(v, 1)}; }
  predicates::Point3 p3(Index v) const { return {coord(v, 0), coord(v, 1), coord(v, 2)}; }
};

/// Oriented facets (edges in 2D, triangles in 3D) with the element each one bounds. The
/// orientation is the one the element induces: counterclockwise boundary in 2D, outward
/// normal (right-hand rule) in 3D.
struct FacetSet {
  int dim = 2;
  std::vector<Index> vertices;       // dim per facet
  std::vector<std::int64_t> owner;   // element (or domain facet) index, for reporting
  std::size_t size() const { return owner.size(); }
  const Index* facet(std::size_t f) const { return vertices.data() + f * static_cast<std::size_t>(dim); }
};

/// Axis-aligned box in double; exact (its bounds are input coordinates).
struct Box {
  double lo[3] = {0, 0, 0};
  double hi[3] = {0, 0, 0};
};

Box facet_box(const MeshView& m, const Index* f, int count);
bool boxes_overlap(const Box& a, const Box& b, int dim);

inline Finding finding(Defect defect, std::int64_t element, std::int64_t other, std::int64_t vertex, std::string why) {
  return Finding{defect, element, other, vertex, std::move(why)};
}

}  // namespace certimesh::certificate::detail
