// What can make a mesh invalid for its domain: one value per condition the certificate checks.
// The checker reports the first defect it finds, in the order of this list (cheap, local and
// input-level conditions before geometric and global ones), so that a mesh broken in exactly
// one way is reported with exactly that reason.
#pragma once

#include <string_view>

namespace certimesh::certificate {

enum class Defect {
  none,
  // input
  no_elements,                 // nothing to certify (no triangles in 2D, no tetrahedra in 3D)
  index_out_of_range,          // an element names a vertex that does not exist
  non_finite_coordinate,       // NaN or Inf
  duplicate_vertex,            // two vertices with identical coordinates
  unused_vertex,               // a vertex no element uses
  repeated_vertex,             // an element lists the same vertex twice
  duplicate_element,           // two elements with the same vertex set
  // combinatorial (facet pairing)
  non_manifold_facet,          // a facet shared by three or more elements
  inconsistent_orientation,    // two elements induce the same orientation on their shared facet
  // geometric, exact
  flat_element,                // zero area / volume
  inverted_element,            // negative area / volume (consistently listed, but turned over)
  non_manifold_boundary,       // the boundary facets around a vertex (2D) or edge (3D) do not
                               // alternate in orientation (a fin, a sheet inside another there);
                               // pinches that alternate are valid (design decision 8)
  t_junction,                  // a vertex lies inside a boundary facet it is not a vertex of
  boundary_intersection,       // two boundary facets meet other than in a shared vertex/edge
  multiple_cover,              // some region is covered more than once (winding number >= 2)
  // against the domain (--domain)
  invalid_domain,              // the domain itself is not a valid boundary description
  facet_off_domain_boundary,   // a boundary facet whose vertices all lie on the domain boundary
                               // but on no common domain segment/face (it cuts across)
  vertex_off_domain_boundary,  // a boundary vertex on no domain segment/face (rounding-box rule);
                               // its facets are then judged by this defect, not the one above
  domain_boundary_not_covered, // part of a domain segment/face covered by no mesh facet
  hole_covered,                // a hole point of the domain lies inside the mesh
  region_not_meshed,           // a bounded region of the domain (no hole point) left empty
};

/// The stable snake_case name used in the JSON certificate and on the command line.
std::string_view defect_name(Defect defect);

}  // namespace certimesh::certificate
