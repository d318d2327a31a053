// Triangle (2D) and TetGen (3D) files: .node, .ele, .face, .edge, .poly, .smesh (1-based or
// 0-based as the .node's first point number says). Reading X.node, X.ele, X.face or X.edge reads
// the mesh X: X.node (required), the named file (required) and whichever of the other three
// exist (X.face only in 3D). Reading X.poly or X.smesh reads its points inline or, when it
// declares 0 points, from X.node; a 3D one's facets go into MeshData::facets as polygons.
// Conventions: docs/formats.md.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_triangle_format(const std::filesystem::path& path);
/// Writes X.node and X.ele (+ X.face for boundary triangles of a tetrahedral mesh, + X.edge for
/// segments) for a path ending in .node, .ele, .face or .edge, or a single X.poly / X.smesh for
/// a path ending in .poly / .smesh.
void write_triangle_format(const MeshData& mesh, const std::filesystem::path& path);

/// Where parse_triangle_format finds a companion file (X.node beside X.ele, ...): its
/// contents, or nullopt when there is no such file.
using CompanionFiles = std::function<std::optional<std::string>(const std::filesystem::path&)>;
/// In-memory form of read_triangle_format (tests, fuzzing): `path` names the main file, whose
/// extension says what it is and which errors name; `contents` is that file.
MeshData parse_triangle_format(const std::filesystem::path& path, std::string contents,
                               const CompanionFiles& companions);

}  // namespace certimesh::io
