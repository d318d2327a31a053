#include "certimesh/predicates/intersection/triangle_segment_3d.h"

#include "dispatch.h"
#include "triangle_segment_3d_rules.h"

namespace certimesh::predicates {
namespace {
template <class Sg>
struct TriangleSegment3dRules {
  static Overlap run(const std::array<Vertex3, 3>& tri, const std::array<Vertex3, 2>& seg) {
    return intersection_detail::triangle_segment_3d_rules<Sg>(tri, seg);
  }
};
}  // namespace

Overlap triangle_segment_3d(const std::array<Vertex3, 3>& tri, const std::array<Vertex3, 2>& seg,
                            IntersectionMode mode) {
  return intersection_detail::dispatch<TriangleSegment3dRules>(tri, seg, mode, "triangle_segment_3d");
}

}  // namespace certimesh::predicates
