// The validity every reader documents for what it returns (io/mesh_data.h): dimension 2 or 3,
// finite numbers, indices naming existing points, one label per item or none, TetGen facet
// offsets increasing and closing their arrays, polygon corners distinct. Written from the
// header's contract, not from the readers; shared by the libFuzzer reader target and the
// `readers` campaign target.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::testing {

namespace mesh_data_detail {

inline std::optional<std::string> cells_defect(const std::vector<io::Index>& cells, const std::vector<io::Label>& labels,
                                               std::size_t corners, std::size_t points) {
  if (cells.size() % corners != 0) return "cell array is not a multiple of its corner count";
  if (!labels.empty() && labels.size() != cells.size() / corners) return "label count mismatch";
  for (const io::Index i : cells)
    if (i >= points) return "index out of range accepted";
  return std::nullopt;
}

inline bool all_finite(const std::vector<double>& values) {
  for (const double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace mesh_data_detail

/// The first broken invariant of `m`, or nullopt when `m` is well formed.
inline std::optional<std::string> mesh_data_defect(const io::MeshData& m) {
  using namespace mesh_data_detail;
  if (m.dimension != 2 && m.dimension != 3) return "dimension not 2 or 3";
  const auto dim = static_cast<std::size_t>(m.dimension);
  if (m.coordinates.size() % dim != 0) return "coordinates not a multiple of the dimension";
  for (const auto* v : {&m.coordinates, &m.holes, &m.region_points, &m.region_attributes, &m.region_max_measures,
                        &m.facets.holes, &m.triangle_attributes})
    if (!all_finite(*v)) return "non-finite number accepted";
  const std::size_t n = m.point_count();
  if (!m.point_labels.empty() && m.point_labels.size() != n) return "point label count mismatch";
  if (auto d = cells_defect(m.segments, m.segment_labels, 2, n)) return d;
  if (auto d = cells_defect(m.triangles, m.triangle_labels, 3, n)) return d;
  if (auto d = cells_defect(m.tetrahedra, m.tetrahedron_labels, 4, n)) return d;
  if (!m.triangle_attributes.empty() && m.triangle_attributes.size() != m.triangle_count()) return "triangle attribute count mismatch";
  if (m.holes.size() % dim != 0 || m.region_points.size() % dim != 0) return "domain points not a multiple of the dimension";
  if (m.region_attributes.size() * dim != m.region_points.size()) return "region attribute count mismatch";
  if (!m.region_max_measures.empty() && m.region_max_measures.size() != m.region_attributes.size()) return "region constraint count mismatch";
  const io::FacetList& f = m.facets;
  if (f.hole_end.size() != f.facet_count() || (!f.labels.empty() && f.labels.size() != f.facet_count())) return "facet arrays differ in length";
  for (std::size_t i = 0; i < f.facet_count(); ++i)
    if (f.facet_end[i] < f.polygon_begin(i) || f.hole_end[i] < f.hole_begin(i)) return "facet offsets decrease";
  if (f.facet_count() > 0 && (f.facet_end.back() != f.polygon_count() || 3 * f.hole_end.back() != f.holes.size())) return "facet offsets do not close";
  for (std::size_t p = 0; p < f.polygon_count(); ++p) {
    if (f.polygon_end[p] <= f.corner_begin(p)) return "a polygon without corners";
    for (std::uint64_t a = f.corner_begin(p); a < f.polygon_end[p]; ++a) {
      if (f.corners[a] >= n) return "corner out of range accepted";
      for (std::uint64_t b = f.corner_begin(p); b < a; ++b)
        if (f.corners[a] == f.corners[b]) return "repeated corner accepted";
    }
  }
  if (f.polygon_count() > 0 && f.polygon_end.back() != f.corners.size()) return "polygon offsets do not close";
  return std::nullopt;
}

}  // namespace certimesh::testing
