// Internal: exact contact tests between facets, shared by the mesh-boundary and domain checks.
#pragma once

#include <string>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

/// Whether facets f and g (vertex ids of `m`) meet beyond their shared vertices, exactly.
bool facets_meet(const MeshView& m, const Index* f, const Index* g);

/// Whether vertex v lies on the closed facet f (v not a vertex of f), exactly.
bool vertex_on_facet(const MeshView& m, Index v, const Index* f);

/// The first pair of facets of `set` that meet beyond shared vertices: `touching` when a
/// vertex of one lies on the other, else `crossing`; defect none when there is no such pair.
Finding first_contact(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing,
                      const std::string& what);

}  // namespace certimesh::certificate::detail
