// The Delaunay triangulation of a 2D point set, as a mesh: what `certimesh mesh POINTS.node`
// writes (Triangle's behaviour for a .node file: the convex hull, every point a vertex).
#pragma once

#include "certimesh/io/mesh_data.h"

namespace certimesh::generators {

/// The Delaunay triangulation of the points of `points` (dimension 2; segments and elements,
/// if any, are ignored), exact with symbolic perturbation: every point is a vertex, points on
/// the hull between two others included; vertex labels are kept. Throws DelaunayError for a
/// non-finite or repeated point (naming the indices) and for fewer than three points or points
/// all on one line (no triangle).
io::MeshData delaunay_of_points(const io::MeshData& points);

}  // namespace certimesh::generators
