// Algorithm 16 (digest C §1.4), written once for both sign sources (sign_source.h).
//
// Certificates: the triangle's plane with both segment ends strictly on one side; for a
// segment crossing the plane strictly, the line pq passing strictly outside one edge
// pair (two strictly opposite signs among k1, k2, k3 = the pierce point's barycentric
// signs); a separating line in a coordinate-plane projection. With exact signs, the
// coplanar and mixed cases (one end in the plane) are decided in the first projection in
// which the triangle's projection has a non-zero orientation, so the rules are complete
// for a non-degenerate triangle and segment.
#pragma once

#include <array>

#include "bounding_box.h"
#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"
#include "projection.h"
#include "shared_vertices.h"
#include "sign_source.h"
#include "triangle_segment_2d_rules.h"

namespace certimesh::predicates::intersection_detail {

/// The line pq misses the closed triangle: two strictly opposite pierce-point signs.
template <class Sg>
bool line_passes_outside(const std::array<Point3, 3>& t, const Point3& p, const Point3& q) {
  const int k[3] = {Sg::o3(p, q, t[1], t[2]), Sg::o3(p, q, t[2], t[0]), Sg::o3(p, q, t[0], t[1])};
  bool pos = false, neg = false;
  for (int s : k) {
    pos = pos || s > 0;
    neg = neg || s < 0;
  }
  return pos && neg;
}

/// Triangle and segment in a projection (Algorithm 11, case 0). Exact: the verdict of the
/// first projection where the triangle stays a triangle. Conservative: any certificate.
template <class Sg>
Overlap projected_no_shared(const std::array<Point3, 3>& t, const Point3& p, const Point3& q) {
  for (int k = 0; k < 3; ++k) {
    const int ax = projection_axis(k);
    const std::array<Point2, 3> pt{project(t[0], ax), project(t[1], ax), project(t[2], ax)};
    if (Sg::exact && Sg::o2(pt[0], pt[1], pt[2]) == 0) continue;
    const Overlap r = triangle_segment_no_shared<Sg>(pt, project(p, ax), project(q, ax));
    if (r == Overlap::disjoint || Sg::exact) return r;
  }
  return Overlap::intersect;
}

template <class Sg>
Overlap triangle_segment_3d_no_shared(const std::array<Point3, 3>& t, const Point3& p,
                                      const Point3& q) {
  const std::array<Point3, 2> seg{p, q};
  if (boxes_apart(t, seg)) return Overlap::disjoint;
  const int s4 = Sg::o3(t[0], t[1], t[2], p);
  const int s5 = Sg::o3(t[0], t[1], t[2], q);
  if (s4 != 0 && s4 == s5) return Overlap::disjoint;  // same open half-space
  if (s4 != 0 && s4 == -s5) {                         // strictly crossing the plane
    if (line_passes_outside<Sg>(t, p, q)) return Overlap::disjoint;
    if (Sg::exact) return Overlap::intersect;
  }
  if (Sg::exact && s4 == 0 && s5 != 0) return projected_no_shared<Sg>(t, p, p);  // mixed:
  if (Sg::exact && s5 == 0 && s4 != 0) return projected_no_shared<Sg>(t, q, q);  // one point
  return projected_no_shared<Sg>(t, p, q);
}

/// Triangle (v, a, b), segment (v, w).
template <class Sg>
Overlap triangle_segment_3d_one_shared(const Point3& v, const Point3& a, const Point3& b,
                                       const Point3& w) {
  if (w == v) return Overlap::disjoint;  // the segment is the shared point itself
  // w strictly off the plane: the segment meets the plane, hence the triangle, at v only.
  if (Sg::o3(v, a, b, w) != 0) return Overlap::disjoint;
  for (int k = 0; k < 3; ++k) {
    const int ax = projection_axis(k);
    const Point2 pv = project(v, ax), pa = project(a, ax), pb = project(b, ax);
    if (Sg::o2(pv, pa, pb) == 0) continue;
    const Overlap r = triangle_segment_one_shared<Sg>(pv, pa, pb, project(w, ax));
    if (r == Overlap::disjoint || Sg::exact) return r;
  }
  return Overlap::intersect;
}

template <class Sg>
Overlap triangle_segment_3d_rules(const std::array<Vertex3, 3>& tri,
                                  const std::array<Vertex3, 2>& seg) {
  const std::span<const Vertex3> ts(tri), ss(seg);
  if (fully_shared(ss, ts) || fully_shared(ts, ss)) return Overlap::disjoint;
  for (int i = 0; i < 2; ++i) {
    const int j = shared_index(seg[i], ts);
    if (j >= 0)
      return triangle_segment_3d_one_shared<Sg>(tri[j].point, tri[(j + 1) % 3].point,
                                                tri[(j + 2) % 3].point, seg[1 - i].point);
  }
  return triangle_segment_3d_no_shared<Sg>({tri[0].point, tri[1].point, tri[2].point}, seg[0].point,
                                           seg[1].point);
}

}  // namespace certimesh::predicates::intersection_detail
