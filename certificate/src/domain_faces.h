// Internal: the faces of a 2D domain's segment arrangement, by Triangle's rules (design
// decision 8), for condition 6: the domain is the bounded faces minus those holding a hole
// point. Decided independently of the mesh and of the generators, exactly:
//  * the boundary cycles of the arrangement, by following each half-edge to the next one
//    clockwise around its head (angular order by half-plane, then orient2d);
//  * the face around each connected component, by the plane sweep (sweep_2d.h): the first
//    segment a leftward ray from the component's lowest, then leftmost, vertex hits bounds it;
//    isolated vertices and hole points are located the same way.
// Cost O(n log n) for n segments, vertices and hole points, whatever the shape.
#pragma once

#include <vector>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

struct DomainFaces {
  std::vector<char> segment_bounds_domain;  // per segment: a domain face on at least one side
  std::vector<char> isolated_in_domain;     // per domain vertex: on no segment, inside a domain face
  std::size_t isolated_vertices = 0;        // on no segment
};

/// `geo`: the domain's points; `segments`: its segments (validated simple); `holes`: 2D hole
/// points. Refuses (invalid_domain) a hole point in no bounded face and an isolated vertex on
/// a segment, naming them.
Finding domain_faces_2d(const MeshView& geo, const FacetSet& segments, const std::vector<double>& holes,
                        DomainFaces& out);

}  // namespace certimesh::certificate::detail
