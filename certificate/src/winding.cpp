// Condition 5 and the exact measurements behind it: the sign of the area / volume a boundary
// component encloses, and winding numbers of components around points off them.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "stages.h"
#include "sweep_2d.h"

namespace certimesh::certificate::detail {
namespace {

using predicates::Sign;

// det[a-r, b-r] (2D) or det[a-r, b-r, c-r] (3D) in T (double or exact rationals); with
// `absolute`, the permanent instead (every product counted positive), which bounds the
// rounding error of the double determinant (Shewchuk).
template <class T>
T facet_det(const MeshView& m, const Index* f, Index r, bool absolute) {
  using std::abs;
  T d[3][3];
  for (int i = 0; i < m.dim; ++i)
    for (int k = 0; k < m.dim; ++k) {
      d[i][k] = T(m.coord(f[i], k)) - T(m.coord(r, k));
      if (absolute) d[i][k] = abs(d[i][k]);
    }
  const T s = absolute ? T(1) : T(-1);
  if (m.dim == 2) return d[0][0] * d[1][1] + s * d[0][1] * d[1][0];
  return d[0][0] * (d[1][1] * d[2][2] + s * d[1][2] * d[2][1]) + s * d[0][1] * (d[1][0] * d[2][2] + s * d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] + s * d[1][1] * d[2][0]);
}

int winding_2d(const MeshView& m, const FacetSet& b, const std::vector<std::size_t>& c, const double* p) {
  const predicates::Point2 q{p[0], p[1]};
  int w = 0;  // half-open crossing rule (upward edges count +1, downward -1), exact
  for (std::size_t f : c) {
    const predicates::Point2 a = m.p2(b.facet(f)[0]), e = m.p2(b.facet(f)[1]);
    if (a.y <= q.y) {
      if (e.y > q.y && predicates::orient2d(a, e, q) == Sign::positive) ++w;
    } else if (e.y <= q.y && predicates::orient2d(a, e, q) == Sign::negative) {
      --w;
    }
  }
  return w;
}

// Signed crossings of the segment p -> far with the component's triangles. orient3d_sos
// never answers zero for distinct points, so every crossing is generic; p is off the
// component, so the infinitesimal perturbation cannot change the winding number.
int winding_3d(const MeshView& m, const FacetSet& b, const std::vector<std::size_t>& c, const double* p) {
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t f : c)
    for (int i = 0; i < 3; ++i) top = std::max(top, m.coord(b.facet(f)[i], 0));
  const predicates::Point3 q{p[0], p[1], p[2]};
  const predicates::Point3 far{std::nextafter(std::max(top, q.x), std::numeric_limits<double>::infinity()), q.y, q.z};
  int w = 0;
  for (std::size_t f : c) {
    const predicates::Point3 t0 = m.p3(b.facet(f)[0]), t1 = m.p3(b.facet(f)[1]), t2 = m.p3(b.facet(f)[2]);
    const Sign sq = predicates::orient3d_sos(t0, t1, t2, q);
    if (sq == predicates::orient3d_sos(t0, t1, t2, far)) continue;
    const Sign s0 = predicates::orient3d_sos(q, far, t0, t1);
    if (s0 != predicates::orient3d_sos(q, far, t1, t2) || s0 != predicates::orient3d_sos(q, far, t2, t0)) continue;
    w += sq == Sign::positive ? 1 : -1;  // q on the inner side: leaving through the facet
  }
  return w;
}

}  // namespace

int enclosed_measure_sign(const MeshView& m, const FacetSet& set, const std::vector<std::size_t>& facets) {
  const Index r = set.facet(facets[0])[0];
  double sum = 0, permanents = 0, magnitudes = 0, largest = 0;
  for (std::size_t f : facets) {
    const double term = facet_det<double>(m, set.facet(f), r, false), permanent = facet_det<double>(m, set.facet(f), r, true);
    sum += term, permanents += permanent, magnitudes += std::abs(term);
    for (int i = 0; i < m.dim; ++i)
      for (int k = 0; k < m.dim; ++k) largest = std::max(largest, std::abs(m.coord(set.facet(f)[i], k) - m.coord(r, k)));
  }
  // Without underflow, Shewchuk's bound for one determinant is below 4u (2D) / 8u (3D) times
  // its permanent, and the sum of n terms adds at most 2nu * sum |term|. Underflow adds to each
  // product an absolute error of at most eta = 2^-1075 (half the smallest subnormal); in 3D a
  // 2x2 minor carries two such errors and is then multiplied by a difference of size at most
  // `largest`, so one determinant gains at most 3 eta (2 largest + 1) (1 + 4u) and the sum
  // n times that: 6 n denorm_min (largest + 1) bounds it (2D: fewer terms). The factor 2 covers
  // the rounding of the bound itself (and of the permanents); proofs/mesh_certificate.md
  // section 6 states it. A bound that overflows falls through to the exact sum.
  const double u = DBL_EPSILON / 2, n = static_cast<double>(facets.size());
  const double underflow = 16 * n * (largest + 1) * std::numeric_limits<double>::denorm_min();
  const double bound = 2 * ((m.dim == 2 ? 4 : 8) * u * permanents + 2 * n * u * magnitudes + underflow);
  if (std::isfinite(bound) && std::abs(sum) > bound) return sum > 0 ? 1 : -1;
  mpq_class exact = 0;
  for (std::size_t f : facets) exact += facet_det<mpq_class>(m, set.facet(f), r, false);
  return sgn(exact);
}

int winding_number(const MeshView& m, const FacetSet& b, const std::vector<std::size_t>& c, const double* p) {
  return m.dim == 2 ? winding_2d(m, b, c, p) : winding_3d(m, b, c, p);
}

namespace {

Finding cover_defect(const FacetSet& b, const Components& comps, std::size_t c, int others) {
  const int inside = others + comps.measure_sign[c];
  if (others >= 0 && others <= 1 && inside >= 0 && inside <= 1) return {};
  const Index v = comps.vertex[c];
  return finding(Defect::multiple_cover, b.owner[comps.facets[c][0]], -1, v,
                 "next to the boundary component through vertex " + std::to_string(v) +
                     " the elements cover the plane/space " + std::to_string(std::max(others, inside)) +
                     " times (winding numbers " + std::to_string(others) + " and " + std::to_string(inside) + ")");
}

// 2D: one sweep answers W just left of every component's lowest-leftmost vertex v, where the
// component itself contributes nothing (it lies above and to the right); with the local
// correction at a pinch (winding_offset: the edges of other components between that point and
// the component's last edge at v) that is W_others next to the component. For an island the
// point just left of v is in the unmeshed face around it (the offset is 0), and the first facet
// left of it bounds that face. An island's ray can only hit a component whose lowest-leftmost
// vertex comes earlier in that order, so resolving `around` in that order needs no recursion
// (`around` of a cavity is not used).
Finding single_cover_2d(const MeshView& m, const FacetSet& b, Components& comps,
                        const std::vector<std::array<double, 2>>& hole_points, const std::vector<Index>* lex_order) {
  const std::size_t n = comps.facets.size();
  std::vector<std::array<double, 2>> at(n);
  for (std::size_t c = 0; c < n; ++c) at[c] = {m.coord(comps.vertex[c], 0), m.coord(comps.vertex[c], 1)};
  at.insert(at.end(), hole_points.begin(), hole_points.end());
  std::vector<SweepAnswer> answers;
  Finding f = sweep_2d(m, b, Defect::t_junction, Defect::boundary_intersection, "boundary edge", at, answers, lex_order);
  if (f.defect != Defect::none) return f;
  comps.hole_answers.assign(answers.begin() + static_cast<std::ptrdiff_t>(n), answers.end());
  at.resize(n);
  std::vector<std::size_t> order(n);
  for (std::size_t c = 0; c < n; ++c) order[c] = c;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return at[x][1] != at[y][1] ? at[x][1] < at[y][1] : at[x][0] < at[y][0]; });
  comps.around.assign(n, -1);
  for (std::size_t c : order) {
    if (f = cover_defect(b, comps, c, answers[c].winding + comps.winding_offset[c]); f.defect != Defect::none) return f;
    if (answers[c].left_facet < 0) continue;
    const std::size_t hit = comps.of_facet[static_cast<std::size_t>(answers[c].left_facet)];
    comps.around[c] = comps.measure_sign[hit] < 0 ? static_cast<std::int64_t>(hit) : comps.around[hit];
  }
  return {};
}

}  // namespace

// With every element positive and every interior facet paired, the number of elements over a
// generic point is the winding number W of the boundary around it, so W >= 0. Next to a
// component C, W is W_others(v) on one side and W_others(v) + sign(C) on the other (v a vertex
// of C), and both sides must be 0 or 1. 2D: a plane sweep, O(B log B) whatever the nesting;
// 3D: per component, the components whose box holds its vertex (O(k B) in the worst case).
Finding check_single_cover(const MeshView& m, const FacetSet& b, Components& comps,
                           const std::vector<std::array<double, 2>>& hole_points, const std::vector<Index>* lex_order) {
  if (m.dim == 2) return single_cover_2d(m, b, comps, hole_points, lex_order);
  const std::size_t n = comps.facets.size();
  comps.enclosed_by.assign(n, {});
  for (std::size_t c = 0; c < n; ++c) {
    const Index v = comps.vertex[c];
    int others = 0;
    for (std::size_t o = 0; o < n; ++o) {
      if (o == c || !boxes_overlap(comps.box[o], facet_box(m, &v, 1), m.dim)) continue;
      const int w = winding_number(m, b, comps.facets[o], m.xyz + static_cast<std::size_t>(v) * m.dim);
      if (w != 0) comps.enclosed_by[c].push_back(o);
      others += w;
    }
    if (Finding f = cover_defect(b, comps, c, others); f.defect != Defect::none) return f;
  }
  return {};
}

}  // namespace certimesh::certificate::detail
