// A picture of a 2D mesh as SVG, for people: triangles filled by region label or by quality,
// boundary and constraint segments drawn thick. Not a mesh format (nothing reads it back).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

struct SvgOptions {
  double width_px = 1200.0;       // the picture's width; the height follows the aspect ratio
  bool colour_by_quality = false; // fill by 12√3|S|/P² (red 0 → green 1) instead of region
  /// When set (one value in [0, 1] per triangle), the fill by these values, red 0 → green 1
  /// (svg_cut_3.h fills each cut polygon by its tetrahedron's quality).
  const std::vector<double>* fill_values = nullptr;
};

/// The SVG text of a 2D mesh (dimension 2). Throws FormatError for a 3D mesh.
std::string svg_picture(const MeshData& mesh, const SvgOptions& options = {});

/// Writes svg_picture(mesh) to `path` atomically.
void write_svg_picture(const MeshData& mesh, const std::filesystem::path& path, const SvgOptions& options = {});

}  // namespace certimesh::io
