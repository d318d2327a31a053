// The exact validation of a planar domain's boundary, before any meshing: every
// geometric question (do two segments cross, overlap, does a vertex lie on a segment) is
// decided by the exact predicates, never by a tolerance. Broad phase by sorting, so 10^5
// segments validate in well under a second.
//
// What this does NOT decide: whether every segment has the domain on one of its sides
// (open_boundary) and whether the domain is empty -- that needs the arrangement's faces,
// which the domain triangulation (mesh_domain_2.h) computes.
#pragma once

#include <cstddef>
#include <vector>

#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::generators {

/// Every problem of the kinds up to vertex_on_segment (see domain_problem.h), at most
/// `max_problems` of them, in a deterministic order; empty when the PSLG is valid.
std::vector<DomainProblem> validate_domain(const PlanarDomain& domain, std::size_t max_problems = 16);

/// The domain a `.poly` file describes. Throws InvalidDomain (wrong_dimension, no_segments,
/// vertex_index_out_of_range) when the file cannot describe one; no geometric check here.
PlanarDomain planar_domain_from_mesh_data(const io::MeshData& data);

/// The `.poly` form of a domain (points, segments with labels, holes, regions).
io::MeshData to_mesh_data(const PlanarDomain& domain);

}  // namespace certimesh::generators
