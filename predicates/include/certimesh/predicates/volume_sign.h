// The one place where the sign conventions of the kernel and of the mesh formats meet.
//
// orient3d(a, b, c, d) follows Shewchuk: the sign of det[a - d; b - d; c - d]. Meshes
// (Medit, Gmsh, VTK) call a tetrahedron (a, b, c, d) positive when det[b - a; c - a; d - a] > 0.
// The two determinants are negatives of each other, and this is the only function that
// says so.
#pragma once

#include "certimesh/predicates/orient3d.h"

namespace certimesh::predicates {

/// Sign of the signed volume det[b - a; c - a; d - a] of the tetrahedron (a, b, c, d):
/// positive for a positively oriented tetrahedron in the Medit/Gmsh convention. Exact.
inline Sign volume_sign(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return -orient3d(a, b, c, d);
}

/// The same, conservative: certain only when exact (the 3D d() of the monograph).
inline FilteredSign volume_sign_filtered(const Point3& a, const Point3& b, const Point3& c,
                                         const Point3& d) noexcept {
  return -orient3d_filtered(a, b, c, d);
}

}  // namespace certimesh::predicates
