// VTK .vtu: XML UnstructuredGrid; labels as the CellData / PointData arrays "label".
//
// Writing (ASCII DataArrays only, `version="1.0" byte_order="LittleEndian"`; a 2D mesh with
// tetrahedra is refused; holes and region points, which only .poly holds, are not written):
//  - FieldData Int32 "certimesh_dimension" (2 or 3), so that a 2D mesh and a planar 3D surface
//    mesh both round-trip;
//  - Points: Float64, 3 components (z = 0 in 2D), shortest round-trip decimals;
//  - Cells: Int64 connectivity (0-based), Int64 offsets, UInt8 types: all segments (3 VTK_LINE),
//    then all triangles (5 VTK_TRIANGLE), then all tetrahedra (10 VTK_TETRA), each in MeshData
//    order;
//  - CellData Int32 "label", one per cell (0 where MeshData has none);
//  - PointData Int32 "label" when the mesh has point labels.
//
// Reading: one <UnstructuredGrid> with one <Piece>, version 0.1 or 1.0. DataArrays may be
// `format="ascii"` or `format="binary"` (inline base64, header_type UInt32 or UInt64,
// LittleEndian; uncompressed, with or without a separate base64 block for the header, or
// compressed by `vtkZLibDataCompressor`, meshio's default, inflated with zlib no further than
// the piece's counts can use). Other compressors (LZ4, LZMA) and appended data are refused:
// write them with meshio `binary=False`, `compression=None` or "zlib". Cell types 3, 5, 10 are
// read, type 1 (vertex) is skipped, any other type is refused naming the line of the types array.
// Cells of each kind keep their file order. Labels come from the CellData / PointData arrays
// named "label" (integer types); other arrays are ignored. A cell kind whose labels are all 0
// reads with an empty label vector (MeshData: "empty = all 0"). Dimension: the FieldData
// "certimesh_dimension" when present (2 requires every z = 0), otherwise 3 when there is a
// tetrahedron or a point with z != 0, else 2.
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
