// The stable names of the defects (JSON certificate and command line).
#include "certimesh/certificate/defect.h"

namespace certimesh::certificate {

std::string_view defect_name(Defect defect) {
  switch (defect) {
    case Defect::none: return "none";
    case Defect::no_elements: return "no_elements";
    case Defect::index_out_of_range: return "index_out_of_range";
    case Defect::non_finite_coordinate: return "non_finite_coordinate";
    case Defect::duplicate_vertex: return "duplicate_vertex";
    case Defect::unused_vertex: return "unused_vertex";
    case Defect::repeated_vertex: return "repeated_vertex";
    case Defect::duplicate_element: return "duplicate_element";
    case Defect::non_manifold_facet: return "non_manifold_facet";
    case Defect::inconsistent_orientation: return "inconsistent_orientation";
    case Defect::flat_element: return "flat_element";
    case Defect::inverted_element: return "inverted_element";
    case Defect::non_manifold_boundary: return "non_manifold_boundary";
    case Defect::t_junction: return "t_junction";
    case Defect::boundary_intersection: return "boundary_intersection";
    case Defect::multiple_cover: return "multiple_cover";
    case Defect::invalid_domain: return "invalid_domain";
    case Defect::facet_off_domain_boundary: return "facet_off_domain_boundary";
    case Defect::vertex_off_domain_boundary: return "vertex_off_domain_boundary";
    case Defect::domain_boundary_not_covered: return "domain_boundary_not_covered";
    case Defect::hole_covered: return "hole_covered";
    case Defect::region_not_meshed: return "region_not_meshed";
  }
  return "unknown";
}

}  // namespace certimesh::certificate
