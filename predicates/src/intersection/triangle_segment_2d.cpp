#include "certimesh/predicates/intersection/triangle_segment_2d.h"

#include "dispatch.h"
#include "triangle_segment_2d_rules.h"

namespace certimesh::predicates {
namespace {
template <class Sg>
struct TriangleSegment2dRules {
  static Overlap run(const std::array<Vertex2, 3>& tri, const std::array<Vertex2, 2>& seg) {
    return intersection_detail::triangle_segment_2d_rules<Sg>(tri, seg);
  }
};
}  // namespace

Overlap triangle_segment_2d(const std::array<Vertex2, 3>& tri, const std::array<Vertex2, 2>& seg,
                            IntersectionMode mode) {
  return intersection_detail::dispatch<TriangleSegment2dRules>(tri, seg, mode, "triangle_segment_2d");
}

}  // namespace certimesh::predicates
