#include "certimesh/generators/domain/domain_problem.h"

#include <string>
#include <utility>

namespace certimesh::generators {

namespace {

// what() of an InvalidDomain: the first problem's sentence, and how many more there are, so a
// caller that prints only what() still names the offending ids.
std::string summary(const std::vector<DomainProblem>& problems) {
  if (problems.empty()) return "invalid domain";
  std::string text = "invalid domain: " + problems.front().message;
  if (problems.size() > 1) {
    text += " (and " + std::to_string(problems.size() - 1) + " more problem" +
            (problems.size() > 2 ? "s" : "") + ")";
  }
  return text;
}

}  // namespace

InvalidDomain::InvalidDomain(std::vector<DomainProblem> problems)
    : std::runtime_error(summary(problems)), problems_(std::move(problems)) {}

const char* to_string(DomainProblemKind kind) noexcept {
  switch (kind) {
    case DomainProblemKind::wrong_dimension: return "wrong_dimension";
    case DomainProblemKind::no_segments: return "no_segments";
    case DomainProblemKind::non_finite_coordinate: return "non_finite_coordinate";
    case DomainProblemKind::vertex_index_out_of_range: return "vertex_index_out_of_range";
    case DomainProblemKind::zero_length_segment: return "zero_length_segment";
    case DomainProblemKind::duplicate_vertices: return "duplicate_vertices";
    case DomainProblemKind::duplicate_segments: return "duplicate_segments";
    case DomainProblemKind::segments_cross: return "segments_cross";
    case DomainProblemKind::segments_overlap: return "segments_overlap";
    case DomainProblemKind::vertex_on_segment: return "vertex_on_segment";
    case DomainProblemKind::isolated_vertex: return "isolated_vertex";
    case DomainProblemKind::open_boundary: return "open_boundary";
    case DomainProblemKind::empty_domain: return "empty_domain";
    case DomainProblemKind::bad_region_attribute: return "bad_region_attribute";
    case DomainProblemKind::hole_outside_domain: return "hole_outside_domain";
  }
  return "unknown";
}

}  // namespace certimesh::generators
