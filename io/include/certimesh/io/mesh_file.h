// Reading and writing meshes by file name: the extension chooses the format.
//   .node .ele .face .poly .smesh        Triangle (2D) / TetGen (3D)   triangle_format.h
//   .mesh                                Medit (INRIA), ASCII           medit_format.h
//   .msh                                 Gmsh 4.1, ASCII                gmsh_format.h
//   .vtu                                 VTK XML unstructured grid      vtu_format.h
//   .off                                 OFF surface, read only         off_format.h
//   .stl                                 STL ASCII/binary, read only    stl_format.h
// Every failure is a FormatError "FILE:LINE: why"; a failed write leaves no partial file.
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

enum class Format { triangle, medit, gmsh, vtu, off, stl };

/// The format an extension names; throws FormatError (line 0) for an unknown extension.
Format format_of(const std::filesystem::path& path);

MeshData read_mesh(const std::filesystem::path& path);
void write_mesh(const MeshData& mesh, const std::filesystem::path& path);

/// Writes `contents` to `path` through a temporary file in the same folder and a rename, so
/// that readers never see a partial file. Throws FormatError (line 0) on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

/// Appends the shortest decimal that reads back to exactly `value` (std::to_chars).
void append_double(std::string& out, double value);

}  // namespace certimesh::io
