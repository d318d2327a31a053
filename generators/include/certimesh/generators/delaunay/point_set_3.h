// The Delaunay tetrahedralization of a 3D point set, as a mesh: what `certimesh mesh
// POINTS.node` writes for a .node of dimension 3 (TetGen's behaviour: the convex hull, every
// point a vertex).
#pragma once

#include "certimesh/generators/progress.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::generators {

/// The Delaunay tetrahedralization (Delaunay3) of the points of `points` (dimension 3;
/// segments and elements, if any, are ignored): every point a vertex, vertex labels kept,
/// tetrahedra positive. Throws DelaunayError for a non-finite or repeated point (naming the
/// indices and the coordinates), for fewer than four points and for points all in one plane.
/// Reports progress as stage "delaunay" (points inserted of all).
io::MeshData delaunay_of_points_3(const io::MeshData& points, const ProgressCallback& progress = {});

}  // namespace certimesh::generators
