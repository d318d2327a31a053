// Object File Format .off (Geomview/Princeton), ASCII, read only: a closed surface or polygon
// soup. Header `OFF` (alone or followed by the counts on its line), `#` comments, then
// `nv nf ne`, nv vertices `x y z`, nf faces `n i1 .. in` (0-based indices) each optionally
// followed by colour numbers, which are ignored. `COFF`/`NOFF`/`4OFF`/binary OFF are refused.
// A file whose faces are all triangles reads into MeshData::triangles; a file with any face of
// 4 or more corners reads every face as a one-polygon facet of MeshData::facets (the corner
// order kept: OFF faces are oriented), which generators/domain/surface_3.h cuts into triangles
// exactly. A face of fewer than 3 corners or with a repeated corner is refused by line.
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_off_format(const std::filesystem::path& path);
/// Parses in-memory contents; `name` is what errors call the file (tests, fuzzing).
MeshData parse_off_format(std::string name, std::string contents);

}  // namespace certimesh::io
