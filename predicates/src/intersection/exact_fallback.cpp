#include "exact_fallback.h"

#include <algorithm>
#include <vector>

#include "hull_intersection.h"
#include "shared_vertices.h"
#include "simplex_pieces.h"

namespace certimesh::predicates::intersection_detail {
namespace {

void add_distinct(std::vector<Point3>& set, const Point3& p) {
  if (!contains_point(set, p)) set.push_back(p);
}

std::vector<Point3> distinct_points(std::span<const Vertex3> e) {
  std::vector<Point3> out;
  for (const Vertex3& v : e) add_distinct(out, v.point);
  return out;
}

bool subset(std::span<const Point3> a, std::span<const Point3> b) {
  return std::all_of(a.begin(), a.end(), [&](const Point3& p) { return contains_point(b, p); });
}

std::vector<Point3> without(std::span<const Point3> set, const Point3& p) {
  std::vector<Point3> out;
  for (const Point3& x : set)
    if (!(x == p)) out.push_back(x);
  return out;
}

// Step 3: non-degenerate simplices f, g with common face c; do they meet outside it?
bool meet_outside_face(std::span<const Point3> f, std::span<const Point3> g,
                       std::span<const Point3> c) {
  if (c.empty()) return hulls_intersect(f, g);
  if (subset(f, c) || subset(g, c)) return false;
  for (const Point3& s : c) {
    const std::vector<Point3> c_rest = without(c, s);
    if (meet_outside_face(without(f, s), g, c_rest) || meet_outside_face(f, without(g, s), c_rest))
      return true;
  }
  return false;
}

}  // namespace

bool exact_overlap(std::span<const Vertex3> a, std::span<const Vertex3> b) {
  std::vector<Point3> sigma;
  for (const Vertex3& v : a)
    if (shared_index(v, b) >= 0) add_distinct(sigma, v.point);
  const std::vector<Point3> pa = distinct_points(a), pb = distinct_points(b);
  if (subset(pa, sigma) || subset(pb, sigma)) return false;
  // Now sigma has at most two points: three would be all of a triangle's points.
  for (const Simplex& f : simplex_pieces(pa, sigma))
    for (const Simplex& g : simplex_pieces(pb, sigma)) {
      std::vector<Point3> c;
      for (const Point3& p : sigma)
        if (contains_point(f, p) && contains_point(g, p)) c.push_back(p);
      if (meet_outside_face(f, g, c)) return true;
    }
  return false;
}

}  // namespace certimesh::predicates::intersection_detail
