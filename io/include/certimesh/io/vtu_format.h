// VTK .vtu: XML UnstructuredGrid with ASCII DataArrays; labels as the CellData array "label".
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_vtu_format(const std::filesystem::path& path);
/// Parses in-memory contents; `name` is what errors call the file (tests, fuzzing).
MeshData parse_vtu_format(std::string name, std::string contents);
/// The file contents that write_vtu_format writes.
std::string format_vtu(const MeshData& mesh);
void write_vtu_format(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace certimesh::io
