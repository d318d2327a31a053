// Shared vertices: the same id with the same coordinates (vertex.h), never coordinates
// alone.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates::intersection_detail {

inline bool same_vertex(const Vertex2& a, const Vertex2& b) {
  return a.id == b.id && a.point == b.point;
}
inline bool same_vertex(const Vertex3& a, const Vertex3& b) {
  return a.id == b.id && a.point == b.point;
}

/// Index in `element` of the vertex shared with v, or -1.
template <class V, class Element>
int shared_index(const V& v, const Element& element) {
  for (std::size_t i = 0; i < element.size(); ++i)
    if (same_vertex(v, element[i])) return static_cast<int>(i);
  return -1;
}

/// Whether every vertex of `element` is shared with `other`: then `element` lies in the
/// shared simplex, and so does anything it meets.
template <class Element, class Other>
bool fully_shared(const Element& element, const Other& other) {
  for (const auto& v : element)
    if (shared_index(v, other) < 0) return false;
  return true;
}

inline bool finite(const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }
inline bool finite(const Point3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

template <class Element>
bool all_finite(const Element& element) {
  for (const auto& v : element)
    if (!finite(v.point)) return false;
  return true;
}

}  // namespace certimesh::predicates::intersection_detail
