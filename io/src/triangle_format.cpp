// PLACEHOLDER while the format is being written (issue 4): every call refuses.
#include "certimesh/io/triangle_format.h"

#include "certimesh/io/format_error.h"

namespace certimesh::io {

MeshData read_triangle_format(const std::filesystem::path& path) {
  throw FormatError(path.string(), 0, "triangle format not implemented yet");
}
void write_triangle_format(const MeshData&, const std::filesystem::path& path) {
  throw FormatError(path.string(), 0, "triangle format not implemented yet");
}

}  // namespace certimesh::io
