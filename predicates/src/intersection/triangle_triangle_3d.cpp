#include "certimesh/predicates/intersection/triangle_triangle_3d.h"

#include "dispatch.h"
#include "triangle_segment_3d_rules.h"

namespace certimesh::predicates {
namespace {

using intersection_detail::fully_shared;
using intersection_detail::triangle_segment_3d_rules;

// A point of the intersection outside the shared simplex lies on an edge of one triangle
// (a vertex of the intersection polygon is on both boundaries or is a free vertex), and
// each edge test is itself second-type-safe, so `disjoint` below is certified.
template <class Sg>
bool an_edge_meets(const std::array<Vertex3, 3>& edges_of, const std::array<Vertex3, 3>& other) {
  for (int i = 0; i < 3; ++i) {
    const std::array<Vertex3, 2> e{edges_of[i], edges_of[(i + 1) % 3]};
    if (triangle_segment_3d_rules<Sg>(other, e) == Overlap::intersect) return true;
  }
  return false;
}

template <class Sg>
struct TriangleTriangle3dRules {
  static Overlap run(const std::array<Vertex3, 3>& a, const std::array<Vertex3, 3>& b) {
    const std::span<const Vertex3> as(a), bs(b);
    if (fully_shared(as, bs) || fully_shared(bs, as)) return Overlap::disjoint;
    if (an_edge_meets<Sg>(a, b) || an_edge_meets<Sg>(b, a)) return Overlap::intersect;
    return Overlap::disjoint;
  }
};

}  // namespace

Overlap triangle_triangle_3d(const std::array<Vertex3, 3>& a, const std::array<Vertex3, 3>& b,
                             IntersectionMode mode) {
  return intersection_detail::dispatch<TriangleTriangle3dRules>(a, b, mode, "triangle_triangle_3d");
}

}  // namespace certimesh::predicates
