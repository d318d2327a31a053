// A picture of a tetrahedral mesh for people: the tetrahedra cut by the plane z = Z, each
// cut polygon filled by a value the caller gives per tetrahedron (its quality: red 0 ->
// green 1), the boundary's trace drawn thick. Not a mesh format (nothing reads it back).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "certimesh/io/mesh_data.h"
#include "certimesh/io/svg_picture.h"

namespace certimesh::io {

/// The middle of the mesh's z range: the default cut.
double middle_z(const MeshData& mesh);

/// The SVG text of the cut of `mesh` (dimension 3, tetrahedra) by z = `z`, seen from above;
/// `values` holds one number in [0, 1] per tetrahedron. Throws FormatError for a 2D mesh, an
/// index out of range, or a value count that is not the tetrahedron count.
std::string svg_cut_picture(const MeshData& mesh, double z, const std::vector<double>& values,
                            const SvgOptions& options = {});

/// Writes svg_cut_picture(...) to `path` atomically.
void write_svg_cut_picture(const MeshData& mesh, double z, const std::vector<double>& values,
                           const std::filesystem::path& path, const SvgOptions& options = {});

}  // namespace certimesh::io
