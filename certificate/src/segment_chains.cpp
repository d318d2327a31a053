// Condition 6d, second half (2D): how the mesh covers each domain segment. The chain of mesh
// edges along a segment is either all boundary facets, oriented the same way (the segment
// bounds the domain, which lies on one side of it), or all interior edges (a segment inside
// the domain: a cut or an interface), and every boundary facet belongs to exactly one chain.
// A segment's two sides lie in one face of the arrangement each, so a chain that switches from
// boundary to interior, or a boundary facet on no chain, is a mesh boundary that leaves the
// domain boundary through rounding slack (issue 12: a sub-ulp gap between two components).
//
// Then the mesh boundary is, as a 1-chain, the sum of the segment chains, and the meshed area
// differs from the area of the domain chain (the segments with the side the mesh takes) by the
// area between each chain and its segment: computed exactly, and bounded by the trapezoids
// between each chain edge and the segment's line (rounded up per segment). Both are reported.
#include <algorithm>
#include <cmath>

#include "certimesh/predicates/orient2d.h"
#include "exact_sum.h"
#include "next_double.h"
#include "rational.h"
#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

struct FacetKey {
  Index lo, hi;
  std::size_t facet;
  friend bool operator<(const FacetKey& a, const FacetKey& b) { return a.lo != b.lo ? a.lo < b.lo : a.hi < b.hi; }
};

// +1 when u -> w is a boundary facet, -1 when w -> u is, 0 for an interior edge; the facet in `f`.
int direction(const std::vector<FacetKey>& keys, const FacetSet& b, Index u, Index w, std::size_t& f) {
  const auto it = std::lower_bound(keys.begin(), keys.end(), FacetKey{std::min(u, w), std::max(u, w), 0});
  if (it == keys.end() || it->lo != std::min(u, w) || it->hi != std::max(u, w)) return 0;
  f = it->facet;
  return b.facet(f)[0] == u ? 1 : -1;
}

// The area between a chain (p_0 = a, ..., p_k = b, oriented as the mesh orients it) and its
// segment, exactly, and a bound on it: per edge pq, the trapezoid between pq and the line of
// the segment, |(q-p).u| (|u x (p-a)| + |u x (q-a)|) / (2|u|^2), u = b - a. All of it in
// integers times powers of two (no rational, no gcd); the chain's bound is then rounded up to
// 64 bits, or, when its parts are normal doubles far from overflow (the common case), bounded
// from above in double with every operation rounded up (bound_in_double). (Summed as rationals, the denominators |u|^2 of 10^4 segments multiplied into one
// number: 40 s on a 10^4-gon star.)
struct Between {
  ExactProductSum twice_area;
  ExactProductSum bound;  // of the per-chain bounds rounded up: never below the exact bound
};

// Adds num / den (num >= 0, den > 0) rounded up to a 64-bit mantissa times a power of two.
void add_quotient_rounded_up(const Dyadic& num, const Dyadic& den, ExactProductSum& sum) {
  if (num.m == 0) return;
  const long bits = static_cast<long>(mpz_sizeinbase(num.m.get_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(den.m.get_mpz_t(), 2));
  const long shift = 64 - bits;  // num 2^shift / den has about 64 bits before the point
  mpz_class n = num.m, d = den.m, q;
  if (shift > 0) n <<= static_cast<mp_bitcnt_t>(shift);
  else d <<= static_cast<mp_bitcnt_t>(-shift);
  mpz_cdiv_q(q.get_mpz_t(), n.get_mpz_t(), d.get_mpz_t());
  sum.add(q, num.e - den.e - shift);
}

// q rounded up to a double (infinite past the doubles).
double rounded_up(const Q& q) {
  const double d = q.get_d();  // truncates toward zero
  if (!std::isfinite(d)) return d;
  return Q(d) < q ? std::nextafter(d, INFINITY) : d;
}

// The chain's bound, sum_i |(p_i+1 - p_i).u| (off_i + off_i+1) / (2 |u|^2), from upper bounds
// of its exact parts in double, every operation rounded up (round to nearest, then one step
// up: the exact result of an operation on positive normal doubles is at most that), |u|^2
// from below. False when a part lies outside [2^-480, 2^480] or the result is not finite: then
// the exact quotient is taken.
bool bound_in_double(const MeshView& m, const std::vector<Index>& chain, const std::vector<ExactProductSum>& off, double& out) {
  auto at = [&](Index v) { return m.xyz + 2 * static_cast<std::size_t>(v); };
  const double *a = at(chain.front()), *b = at(chain.back());
  auto up = [](double x) { return next_up(x); };
  std::vector<double> off_up(chain.size(), 0.0);
  double lo = 0;
  for (std::size_t i = 1; i + 1 < chain.size(); ++i)
    if (!magnitude_bounds(off[i], lo, off_up[i])) return false;
  double sum = 0, dot_up = 0, uu_lo = 0, uu_hi = 0;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    if (off_up[i] == 0 && off_up[i + 1] == 0) continue;
    if (!magnitude_bounds(dot_of_differences(at(chain[i]), at(chain[i + 1]), a, b), lo, dot_up)) return false;
    if (dot_up != 0) sum = up(sum + up(dot_up * up(off_up[i] + off_up[i + 1])));
  }
  if (!magnitude_bounds(dot_of_differences(a, b, a, b), uu_lo, uu_hi) || uu_lo == 0) return false;
  out = up(sum / (2 * uu_lo));
  return std::isfinite(out);
}

void add_between(const MeshView& m, const std::vector<Index>& chain, int dir, Between& out) {
  auto at = [&](Index v) { return m.xyz + 2 * static_cast<std::size_t>(v); };
  const double *a = at(chain.front()), *b = at(chain.back());
  std::vector<ExactProductSum> off(chain.size());  // u x (p_i - a)
  bool all_on_line = true;
  for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
    off[i] = cross_from(a, b, at(chain[i]));
    all_on_line = all_on_line && off[i].sign() == 0;
  }
  if (all_on_line) return;  // a degenerate polygon: area and bound are zero
  // Twice the area of the polygon a, p_1, ..., b closed by the segment: the shoelace sum.
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const double *p = at(chain[i]), *q = at(chain[i + 1]);
    out.twice_area.add(p[0], q[1], dir), out.twice_area.add(p[1], q[0], -dir);
  }
  out.twice_area.add(b[0], a[1], dir), out.twice_area.add(b[1], a[0], -dir);
  if (double bound = 0; bound_in_double(m, chain, off, bound)) {
    out.bound.add(bound, 1.0);
    return;
  }
  Dyadic twice_bound_times_uu;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const Dyadic left = abs(off[i].dyadic()), right = abs(off[i + 1].dyadic());
    if (left.m != 0 || right.m != 0)
      twice_bound_times_uu = twice_bound_times_uu + abs(dot_of_differences(at(chain[i]), at(chain[i + 1]), a, b).dyadic()) * (left + right);
  }
  Dyadic twice_uu = abs(dot_of_differences(a, b, a, b).dyadic());
  twice_uu.e += 1;
  add_quotient_rounded_up(twice_bound_times_uu, twice_uu, out.bound);
}

}  // namespace

Finding check_segment_chains(const MeshView& m, const FacetSet& b, const std::vector<SegmentChain>& chains,
                             Statistics& stats) {
  std::vector<FacetKey> keys;
  keys.reserve(b.size());
  for (std::size_t f = 0; f < b.size(); ++f) keys.push_back({std::min(b.facet(f)[0], b.facet(f)[1]), std::max(b.facet(f)[0], b.facet(f)[1]), f});
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> chain_of(b.size(), UINT32_MAX);
  Between between;
  ExactProductSum twice_domain_area;  // the shoelace sum over the segments the mesh bounds
  for (const SegmentChain& c : chains) {
    const auto& p = c.path;
    int dir = 2;  // not yet known
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
      std::size_t f = SIZE_MAX;
      const int d = direction(keys, b, p[i], p[i + 1], f);
      if (dir != 2 && d != dir)
        return finding(Defect::domain_boundary_not_covered, -1, c.segment, p[i],
                       "domain segment " + std::to_string(c.segment) + " is bounded by the mesh along part of its length only "
                       "(at mesh vertex " + std::to_string(p[i]) + " its mesh edges change from " +
                           (dir == 0 ? "interior to boundary" : "boundary to interior or reverse") + ")");
      dir = d;
      if (d == 0) continue;
      if (chain_of[f] != UINT32_MAX)
        return finding(Defect::facet_off_domain_boundary, b.owner[f], c.segment, p[i],
                       "boundary facet " + std::to_string(f) + " of element " + std::to_string(b.owner[f]) +
                           " runs along two domain segments (" + std::to_string(chain_of[f]) + " and " + std::to_string(c.segment) + ")");
      chain_of[f] = static_cast<std::uint32_t>(c.segment);
    }
    if (dir == 0) continue;
    twice_domain_area.add(m.coord(p.front(), 0), m.coord(p.back(), 1), dir);
    twice_domain_area.add(m.coord(p.front(), 1), m.coord(p.back(), 0), -dir);
    add_between(m, p, dir, between);
  }
  for (std::size_t f = 0; f < b.size(); ++f)
    if (chain_of[f] == UINT32_MAX)
      return finding(Defect::facet_off_domain_boundary, b.owner[f], -1, b.facet(f)[0],
                     "boundary facet " + std::to_string(f) + " of element " + std::to_string(b.owner[f]) +
                         " is on no domain segment's chain of mesh edges: the mesh boundary leaves the domain boundary there");
  const Q domain_area = twice_domain_area.value() / 2;
  stats.domain_measure = domain_area.get_d();
  const Q difference = between.twice_area.value() / 2;
  stats.measure = Q(domain_area + difference).get_d();
  stats.measure_difference = difference.get_d();
  const Q bound = between.bound.value();
  stats.measure_difference_bound = rounded_up(bound);
  if (abs(difference) > bound)
    return finding(Defect::facet_off_domain_boundary, -1, -1, -1,
                   "the meshed area differs from the domain's by " + std::to_string(stats.measure_difference) +
                       ", more than the rounding of its boundary vertices allows (" + std::to_string(stats.measure_difference_bound) + ")");
  return {};
}

}  // namespace certimesh::certificate::detail
