// The `delaunay2d` target: the Delaunay triangulation of a point set
// (generators::delaunay_of_points) against a brute-force exact oracle sharing no code with it.
//
// A case draws up to 24 points with integer coordinates (|x|, |y| <= 2^16): a subset of a
// small grid or of a sheared grid, lattice points of one circle (x^2 + y^2 = 25, 625 or
// 4225) with or without the centre, random integers at several ranges, all on one line, or a
// set with a repeated point, or fewer than 3 -- then scales them all by 2^k, k from -1074
// (subnormal coordinates) to 1006 (the largest that keeps them finite), which is exact.
// Checked, with every sign computed in __int128 on the integers (scaling by 2^k changes no
// sign): repeated points, fewer than 3 points and points all on one line are refused with
// DelaunayError, and everything else is not; the output keeps the coordinates bit for bit;
// every triangle is counterclockwise with positive area; no directed edge is used twice;
// every edge without a twin is a hull edge; every point is a vertex; the triangles' areas sum
// exactly to the convex hull's (monotone chain); no point is strictly inside a triangle's
// circumcircle; and the triangles are the same as those of the unscaled points.
// Payload: "K x0 y0 x1 y1 ..." (decimal integers; the points are x * 2^K).
#pragma once

#include <memory>
#include <string>

#include "certimesh/fuzz/campaign/target.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::fuzz::campaign {

/// The triangulation the target checks, so that a test can substitute a mutant.
struct DelaunayKernel {
  io::MeshData (*triangulate)(const io::MeshData& points);
};

/// generators::delaunay_of_points.
DelaunayKernel certimesh_delaunay_kernel();

std::unique_ptr<Target> make_delaunay2d_target(const DelaunayKernel& kernel, std::string name, std::string description);

/// The shipped target, named "delaunay2d".
std::unique_ptr<Target> make_delaunay2d_target();

}  // namespace certimesh::fuzz::campaign
