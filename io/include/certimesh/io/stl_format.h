// STL (stereolithography), ASCII and binary, read only: a triangle soup that certimesh welds
// into a surface. Binary is recognised by its size, 84 + 50 n bytes for the n triangles its
// header announces, not by the word `solid` (binary files often begin with it); a file that
// begins with `solid` and holds no NUL byte is ASCII; anything else is refused (a truncated
// binary file names the announced and the actual size). Normals are ignored (the corner
// order orients a triangle), and so are the binary attribute bytes. Corners with equal
// coordinates (==, so -0 and 0 are one point) become one vertex, numbered in order of first
// appearance, with the coordinates of that first appearance; triangle i is the file's i-th
// (0-based). An ASCII file of several `solid` blocks labels each triangle with its block's
// 1-based number. NaN and infinite coordinates are refused naming the line (ASCII) or the
// triangle (binary, line 0).
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_stl_format(const std::filesystem::path& path);
/// Parses in-memory contents (binary or ASCII); `name` is what errors call the file.
MeshData parse_stl_format(std::string name, std::string contents);

}  // namespace certimesh::io
