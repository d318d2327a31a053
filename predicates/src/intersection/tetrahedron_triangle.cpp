#include "certimesh/predicates/intersection/tetrahedron_triangle.h"

#include "dispatch.h"
#include "triangle_segment_3d_rules.h"

namespace certimesh::predicates {
namespace {

using intersection_detail::fully_shared;
using intersection_detail::shared_index;
using intersection_detail::triangle_segment_3d_rules;

// Algorithm 17, steps 1-2: a tetrahedron face against a triangle edge (12 calls), the
// triangle against a tetrahedron edge (6 calls).
template <class Sg>
bool boundaries_meet(const std::array<Vertex3, 4>& tet, const std::array<Vertex3, 3>& tri) {
  for (int skip = 0; skip < 4; ++skip) {
    const std::array<Vertex3, 3> face{tet[(skip + 1) % 4], tet[(skip + 2) % 4],
                                      tet[(skip + 3) % 4]};
    for (int i = 0; i < 3; ++i)
      if (triangle_segment_3d_rules<Sg>(face, {tri[i], tri[(i + 1) % 3]}) == Overlap::intersect)
        return true;
  }
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (triangle_segment_3d_rules<Sg>(tri, {tet[i], tet[j]}) == Overlap::intersect) return true;
  return false;
}

// p strictly outside a face of the tetrahedron whose orientation is `orientation` != 0:
// replacing a vertex by p flips the sign.
template <class Sg>
bool certified_outside(const std::array<Vertex3, 4>& tet, int orientation, const Point3& p) {
  for (int i = 0; i < 4; ++i) {
    std::array<Point3, 4> t{tet[0].point, tet[1].point, tet[2].point, tet[3].point};
    t[i] = p;
    if (Sg::o3(t[0], t[1], t[2], t[3]) == -orientation) return true;
  }
  return false;
}

// Steps 3-13. The boundaries do not meet outside the shared simplex, so the triangle is
// either inside the tetrahedron or meets it only there; one free vertex certified outside
// rules out the first. "Inside" is "not certified outside" (digest C §1.5 [CAVEAT]).
template <class Sg>
Overlap containment(const std::array<Vertex3, 4>& tet, const std::array<Vertex3, 3>& tri) {
  const int orientation = Sg::o3(tet[0].point, tet[1].point, tet[2].point, tet[3].point);
  if (orientation == 0) return Overlap::intersect;  // no outside is known
  for (const Vertex3& v : tri)
    if (shared_index(v, std::span<const Vertex3>(tet)) < 0 &&
        certified_outside<Sg>(tet, orientation, v.point))
      return Overlap::disjoint;
  return Overlap::intersect;
}

template <class Sg>
struct TetrahedronTriangleRules {
  static Overlap run(const std::array<Vertex3, 4>& tet, const std::array<Vertex3, 3>& tri) {
    const std::span<const Vertex3> ts(tet), fs(tri);
    if (fully_shared(fs, ts) || fully_shared(ts, fs)) return Overlap::disjoint;
    if (boundaries_meet<Sg>(tet, tri)) return Overlap::intersect;
    return containment<Sg>(tet, tri);
  }
};

}  // namespace

Overlap tetrahedron_triangle(const std::array<Vertex3, 4>& tet, const std::array<Vertex3, 3>& tri,
                             IntersectionMode mode) {
  return intersection_detail::dispatch<TetrahedronTriangleRules>(tet, tri, mode, "tetrahedron_triangle");
}

}  // namespace certimesh::predicates
