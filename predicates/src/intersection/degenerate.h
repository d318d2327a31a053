// Exact degeneracy of an element: the rules (the *_rules.h headers) are complete for
// non-degenerate elements; a degenerate one goes to the exact fallback (exact_fallback.h).
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "certimesh/predicates/intersection/vertex.h"
#include "certimesh/predicates/non_finite_input.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "projection.h"
#include "shared_vertices.h"

namespace certimesh::predicates::intersection_detail {

inline bool degenerate(const std::array<Vertex2, 2>& s) { return s[0].point == s[1].point; }
inline bool degenerate(const std::array<Vertex3, 2>& s) { return s[0].point == s[1].point; }
inline bool degenerate(const std::array<Vertex2, 3>& t) {
  return orient2d(t[0].point, t[1].point, t[2].point) == Sign::zero;
}
/// Collinear in space: collinear in all three coordinate-plane projections.
inline bool degenerate(const std::array<Vertex3, 3>& t) {
  for (int k = 0; k < 3; ++k) {
    const int ax = projection_axis(k);
    if (orient2d(project(t[0].point, ax), project(t[1].point, ax), project(t[2].point, ax)) !=
        Sign::zero)
      return false;
  }
  return true;
}
inline bool degenerate(const std::array<Vertex3, 4>& t) {
  return orient3d(t[0].point, t[1].point, t[2].point, t[3].point) == Sign::zero;
}

/// The plane as the z = 0 plane of space, for the fallback.
template <std::size_t N>
std::vector<Vertex3> lift(const std::array<Vertex2, N>& e) {
  std::vector<Vertex3> out;
  for (const Vertex2& v : e) out.push_back({{v.point.x, v.point.y, 0.0}, v.id});
  return out;
}
template <std::size_t N>
std::vector<Vertex3> lift(const std::array<Vertex3, N>& e) {
  return {e.begin(), e.end()};
}

/// Exact mode refuses NaN and infinity, as the exact predicates do.
template <class A, class B>
void require_finite(const A& a, const B& b, const char* test) {
  if (!all_finite(a) || !all_finite(b)) throw NonFiniteInput(test);
}

}  // namespace certimesh::predicates::intersection_detail
