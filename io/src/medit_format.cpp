// PLACEHOLDER while the format is being written (issue 4): every call refuses.
#include "certimesh/io/medit_format.h"

#include "certimesh/io/format_error.h"

namespace certimesh::io {

MeshData read_medit_format(const std::filesystem::path& path) {
  throw FormatError(path.string(), 0, "medit format not implemented yet");
}
MeshData parse_medit_format(std::string name, std::string) {
  throw FormatError(std::move(name), 0, "medit format not implemented yet");
}
std::string format_medit(const MeshData&) { throw FormatError("medit", 0, "not implemented yet"); }
void write_medit_format(const MeshData&, const std::filesystem::path& path) {
  throw FormatError(path.string(), 0, "medit format not implemented yet");
}

}  // namespace certimesh::io
