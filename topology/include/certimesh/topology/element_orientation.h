// The exact orientation of a mesh element, in the mesh formats' convention (design README,
// decision 4): a triangle of a planar mesh is positive when counterclockwise (orient2d), a
// tetrahedron when det[b-a, c-a, d-a] > 0 (predicates::volume_sign). Zero exactly when the
// element is degenerate. Surface triangles have no orientation of their own in space.
#pragma once

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/volume_sign.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

inline predicates::Sign element_orientation(const TriangleMesh2& mesh, ElementId e) {
  const auto v = mesh.vertices(e);
  const auto p = [&](std::size_t i) {
    const auto q = mesh.point(v[i]);
    return predicates::Point2{q[0], q[1]};
  };
  return predicates::orient2d(p(0), p(1), p(2));
}

inline predicates::Sign element_orientation(const TetrahedralMesh3& mesh, ElementId e) {
  const auto v = mesh.vertices(e);
  const auto p = [&](std::size_t i) {
    const auto q = mesh.point(v[i]);
    return predicates::Point3{q[0], q[1], q[2]};
  };
  return predicates::volume_sign(p(0), p(1), p(2), p(3));
}

}  // namespace certimesh::topology
