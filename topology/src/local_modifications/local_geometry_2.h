// Shared pieces of the five 2D local modifications (local_modifications_2.h): the ordered star
// of a vertex, exact positivity of a virtual triangle, and the quality of an element or a
// virtual triangle computed the same way (vertices in stored order) so that Q0 of an element
// equals, bit for bit, the quality a caller computed for it.
#pragma once

#include <optional>
#include <vector>

#include "certimesh/topology/local_modifications_2.h"

namespace certimesh::topology::local {

/// v's star in counterclockwise order: element k has v and the link edge (link[k], link[k+1])
/// (indices mod link.size() when closed). An open star (v on the boundary) has one more link
/// vertex than elements.
struct OrderedStar2 {
  std::vector<ElementId> elements;
  std::vector<VertexId> link;
  bool closed = false;
};

/// std::nullopt when v has no element or its star is not one fan connected through edges.
std::optional<OrderedStar2> ordered_star(const TriangleMesh2& mesh, VertexId v);

/// The local index of v in e, or -1.
int local_index(const TriangleMesh2& mesh, ElementId e, VertexId v);

/// Exactly counterclockwise (orient2d > 0).
bool is_positive(const Point2d& a, const Point2d& b, const Point2d& c);

/// A triangle not yet in the mesh: its vertex ids (in the order it will be added) and points.
struct VirtualTriangle {
  TriangleMesh2::Element vertices;
  std::array<Point2d, 3> points;
  Label label = 0;
};

VirtualTriangle virtual_triangle(const TriangleMesh2& mesh, const TriangleMesh2::Element& vertices,
                                 Label label);
bool is_positive(const VirtualTriangle& t);
double quality_of(const VirtualTriangle& t, const LocalModificationOptions2& options);
double quality_of(const TriangleMesh2& mesh, ElementId e, const LocalModificationOptions2& options);

/// Replaces `removed` by `added` (removal first, so facets can be re-held), returning the ids.
LocalChange2 replace_elements(TriangleMesh2& mesh, const std::vector<ElementId>& removed,
                              const std::vector<VirtualTriangle>& added);

Point2d midpoint(const Point2d& a, const Point2d& b);

}  // namespace certimesh::topology::local
