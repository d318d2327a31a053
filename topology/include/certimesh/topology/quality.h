// Element quality measures (monograph §2.1 and §6.1).
//
//   shape quality, triangle     Q = 12√3 |S| / P²      (2.1.3), P the perimeter
//   shape quality, tetrahedron  Q = 6⁴√2 |V| / P³      (2.1.7), P the sum of the 6 edge lengths
//   size factor                 F(γ) = [m (2 - m)]³, m = min(γ, 1/γ)     (6.1.3)
//   size-aware quality          Q = F(γ) · Q_shape, γ = P / (p_d h)      (6.1.5),
//                               p_2 = 3, p_3 = 6, h the desired size at the element
//
// Each is 1 for the equilateral simplex (of edge h, for the size-aware one) and in (0, 1]
// otherwise. Whether an element is degenerate is decided by the exact predicates (orient2d,
// volume_sign), never by a tolerance: a collinear triangle or coplanar tetrahedron (including
// all-coincident vertices, P = 0) has quality exactly 0. The magnitudes |S|, |V| and P are
// computed in double, so a non-degenerate quality is accurate to a few ulps relative.
// Non-finite coordinates throw predicates::NonFiniteInput.
#pragma once

#include <array>

#include "certimesh/topology/index.h"

namespace certimesh::topology {

using Point2d = std::array<double, 2>;
using Point3d = std::array<double, 3>;

/// |S| of a planar triangle, exactly 0 when the vertices are collinear.
double triangle_area(const Point2d& a, const Point2d& b, const Point2d& c);
/// |S| = ½|(b-a) × (c-a)| of a triangle in space, exactly 0 when the vertices are collinear.
double triangle_area(const Point3d& a, const Point3d& b, const Point3d& c);
/// |V| of a tetrahedron, exactly 0 when the vertices are coplanar.
double tetrahedron_volume(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d);

double triangle_quality(const Point2d& a, const Point2d& b, const Point2d& c);
double triangle_quality(const Point3d& a, const Point3d& b, const Point3d& c);
double tetrahedron_quality(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d);

/// The smallest of the six interior dihedral angles of a tetrahedron, in degrees (70.53 for
/// a regular one); exactly 0 when the vertices are coplanar (decided exactly).
double tetrahedron_min_dihedral_angle(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d);

/// F(γ) of (6.1.3): 1 at γ = 1, falling smoothly on both sides; 0 for γ = 0.
/// Throws std::invalid_argument for a negative or NaN γ.
double size_quality_factor(double gamma);

/// (6.1.5) with the size h wanted at the element (h > 0, finite; else std::invalid_argument).
double size_aware_triangle_quality(const Point2d& a, const Point2d& b, const Point2d& c, double h);
double size_aware_tetrahedron_quality(const Point3d& a, const Point3d& b, const Point3d& c,
                                      const Point3d& d, double h);

/// Shape quality of a live element of a mesh (SimplexMesh<2,2>, <3,2> or <3,3>).
template <class Mesh>
double element_quality(const Mesh& mesh, ElementId e) {
  const auto vertices = mesh.vertices(e);
  const auto p = [&](int i) { return mesh.point(vertices[static_cast<unsigned>(i)]); };
  if constexpr (Mesh::simplex_dimension == 3)
    return tetrahedron_quality(p(0), p(1), p(2), p(3));
  else
    return triangle_quality(p(0), p(1), p(2));
}

}  // namespace certimesh::topology
