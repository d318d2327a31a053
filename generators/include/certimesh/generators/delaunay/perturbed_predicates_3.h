// The signs the 3D Delaunay tetrahedralization decides with, as ints: the exact orientation
// and the perturbed (SoS) in-sphere sign. The filter is inline here, on the hot path; when it
// is uncertain the kernel's exact stage (orient3d) or insphere_sos decides.
//
// Why orient3d is exact and not perturbed: the tetrahedralization never holds a flat
// tetrahedron, so every in-sphere test is against four points off one plane, and then
// insphere_sos's perturbation stops at its first, lifted terms (symbolic_perturbation.h:
// the coefficient of a point's lifted entry is the orientation of the other four, and the
// tetrahedron's own is not zero). That is the perturbation of the lifting alone, a regular
// triangulation with infinitesimal generic weights: unique, with no flat tetrahedron. A
// point exactly in the plane of a hull face is decided by the same in-sphere sign
// (delaunay_3.cpp, conflicts()). orient3d_sos would instead tilt coplanar hull points into
// flat tetrahedra, as the 2D triangulation's flat hull triangles.
#pragma once

#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::generators::detail {

using predicates::Point3;

/// The exact orientation (Shewchuk's sign of det[a - d; b - d; c - d]).
inline int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const predicates::FilteredSign f = predicates::orient3d_filtered(a, b, c, d);
  if (predicates::is_certain(f)) [[likely]]
    return predicates::to_int(f);
  return predicates::to_int(predicates::orient3d(a, b, c, d));
}

/// The perturbed in-sphere sign of e against (a, b, c, d): 0 only when e equals one of them.
inline int insphere_perturbed(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
  const predicates::FilteredSign f = predicates::insphere_filtered(a, b, c, d, e);
  if (predicates::is_certain(f)) [[likely]]
    return predicates::to_int(f);
  return predicates::to_int(predicates::insphere_sos(a, b, c, d, e));
}

}  // namespace certimesh::generators::detail
