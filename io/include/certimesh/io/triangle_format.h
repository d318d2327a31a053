// Triangle (2D) and TetGen (3D) files: .node, .ele, .face, .poly (1-based or 0-based as the
// file's first index says). Reading X.ele also reads X.node (and X.face in 3D when present);
// reading X.poly reads its points inline or, when it declares 0 points, from X.node.
#pragma once

#include <filesystem>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_triangle_format(const std::filesystem::path& path);
/// Writes X.node and X.ele (+ X.face for boundary triangles of a tetrahedral mesh) for a path
/// ending in .node or .ele, or a single X.poly for a path ending in .poly.
void write_triangle_format(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace certimesh::io
