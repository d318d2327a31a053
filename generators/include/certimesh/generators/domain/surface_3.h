// A closed triangulated surface as the 3D mesher takes it (issue 13, design decision 8): points,
// oriented triangles with a label and the input facet each comes from, and TetGen's hole and
// region points. Built from what the readers return (io::MeshData):
//   - triangles (Medit .mesh Triangles, .off, .stl, a .face): as given, oriented by corner order;
//   - TetGen facets (.poly/.smesh, or an OFF file with polygons): each facet cut into triangles
//     on its own vertices, exactly (surface_3.cpp): a facet must be one planar simple polygon
//     (collinear and reflex corners allowed), cut by ear clipping; several polygons, facet
//     holes, isolated points or segments in a facet are refused as bad_facet (not yet supported).
// Whether the corner order means anything is `oriented`: true for .mesh, .off, .stl; false for
// .poly/.smesh, whose facets TetGen reads without orientation (surface_validation_3.h then
// orients every shell outward).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "certimesh/io/mesh_data.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

struct Surface3 {
  std::vector<predicates::Point3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<io::Label> labels;          // one per triangle (0 when the file has none)
  std::vector<std::uint32_t> facet_of;    // per triangle: its input facet / polygon / triangle
  bool from_facets = false;               // facet_of names TetGen facets (or OFF polygons)
  bool oriented = true;                   // the corner order orients the triangles
  std::vector<predicates::Point3> holes;  // TetGen volume hole points
  std::vector<predicates::Point3> region_points;
  std::vector<double> region_attributes;  // one per region point
  std::vector<double> region_max_volumes; // empty, or one per region point (negative: none)
};

/// The surface `data` describes, with `oriented` as the file format says. Throws
/// InvalidSurface (wrong_dimension, no_triangles, vertex_index_out_of_range, bad_facet);
/// cost O(n) plus O(k^2) per polygonal facet of k corners.
Surface3 surface_from_mesh_data(const io::MeshData& data, bool oriented);

/// Reads `path` (.mesh .off .stl .poly .smesh .face .ele, any reader of io/mesh_file.h) and
/// builds its surface, oriented unless it is a .poly/.smesh. Throws io::FormatError for an
/// unreadable file, InvalidSurface as above.
Surface3 read_surface_3(const std::filesystem::path& path);

/// "(x y z)" with each coordinate the shortest decimal that reads back to it.
std::string format_point(const predicates::Point3& p);
/// "triangle 7 (0 0 0)-(1 0 0)-(0 1 0)", with " of facet F" when the triangle was cut from one.
std::string describe_triangle(const Surface3& s, std::uint32_t t);

}  // namespace certimesh::generators
