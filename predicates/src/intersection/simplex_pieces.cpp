#include "simplex_pieces.h"

#include <algorithm>
#include <cstddef>

#include "affine_frame.h"
#include "hull_intersection.h"

namespace certimesh::predicates::intersection_detail {
namespace {

// Points strictly inside the segment sigma are redundant: the end points span them.
void drop_inside_sigma(std::vector<Point3>& pts, std::span<const Point3> sigma) {
  if (sigma.size() != 2) return;
  std::erase_if(pts, [&](const Point3& x) {
    return !contains_point(sigma, x) && hulls_intersect(std::span<const Point3>(&x, 1), sigma);
  });
}

std::vector<Simplex> collinear_pieces(std::vector<Point3> pts, int axis) {
  std::sort(pts.begin(), pts.end(),
            [axis](const Point3& a, const Point3& b) { return coord(a, axis) < coord(b, axis); });
  std::vector<Simplex> out;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) out.push_back({pts[i], pts[i + 1]});
  return out;
}

// Four coplanar points, (a, b, c) counterclockwise in frame f, m the fourth.
std::vector<Simplex> planar_pieces(const Frame& f, const Point3& a, const Point3& b,
                                   const Point3& c, const Point3& m,
                                   std::span<const Point3> sigma) {
  const std::array<Point3, 3> t{a, b, c};
  int e[3], negative = 0, zero = 0;
  for (int i = 0; i < 3; ++i) {
    e[i] = frame_orient2(f, t[i], t[(i + 1) % 3], m);
    negative += e[i] < 0;
    zero += e[i] == 0;
  }
  if (negative == 0 && zero == 0) return {{a, b, m}, {b, c, m}, {c, a, m}};  // m inside
  if (negative == 0)  // m inside side i (m is not a vertex: points are distinct)
    for (int i = 0; i < 3; ++i)
      if (e[i] == 0) return {{t[i], m, t[(i + 2) % 3]}, {m, t[(i + 1) % 3], t[(i + 2) % 3]}};
  std::vector<Simplex> out{{a, b, c}};
  for (int i = 0; i < 3; ++i)
    if (e[i] < 0) out.push_back({t[(i + 1) % 3], t[i], m});  // m sees side i
  if (negative != 1 || sigma.size() != 2) return out;
  // Convex quadrilateral with diagonal (u, w): flip it when sigma is the other diagonal.
  for (int i = 0; i < 3; ++i) {
    if (e[i] >= 0) continue;
    const Point3 &u = t[i], &w = t[(i + 1) % 3], &o = t[(i + 2) % 3];
    if (!contains_point(sigma, o) || !contains_point(sigma, m)) break;
    if (frame_orient2(f, m, o, u) * frame_orient2(f, m, o, w) < 0) return {{u, m, o}, {m, w, o}};
  }
  return out;
}

}  // namespace

std::vector<Simplex> simplex_pieces(std::vector<Point3> pts, std::span<const Point3> sigma) {
  drop_inside_sigma(pts, sigma);
  const AffineSpan s = affine_span(pts, space_frame);
  if (s.dim + 1 == static_cast<int>(pts.size())) return {pts};  // already a simplex
  if (s.dim == 1) return collinear_pieces(pts, s.frame.axis[0]);
  // dim 2 with four points (three coplanar points would be a simplex)
  const Point3 &a = pts[s.basis[0]], &b = pts[s.basis[1]], &c = pts[s.basis[2]];
  int mi = 0;
  while (mi == s.basis[0] || mi == s.basis[1] || mi == s.basis[2]) ++mi;
  if (frame_orient2(s.frame, a, b, c) > 0) return planar_pieces(s.frame, a, b, c, pts[mi], sigma);
  return planar_pieces(s.frame, a, c, b, pts[mi], sigma);
}

}  // namespace certimesh::predicates::intersection_detail
