// The two sign sources every intersection rule is written against, once.
//
// A rule only ever asks "is this sign certainly positive / negative?"; a zero answer means
// "nothing certified". With FilteredSigns that zero is the filter's `uncertain` (the
// monograph's d() = 0); with ExactSigns it is a true zero, and `exact` lets a rule whose
// certificates are complete for exact signs answer `intersect` as a fact.
#pragma once

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::predicates::intersection_detail {

struct FilteredSigns {
  static constexpr bool exact = false;
  static int o2(const Point2& a, const Point2& b, const Point2& c) {
    return to_int(orient2d_filtered(a, b, c));
  }
  static int o3(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return to_int(orient3d_filtered(a, b, c, d));
  }
};

struct ExactSigns {
  static constexpr bool exact = true;
  static int o2(const Point2& a, const Point2& b, const Point2& c) {
    return to_int(orient2d(a, b, c));
  }
  static int o3(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return to_int(orient3d(a, b, c, d));
  }
};

/// Coordinate comparisons are exact in both modes: the 1D orientation predicate.
inline int compare(double a, double b) { return a < b ? -1 : (b < a ? 1 : 0); }

}  // namespace certimesh::predicates::intersection_detail
