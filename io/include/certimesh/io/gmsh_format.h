// Gmsh .msh version 4.1 ASCII ($MeshFormat, $Entities, $Nodes, $Elements; labels as physical tags of entities).
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_gmsh_format(const std::filesystem::path& path);
/// Parses in-memory contents; `name` is what errors call the file (tests, fuzzing).
MeshData parse_gmsh_format(std::string name, std::string contents);
/// The file contents that write_gmsh_format writes.
std::string format_gmsh(const MeshData& mesh);
void write_gmsh_format(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace certimesh::io
