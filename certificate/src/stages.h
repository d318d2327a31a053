// Internal: the checker's stages, in the order of the Defect list (defect.h). Each returns a
// Finding whose defect is `none` when its conditions hold. proofs/mesh_certificate.md
// explains why, together, they certify an exact single cover.
#pragma once

#include <vector>

#include "mesh_view.h"
#include "sweep_2d.h"

namespace certimesh::certificate::detail {

/// Condition 1 (no_elements .. repeated_vertex). Fills `lex_order`: the vertices sorted by
/// coordinates (vertex_order_less, ties by index), for exact look-up of a point later and, in
/// 2D, as the plane sweep's event order.
Finding check_input(const MeshView& m, std::vector<Index>& lex_order);

/// The order of `lex_order` on points: 2D by y, then x (the 2D sweep's order); 3D by x, y, z.
inline bool vertex_order_less(const double* a, const double* b, int dim) {
  if (dim == 2) return a[1] != b[1] ? a[1] < b[1] : a[0] < b[0];
  for (int k = 0; k < 3; ++k)
    if (a[k] != b[k]) return a[k] < b[k];
  return false;
}

/// Condition 2 (duplicate_element, non_manifold_facet, inconsistent_orientation): matches the
/// facets by a counting sort on their smallest vertex; the unmatched ones become `boundary`.
Finding pair_facets(const MeshView& m, FacetSet& boundary, std::size_t& interior_facets);

/// Condition 3 (flat_element, inverted_element), exact; also the (approximate) worst quality.
Finding check_orientation(const MeshView& m, Statistics& stats);

/// Closed boundary components: facets (as indices into the FacetSet), a vertex on them, their
/// bounding box and the sign of the area / volume they enclose.
struct Components {
  std::vector<std::vector<std::size_t>> facets;
  std::vector<Index> vertex;
  std::vector<Box> box;
  std::vector<int> measure_sign;  // +1 outer, -1 cavity
  std::vector<std::vector<std::size_t>> enclosed_by;  // 3D: components with winding != 0 at vertex
  // Of each facet its component. 2D: `vertex` is the lowest, then leftmost vertex v, and
  // `winding_offset` what to add to W just left of v to get W just counterclockwise of the
  // component's last edge at v (non-zero only at a pinch: other components' edges between);
  // filled by check_single_cover's sweep: of each outer component (an island of the mesh), the
  // cavity component that bounds the unmeshed face around it (-1: the unbounded face). 3D:
  // `vertex` is on no other component.
  std::vector<std::size_t> of_facet;
  std::vector<int> winding_offset;
  std::vector<std::int64_t> around;
  // 2D: the same sweep's answers for the domain's hole points, when check_single_cover got them.
  std::vector<SweepAnswer> hole_answers;
};

/// Condition 4, first half (non_manifold_boundary; two facets leaving a pinch in one direction
/// are reported as their contact), and the components.
Finding check_boundary_manifold(const MeshView& m, const FacetSet& boundary, Components& comps);

/// Condition 4, second half (t_junction, boundary_intersection), exact.
Finding check_boundary_embedding(const MeshView& m, const FacetSet& boundary);

/// The first pair of facets of `set` meeting beyond shared vertices, exactly: `touching` when
/// a vertex of one lies on the other, else `crossing` (condition 4, and the domain's check).
Finding first_contact(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing, const std::string& what);

/// Whether facets i and j of `set` meet beyond their shared vertices, as a Finding (none if
/// not): `touching` when a vertex of one lies on the other, else `crossing`. Exact.
Finding contact_of(const MeshView& m, const FacetSet& set, std::size_t i, std::size_t j, Defect touching, Defect crossing,
                   const std::string& what);

/// Condition 5 (multiple_cover): winding numbers of the components at each other's vertices.
/// In 2D the sweep that finds them also answers for `hole_points` (the domain's, or none), into
/// comps.hole_answers, so condition 6 needs no second sweep.
/// `lex_order` (check_input's), when given, spares the 2D sweep its own sort of the endpoints.
Finding check_single_cover(const MeshView& m, const FacetSet& boundary, Components& comps,
                           const std::vector<std::array<double, 2>>& hole_points = {},
                           const std::vector<Index>* lex_order = nullptr);

/// Exact winding number of component `c` around point `p` (off it); the sign of the area /
/// volume enclosed by closed oriented facets (filtered, then exact).
int winding_number(const MeshView& m, const FacetSet& boundary, const std::vector<std::size_t>& c, const double* p);
int enclosed_measure_sign(const MeshView& m, const FacetSet& set, const std::vector<std::size_t>& facets);

/// The mesh vertices along domain segment `segment`, from the mesh vertex at its first domain
/// vertex to the one at its second, consecutive ones joined by a mesh edge (2D).
struct SegmentChain {
  std::int64_t segment;
  std::vector<Index> path;
};

/// Condition 6d, 2D: every chain all boundary facets oriented alike or all interior edges,
/// every boundary facet on exactly one chain; the exact area difference and its bound.
Finding check_segment_chains(const MeshView& m, const FacetSet& boundary, const std::vector<SegmentChain>& chains,
                             Statistics& stats);

/// Condition 6 (invalid_domain .. region_label_mismatch, in the order of defect.h) and the
/// statistics of boundary vertices on the domain boundary.
Finding check_domain(const MeshView& m, const FacetSet& boundary, const Components& comps,
                     const std::vector<Index>& lex_order, const io::MeshData& domain, const BoundaryTolerance& tolerance,
                     Statistics& stats);

/// Lower-case hex SHA-256 of the canonical binary form of the mesh (proofs/mesh_certificate.md).
std::string mesh_sha256(const io::MeshData& mesh);

}  // namespace certimesh::certificate::detail
