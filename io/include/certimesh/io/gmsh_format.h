// Gmsh .msh version 4.1 ASCII ($MeshFormat, $Entities, $Nodes, $Elements; labels as physical
// tags of entities).
//
// Writing (`4.1 0 8`; a 2D mesh with tetrahedra is refused; holes and region points, which only
// .poly holds, are not written):
//  - every (dimension, label) pair of the mesh's cells becomes one entity (curve, surface or
//    volume) whose only physical tag is the label, label 0 included (physical tag 0). Why 0 is
//    written rather than left out: Gmsh saves only elements of physical groups (unless
//    Mesh.SaveAll), and meshio 5.0 fails on files that mix entities with and without physical
//    tags; with a tag on every entity, Gmsh keeps every element and meshio gives one
//    cell_data["gmsh:physical"] value per cell. Entity tags count from 1 per dimension, in
//    ascending label order; no $PhysicalNames.
//  - all nodes go in one block on the first entity of the highest dimension, tags 1..N in
//    point order; 2D points are written with z = 0.
//  - element tags number the cells 1.. in the order segments, triangles, tetrahedra, each kind
//    in its MeshData order (so the reader restores that order); types 1, 2, 4.
//  - point labels (when present) as a `$NodeData` view named "label", one integer per node:
//    meshio reads it as point_data["label"]; Gmsh loads it as a post-processing view (a Gmsh
//    re-save of the mesh drops it).
//
// Reading:
//  - $MeshFormat must be `4.1 0 <size>`: binary files (file-type 1) and other versions are
//    refused. $Entities, $Nodes and $Elements are read; $NodeData named "label" with one
//    component gives the point labels (nodes it does not list get 0); every other section
//    ($PhysicalNames, $Periodic, $Comments, other views, ...) is skipped. The $Nodes header may
//    declare more nodes than its blocks hold (Gmsh 4.8 does so when it leaves out entities that
//    have no physical group), not fewer.
//  - node tags may be any positive integers, in any block order: point i is the node with the
//    i-th smallest tag. Parametric coordinates are read and dropped.
//  - element types 1 (line), 2 (triangle), 4 (tetrahedron) become segments, triangles,
//    tetrahedra, each kind ordered by element tag; type 15 (point) is skipped; any other type
//    (quadrangles, second-order elements, ...) is refused naming its line.
//  - an element's label is the first physical tag of its entity, 0 when the entity has none, is
//    not listed or the file has no $Entities; a cell kind whose labels are all 0 reads with an
//    empty label vector (MeshData: "empty = all 0").
//  - dimension: 3 when the file has a tetrahedron or a node with z != 0, otherwise 2. A planar
//    surface mesh in the plane z = 0 written as 3D therefore reads back as 2D (the format does
//    not say which was meant).
//
// Precision: certimesh writes the shortest decimal that reads back bit for bit. Gmsh 4.8 itself
// writes 16 significant digits (%.16g), so a mesh re-saved by Gmsh may come back with
// coordinates one or two ulps off (tests/io/interop_test.py measures and bounds it).
#pragma once

#include <filesystem>
#include <string>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io {

MeshData read_gmsh_format(const std::filesystem::path& path);
/// Parses in-memory contents; `name` is what errors call the file (tests, fuzzing).
MeshData parse_gmsh_format(std::string name, std::string contents);
/// The file contents that write_gmsh_format writes.
std::string format_gmsh(const MeshData& mesh);
void write_gmsh_format(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace certimesh::io
