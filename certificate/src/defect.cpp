// The stable names of the defects (JSON certificate and command line).
#include "certimesh/certificate/defect.h"

#include <iterator>

namespace certimesh::certificate {

std::string_view defect_name(Defect defect) {
  static constexpr std::string_view names[] = {  // the order of the enum
      "none", "no_elements", "index_out_of_range", "non_finite_coordinate", "duplicate_vertex",
      "unused_vertex", "repeated_vertex", "duplicate_element", "non_manifold_facet",
      "inconsistent_orientation", "flat_element", "inverted_element", "non_manifold_boundary",
      "t_junction", "boundary_intersection", "multiple_cover", "invalid_domain",
      "facet_off_domain_boundary", "vertex_off_domain_boundary", "domain_boundary_not_covered",
      "hole_covered", "region_not_meshed", "region_label_mismatch"};
  static_assert(std::size(names) == static_cast<std::size_t>(Defect::region_label_mismatch) + 1);
  const auto i = static_cast<std::size_t>(defect);
  return i < std::size(names) ? names[i] : "unknown";
}

}  // namespace certimesh::certificate
