// Internal: condition 6, the mesh against its domain (--domain).
#pragma once

#include <vector>

#include "stages.h"

namespace certimesh::certificate::detail {

/// invalid_domain .. region_not_meshed, in the order of defect.h; fills the statistics of the
/// boundary vertices on the domain boundary. `lex_order` sorts the mesh vertices by coordinates.
Finding check_domain(const MeshView& m, const FacetSet& boundary, const Components& comps,
                     const std::vector<Index>& lex_order, const io::MeshData& domain, Statistics& stats);

}  // namespace certimesh::certificate::detail
