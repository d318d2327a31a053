// An axis-aligned line or plane strictly between two point sets: a separation
// certificate that needs no orientation sign at all, since coordinate comparisons are
// exact in both modes. It settles touching-free configurations whose orientation signs
// are exact zeros, which a filter can never certify.
#pragma once

#include <algorithm>
#include <span>
#include <utility>

#include "certimesh/predicates/point.h"

namespace certimesh::predicates::intersection_detail {

template <class P, class Coord>
bool apart_along(std::span<const P> a, std::span<const P> b, Coord coord) {
  const auto lo_hi = [&](std::span<const P> s) {
    double lo = coord(s[0]), hi = lo;
    for (const P& p : s) {
      lo = std::min(lo, coord(p));
      hi = std::max(hi, coord(p));
    }
    return std::pair{lo, hi};
  };
  const auto [alo, ahi] = lo_hi(a);
  const auto [blo, bhi] = lo_hi(b);
  return ahi < blo || bhi < alo;
}

inline bool boxes_apart(std::span<const Point2> a, std::span<const Point2> b) {
  return apart_along(a, b, [](const Point2& p) { return p.x; }) ||
         apart_along(a, b, [](const Point2& p) { return p.y; });
}

inline bool boxes_apart(std::span<const Point3> a, std::span<const Point3> b) {
  return apart_along(a, b, [](const Point3& p) { return p.x; }) ||
         apart_along(a, b, [](const Point3& p) { return p.y; }) ||
         apart_along(a, b, [](const Point3& p) { return p.z; });
}

}  // namespace certimesh::predicates::intersection_detail
