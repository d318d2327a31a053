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
  if (mesh.region_points.size() / dim != mesh.region_attributes.size()) {
    throw FormatError(file, 0, "region points and region attributes differ in number");
  }
  check_finite(mesh.coordinates, file, "coordinate");
  check_finite(mesh.holes, file, "hole coordinate");
  check_finite(mesh.region_points, file, "region coordinate");
  check_finite(mesh.region_attributes, file, "region attribute");
  check_finite(mesh.triangle_attributes, file, "triangle attribute");
  if (!mesh.region_max_areas.empty() && mesh.region_max_areas.size() != mesh.region_attributes.size()) {
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
  if (mesh.dimension == 2 && !mesh.tetrahedra.empty()) {
    throw FormatError(file, 0, "a 2D mesh cannot hold tetrahedra");
  }
}

}  // namespace certimesh::io::detail
