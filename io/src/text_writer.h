// What the text writers share: the check that a MeshData is well formed before any byte is
// written (a writer must never produce a file its own reader refuses), and number output.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_data.h"
#include "certimesh/io/mesh_file.h"

namespace certimesh::io::detail {

template <class Integer>
void append_integer(std::string& out, Integer value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

inline void check_finite(const std::vector<double>& values, const std::string& file,
                         const char* what) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw FormatError(file, 0, std::string(what) + " value " + std::to_string(i) +
                                     " is not finite: no reader would accept it back");
    }
  }
}

inline void check_cells(const std::vector<Index>& cells, const std::vector<Label>& labels,
                        std::size_t corners, std::size_t point_count, const std::string& file,
                        const char* what) {
  if (cells.size() % corners != 0) {
    throw FormatError(file, 0, std::string(what) + ": " + std::to_string(cells.size()) +
                                   " indices is not a multiple of " + std::to_string(corners));
  }
  const std::size_t count = cells.size() / corners;
  if (!labels.empty() && labels.size() != count) {
    throw FormatError(file, 0, std::string(what) + ": " + std::to_string(labels.size()) +
                                   " labels for " + std::to_string(count) + " cells");
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells[i] >= point_count) {
      throw FormatError(file, 0, std::string(what) + " " + std::to_string(i / corners) +
                                     " names vertex " + std::to_string(cells[i]) + " of " +
                                     std::to_string(point_count));
    }
  }
}

/// Refuses a facet list whose offsets or corners contradict each other or the points.
inline void check_facets(const FacetList& f, std::size_t point_count, const std::string& file) {
  auto bad = [&](const std::string& why) { throw FormatError(file, 0, "facet list: " + why); };
  const std::size_t n = f.facet_count();
  if (f.hole_end.size() != n || (!f.labels.empty() && f.labels.size() != n)) bad("per-facet arrays differ in length");
  if (f.holes.size() % 3 != 0) bad("facet holes are not 3 coordinates each");
  check_finite(f.holes, file, "facet hole coordinate");
  for (std::size_t i = 0; i < n; ++i) {
    if (f.facet_end[i] < f.polygon_begin(i) || f.facet_end[i] > f.polygon_count()) bad("facet offsets out of order");
    if (f.hole_end[i] < f.hole_begin(i) || f.hole_end[i] > f.holes.size() / 3) bad("facet hole offsets out of order");
  }
  if (n > 0 && f.facet_end.back() != f.polygon_count()) bad("polygons belong to no facet");
  for (std::size_t p = 0; p < f.polygon_count(); ++p) {
    if (f.polygon_end[p] <= f.corner_begin(p) || f.polygon_end[p] > f.corners.size()) bad("polygon offsets out of order");
  }
  if (f.polygon_count() > 0 && f.polygon_end.back() != f.corners.size()) bad("corners belong to no polygon");
  for (const Index v : f.corners) {
    if (v >= point_count) bad("a corner names vertex " + std::to_string(v) + " of " + std::to_string(point_count));
  }
}

/// Refuses a MeshData whose arrays contradict each other (FormatError, line 0, naming `file`).
inline void check_writable(const MeshData& mesh, const std::string& file) {
  if (mesh.dimension != 2 && mesh.dimension != 3) {
    throw FormatError(file, 0, "dimension " + std::to_string(mesh.dimension) + " is not 2 or 3");
  }
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  if (mesh.coordinates.size() % dim != 0 || mesh.holes.size() % dim != 0 ||
      mesh.region_points.size() % dim != 0) {
    throw FormatError(file, 0, "a coordinate array is not a multiple of the dimension");
  }
  if (mesh.region_points.size() / dim != mesh.region_attributes.size() ||
      (!mesh.region_max_measures.empty() && mesh.region_max_measures.size() != mesh.region_attributes.size())) {
    throw FormatError(file, 0, "region points, attributes and constraints differ in number");
  }
  check_finite(mesh.region_max_measures, file, "region constraint");
  check_finite(mesh.coordinates, file, "coordinate");
  check_finite(mesh.holes, file, "hole coordinate");
  check_finite(mesh.region_points, file, "region coordinate");
  check_finite(mesh.region_attributes, file, "region attribute");
  check_finite(mesh.triangle_attributes, file, "triangle attribute");
  if (!mesh.region_max_measures.empty() && mesh.region_max_measures.size() != mesh.region_attributes.size()) {
    throw FormatError(file, 0, "region points and region maximum areas differ in number");
  }
  if (!mesh.triangle_attributes.empty() && mesh.triangle_attributes.size() != mesh.triangle_count()) {
    throw FormatError(file, 0, std::to_string(mesh.triangle_attributes.size()) + " triangle attributes for " +
                                   std::to_string(mesh.triangle_count()) + " triangles");
  }
  const std::size_t n = mesh.point_count();
  if (!mesh.point_labels.empty() && mesh.point_labels.size() != n) {
    throw FormatError(file, 0, std::to_string(mesh.point_labels.size()) + " point labels for " +
                                   std::to_string(n) + " points");
  }
  check_cells(mesh.segments, mesh.segment_labels, 2, n, file, "segment");
  check_cells(mesh.triangles, mesh.triangle_labels, 3, n, file, "triangle");
  check_cells(mesh.tetrahedra, mesh.tetrahedron_labels, 4, n, file, "tetrahedron");
  check_facets(mesh.facets, n, file);
  if (mesh.dimension == 2 && !mesh.facets.empty()) throw FormatError(file, 0, "a 2D domain cannot hold facets");
  if (mesh.dimension == 2 && !mesh.tetrahedra.empty()) {
    throw FormatError(file, 0, "a 2D mesh cannot hold tetrahedra");
  }
}

}  // namespace certimesh::io::detail
