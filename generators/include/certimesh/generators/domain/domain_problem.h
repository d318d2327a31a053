// What can be wrong with a planar domain, and where. Every refusal names the offending
// segment ids and vertex ids (0-based, as in PlanarDomain) and a message a person can act on
// ("segments 3 (0 0)-(1 0) and 7 (0.5 -1)-(0.5 1) cross"). Coordinates in messages are
// printed so that they read back bit for bit.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace certimesh::generators {

enum class DomainProblemKind {
  wrong_dimension,          // not a 2D file
  no_segments,              // nothing bounds a region
  non_finite_coordinate,    // NaN or infinite point, hole or region coordinate
  vertex_index_out_of_range,
  zero_length_segment,      // both ends are the same vertex, or bit-identical points
  duplicate_vertices,       // two vertex ids with bit-identical coordinates
  duplicate_segments,       // the same vertex pair twice
  segments_cross,           // interiors meet in one point
  segments_overlap,         // collinear segments sharing more than a point
  vertex_on_segment,        // a vertex in the open interior of a segment (a T-junction)
  isolated_vertex,          // no longer refused: an isolated vertex is a mesh vertex (kept for callers)
  open_boundary,            // a segment with the domain on neither side (an open loop)
  empty_domain,             // every face is a hole or unbounded
  bad_region_attribute,     // a .poly region attribute that is not a finite number
  hole_outside_domain,      // a hole point in no bounded face of the segments
};

struct DomainProblem {
  DomainProblemKind kind{};
  std::vector<std::uint32_t> segments;  // offending segment ids
  std::vector<std::uint32_t> vertices;  // offending vertex ids
  std::string message;                  // the whole sentence, ids and coordinates included
};

/// Thrown by the generators when a domain is refused; holds every problem found (capped).
class InvalidDomain : public std::runtime_error {
 public:
  explicit InvalidDomain(std::vector<DomainProblem> problems);
  const std::vector<DomainProblem>& problems() const noexcept { return problems_; }

 private:
  std::vector<DomainProblem> problems_;
};

const char* to_string(DomainProblemKind kind) noexcept;

}  // namespace certimesh::generators
