// Medit .mesh, ASCII (MeshVersionFormatted 1 or 2, Dimension 2|3, Vertices, Edges, Triangles, Tetrahedra, each with a reference label).
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_medit_format(const std::filesystem::path& path);
/// Parses in-memory contents; `name` is what errors call the file (tests, fuzzing).
MeshData parse_medit_format(std::string name, std::string contents);
/// The file contents that write_medit_format writes.
std::string format_medit(const MeshData& mesh);
void write_medit_format(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace certimesh::io
