#include "local_geometry_2.h"

#include "certimesh/predicates/orient2d.h"

namespace certimesh::topology::local {

int local_index(const TriangleMesh2& mesh, ElementId e, VertexId v) {
  const auto vs = mesh.vertices(e);
  for (int i = 0; i < 3; ++i)
    if (vs[static_cast<std::size_t>(i)] == v) return i;
  return -1;
}

namespace {

VertexId vertex_at(const TriangleMesh2::Element& vs, int i) { return vs[static_cast<std::size_t>(i % 3)]; }

// Across the edge (v, b) of e = (v, a, b): the next element counterclockwise around v.
ElementId next_counterclockwise(const TriangleMesh2& mesh, ElementId e, VertexId v) {
  return mesh.neighbour(e, (local_index(mesh, e, v) + 1) % 3);
}
// Across the edge (a, v): the next element clockwise.
ElementId next_clockwise(const TriangleMesh2& mesh, ElementId e, VertexId v) {
  return mesh.neighbour(e, (local_index(mesh, e, v) + 2) % 3);
}

}  // namespace

std::optional<OrderedStar2> ordered_star(const TriangleMesh2& mesh, VertexId v) {
  if (!mesh.is_live(v)) return std::nullopt;
  const ElementId hint = mesh.incident_element(v);
  const std::size_t degree = mesh.incident_element_count(v);
  if (hint.is_none() || degree == 0) return std::nullopt;
  // Back up clockwise to the first element of an open fan (or around to the hint: closed).
  ElementId start = hint;
  bool closed = false;
  for (std::size_t step = 0; step <= degree; ++step) {
    const ElementId previous = next_clockwise(mesh, start, v);
    if (previous == no_element) break;
    if (previous == hint) {
      closed = true;
      break;
    }
    start = previous;
  }
  OrderedStar2 star;
  star.closed = closed;
  ElementId e = start;
  for (std::size_t step = 0; step < degree; ++step) {
    const auto vs = mesh.vertices(e);
    const int i = local_index(mesh, e, v);
    star.elements.push_back(e);
    star.link.push_back(vertex_at(vs, i + 1));
    const ElementId next = next_counterclockwise(mesh, e, v);
    if (next == no_element) {
      star.link.push_back(vertex_at(vs, i + 2));
      break;
    }
    if (next == start) break;
    e = next;
  }
  // A pinched star (two fans meeting at v) or a walk that did not close up where it should.
  if (star.elements.size() != degree) return std::nullopt;
  if (closed && star.link.size() != degree) return std::nullopt;
  return star;
}

bool is_positive(const Point2d& a, const Point2d& b, const Point2d& c) {
  return predicates::orient2d({a[0], a[1]}, {b[0], b[1]}, {c[0], c[1]}) == predicates::Sign::positive;
}

VirtualTriangle virtual_triangle(const TriangleMesh2& mesh, const TriangleMesh2::Element& vertices,
                                 Label label) {
  VirtualTriangle t{vertices, {}, label};
  for (std::size_t i = 0; i < 3; ++i) t.points[i] = mesh.point(vertices[i]);
  return t;
}

bool is_positive(const VirtualTriangle& t) { return is_positive(t.points[0], t.points[1], t.points[2]); }

double quality_of(const VirtualTriangle& t, const LocalModificationOptions2& options) {
  return options.quality(t.points[0], t.points[1], t.points[2]);
}

double quality_of(const TriangleMesh2& mesh, ElementId e, const LocalModificationOptions2& options) {
  return quality_of(virtual_triangle(mesh, mesh.vertices(e), mesh.label(e)), options);
}

LocalChange2 replace_elements(TriangleMesh2& mesh, const std::vector<ElementId>& removed,
                              const std::vector<VirtualTriangle>& added) {
  LocalChange2 change{removed, {}};
  for (const ElementId e : removed) mesh.remove_element(e);
  for (const VirtualTriangle& t : added) change.added.push_back(mesh.add_element(t.vertices, t.label));
  return change;
}

Point2d midpoint(const Point2d& a, const Point2d& b) {
  return {0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]};
}

}  // namespace certimesh::topology::local
