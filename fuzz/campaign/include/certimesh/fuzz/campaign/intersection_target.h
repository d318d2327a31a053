// The `intersection` target: the five intersection tests (segment_segment_2d,
// triangle_segment_2d, triangle_segment_3d, tetrahedron_triangle, triangle_triangle_3d) in
// both modes, against an exact linear-programming oracle (hull_intersection_oracle.h)
// that shares no code with the kernel.
//
// A case draws a pool of 8 points -- uniform in [-1, 1], small integers (collinear,
// coplanar, coincident galore), exact midpoints/quarter points/reflections/copies of them,
// those moved by 1-2 ulps, on the plane z = x + y, or scaled by 2^600 or 2^-600 -- then one
// test and its elements by pool index; points with identical coordinates get the same
// vertex id, so repeated picks are shared vertices. 1 case in 32 gets one NaN or infinite
// coordinate. Checked: exact mode equals the oracle, and so does exact mode with the first
// element's vertices in reverse order; conservative mode never answers `disjoint` for an
// intersecting pair; non-finite input: exact throws NonFiniteInput, conservative answers
// `intersect`. Cases where both elements are degenerate and share a vertex are skipped
// (the oracle's question is then not defined). Payload: "TEST x y [z] ..." in %a.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "certimesh/fuzz/campaign/target.h"
#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::fuzz::campaign {

/// The kernel functions the target calls (a test substitutes a mutant).
struct IntersectionKernel {
  using V2 = predicates::Vertex2;
  using V3 = predicates::Vertex3;
  using Mode = predicates::IntersectionMode;
  using Overlap = predicates::Overlap;
  Overlap (*segment_segment_2d)(const std::array<V2, 2>&, const std::array<V2, 2>&, Mode);
  Overlap (*triangle_segment_2d)(const std::array<V2, 3>&, const std::array<V2, 2>&, Mode);
  Overlap (*triangle_segment_3d)(const std::array<V3, 3>&, const std::array<V3, 2>&, Mode);
  Overlap (*tetrahedron_triangle)(const std::array<V3, 4>&, const std::array<V3, 3>&, Mode);
  Overlap (*triangle_triangle_3d)(const std::array<V3, 3>&, const std::array<V3, 3>&, Mode);
};

/// certimesh's own intersection tests.
IntersectionKernel certimesh_intersection_kernel();

std::unique_ptr<Target> make_intersection_target(const IntersectionKernel& kernel, std::string name,
                                                 std::string description);

/// The shipped target, named "intersection".
std::unique_ptr<Target> make_intersection_target();

}  // namespace certimesh::fuzz::campaign
