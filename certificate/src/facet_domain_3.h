// Internal: TetGen's polygonal facets (io::FacetList, from a 3D .poly or .smesh) as the
// certificate uses them. io/ hands over the polygons as the file has them; the geometry is
// here: each facet is checked planar exactly (orient3d), its region -- the points inside an odd
// number of its polygons, which facet hole points must mark (proofs/mesh_certificate.md, the
// polygonal facets) -- is cut into triangles on the facet's own vertices, only as a point-
// location structure: the mesh need not refine these triangles, it must tile the region, which
// the checks do per facet (its boundary edges and the mod-2 boundary of the mesh triangles on it).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

struct PolygonalFacets {
  std::vector<Index> triangles;               // 3 domain vertices each, oriented as their facet
  std::vector<std::uint32_t> facet_of;        // per triangle: the facet it tiles
  using Edge = std::pair<Index, Index>;       // (smaller, larger) domain vertex
  std::vector<std::vector<Edge>> boundary;    // per facet: edges of its region's boundary, sorted
  std::vector<std::vector<Edge>> edges;       // per facet: every polygon edge (constraints), sorted
};

/// The facets of `domain` (domain.facets non-empty) as triangles; invalid_domain naming the
/// facet (0-based, as every index the certificate reports) when one is not planar, has a
/// polygon of fewer than 3 corners, nested polygons without a facet hole, a facet hole outside
/// its holes, or cannot be cut.
Finding triangulate_facets(const io::MeshData& domain, PolygonalFacets& out);

/// A facet of the domain that the mesh covers on neither side is allowed when both of its sides
/// are outside the solid by the hole points (TetGen removes such a facet, as the window of its
/// example.poly): from a point of the facet a straight segment reaches a volume hole point, or
/// leaves the domain's bounding box, crossing no domain triangle. Sufficient, exact (rational).
bool facet_void_on_both_sides(const MeshView& geo, const FacetSet& triangles, const PolygonalFacets& facets,
                              std::uint32_t facet, const std::vector<double>& holes);

/// Whether from p a segment along a coordinate axis leaves the domain's bounding box meeting no
/// domain triangle: then p is in the unbounded part of the domain's complement (exact).
bool point_escapes(const MeshView& geo, const FacetSet& triangles, const double* p);

/// Region attributes against tetrahedron labels (m.labels, or all 0): the region point's
/// tetrahedron (exactly, by orient3d) and every tetrahedron reached from it across faces that
/// lie on no domain facet carry the label equal to the attribute. `face_on_facet[4 * e + i]`
/// says whether the face of element e opposite its corner i lies on a domain facet.
Finding region_labels(const MeshView& m, const io::MeshData& domain, const std::vector<char>& face_on_facet);

}  // namespace certimesh::certificate::detail
