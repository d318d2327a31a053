#include "certimesh/predicates/intersection/segment_segment_2d.h"

#include "dispatch.h"
#include "segment_segment_2d_rules.h"

namespace certimesh::predicates {
namespace {
template <class Sg>
struct SegmentSegment2dRules {
  static Overlap run(const std::array<Vertex2, 2>& s, const std::array<Vertex2, 2>& t) {
    return intersection_detail::segment_segment_rules<Sg>(s, t);
  }
};
}  // namespace

Overlap segment_segment_2d(const std::array<Vertex2, 2>& s, const std::array<Vertex2, 2>& t,
                           IntersectionMode mode) {
  return intersection_detail::dispatch<SegmentSegment2dRules>(s, t, mode, "segment_segment_2d");
}

}  // namespace certimesh::predicates
