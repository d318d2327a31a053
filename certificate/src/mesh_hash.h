// Internal: the SHA-256 of the canonical binary form of a mesh (proofs/mesh_certificate.md,
// "The JSON certificate"), and the JSON certificate itself.
#pragma once

#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::certificate::detail {

/// Lower-case hex SHA-256 of: "certimesh-mesh-v1\n", dimension (u32), vertex count (u64),
/// element count (u64), every coordinate (f64), every element's vertex indices (u32), every
/// element's label (i32, 0 when the file has none); all little-endian.
std::string mesh_sha256(const io::MeshData& mesh);

}  // namespace certimesh::certificate::detail
