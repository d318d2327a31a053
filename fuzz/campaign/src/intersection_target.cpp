#include "certimesh/fuzz/campaign/intersection_target.h"

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "certimesh/fuzz/campaign/case_seed.h"
#include "certimesh/fuzz/campaign/named_target.h"
#include "certimesh/fuzz/recipes.h"
#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/intersection/tetrahedron_triangle.h"
#include "certimesh/predicates/intersection/triangle_segment_2d.h"
#include "certimesh/predicates/intersection/triangle_segment_3d.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "hull_intersection_oracle.h"
#include "payload_text.h"

namespace certimesh::fuzz::campaign {

namespace {

namespace pr = certimesh::predicates;
using pr::IntersectionMode;
using pr::Overlap;

constexpr std::size_t kPool = 8;

template <std::size_t D>
using Pool = std::array<std::array<double, D>, kPool>;

// Small integers, then exact affine combinations of them: every coordinate exact.
template <std::size_t D>
Pool<D> derived_pool(SplitMixSource& s) {
  Pool<D> p{};
  for (std::size_t i = 0; i < 4; ++i)
    for (auto& v : p[i]) v = static_cast<double>(draw_int(s, -2, 2));
  static constexpr double ts[] = {0.5, 0.25, -1.0, 2.0, 0.75};
  for (std::size_t i = 4; i < kPool; ++i) {
    const auto& a = p[s.below(i)];
    const auto& b = p[s.below(i)];
    const double t = s.below(4) == 0 ? 0.0 : ts[s.below(std::size(ts))];  // t = 0: a copy
    for (std::size_t k = 0; k < D; ++k) p[i][k] = a[k] + t * (b[k] - a[k]);
  }
  return p;
}

template <std::size_t D>
Pool<D> draw_pool(SplitMixSource& s) {
  Pool<D> p{};
  switch (s.below(6)) {
    case 0:
      for (auto& q : p)
        for (auto& v : q) v = draw_unit_interval(s);
      return p;
    case 1:
      for (auto& q : p)
        for (auto& v : q) v = static_cast<double>(draw_int(s, -2, 2));
      return p;
    case 2: return derived_pool<D>(s);
    case 3: {
      p = derived_pool<D>(s);
      for (std::uint64_t m = 1 + s.below(3); m > 0; --m) {
        double& v = p[s.below(kPool)][s.below(D)];
        v = ulp_steps(v, static_cast<int>(draw_nonzero(s, 2)));
      }
      return p;
    }
    case 4:
      p = derived_pool<D>(s);
      if constexpr (D == 3)
        for (auto& q : p) q[2] = q[0] + q[1];  // exact: small dyadic values
      return p;
    default: {
      p = derived_pool<D>(s);
      const int e = s.below(2) ? 600 : -600;
      for (auto& q : p)
        for (auto& v : q) v = std::ldexp(v, e);
      return p;
    }
  }
}

// Vertex ids by coordinates: the first point with the same bits names them all.
template <std::size_t D, std::size_t N>
std::array<std::int64_t, N> ids_of(const std::array<std::array<double, D>, N>& pts) {
  std::array<std::int64_t, N> id{};
  for (std::size_t i = 0; i < N; ++i) {
    id[i] = static_cast<std::int64_t>(i);
    for (std::size_t j = 0; j < i; ++j) {
      bool same = true;
      for (std::size_t k = 0; k < D; ++k)
        same = same && std::bit_cast<std::uint64_t>(pts[i][k]) == std::bit_cast<std::uint64_t>(pts[j][k]);
      if (same) {
        id[i] = id[j];
        break;
      }
    }
  }
  return id;
}

pr::Vertex2 vertex(const std::array<double, 2>& p, std::int64_t id) { return {{p[0], p[1]}, id}; }
pr::Vertex3 vertex(const std::array<double, 3>& p, std::int64_t id) { return {{p[0], p[1], p[2]}, id}; }

// One test: its name, dimension, element sizes and kernel entry.
template <std::size_t D, std::size_t NA, std::size_t NB>
struct Test {
  using V = std::conditional_t<D == 2, pr::Vertex2, pr::Vertex3>;
  using Call = Overlap (*)(const std::array<V, NA>&, const std::array<V, NB>&, IntersectionMode);
  const char* name;
  Call IntersectionKernel::*entry;
};

const char* answer(Overlap o) { return o == Overlap::intersect ? "intersect" : "disjoint"; }

template <std::size_t D, std::size_t NA, std::size_t NB>
std::optional<Finding> check(const IntersectionKernel& kernel, const Test<D, NA, NB>& t,
                             const std::array<std::array<double, D>, NA + NB>& pts) {
  using V = typename Test<D, NA, NB>::V;
  const auto call = kernel.*(t.entry);
  std::string payload = t.name;
  for (const auto& q : pts)
    for (double v : q) {
      payload.push_back(' ');
      payload.append(hex_double(v));
    }
  const auto found = [&](const std::string& what) { return Finding{std::string(t.name) + ": " + what, payload}; };
  const auto id = ids_of<D, NA + NB>(pts);
  std::array<V, NA> a{};
  std::array<V, NB> b{};
  std::array<std::array<double, D>, NA> pa{};
  std::array<std::array<double, D>, NB> pb{};
  for (std::size_t i = 0; i < NA; ++i) a[i] = vertex(pa[i] = pts[i], id[i]);
  for (std::size_t j = 0; j < NB; ++j) b[j] = vertex(pb[j] = pts[NA + j], id[NA + j]);

  if (!all_finite(pts)) {
    if (call(a, b, IntersectionMode::conservative) != Overlap::intersect)
      return found("conservative mode says disjoint for non-finite input");
    try {
      (void)call(a, b, IntersectionMode::exact);
    } catch (const pr::NonFiniteInput&) {
      return std::nullopt;
    }
    return found("exact mode accepted non-finite input");
  }
  const std::optional<bool> o = certimesh::testing::hulls_intersect_beyond_shared<D, NA, NB>(pa, pb);
  if (!o) return std::nullopt;  // both degenerate with a shared vertex: no oracle
  const Overlap want = *o ? Overlap::intersect : Overlap::disjoint;
  const Overlap exact = call(a, b, IntersectionMode::exact);
  if (exact != want) return found(std::string("exact mode says ") + answer(exact) + ", the exact oracle " + answer(want));
  if (want == Overlap::intersect && call(a, b, IntersectionMode::conservative) == Overlap::disjoint)
    return found("conservative mode says disjoint for an intersecting pair");
  auto reversed = a;
  for (std::size_t i = 0; i < NA / 2; ++i) std::swap(reversed[i], reversed[NA - 1 - i]);
  const Overlap r = call(reversed, b, IntersectionMode::exact);
  if (r != want) return found(std::string("exact mode says ") + answer(r) + " with the first element's vertices reversed, the exact oracle " + answer(want));
  return std::nullopt;
}

const Test<2, 2, 2> kSegSeg2{"seg_seg2d", &IntersectionKernel::segment_segment_2d};
const Test<2, 3, 2> kTriSeg2{"tri_seg2d", &IntersectionKernel::triangle_segment_2d};
const Test<3, 3, 2> kTriSeg3{"tri_seg3d", &IntersectionKernel::triangle_segment_3d};
const Test<3, 4, 3> kTetTri{"tet_tri", &IntersectionKernel::tetrahedron_triangle};
const Test<3, 3, 3> kTriTri3{"tri_tri3d", &IntersectionKernel::triangle_triangle_3d};

template <std::size_t D, std::size_t NA, std::size_t NB>
std::optional<Finding> run_test(const IntersectionKernel& k, const Test<D, NA, NB>& t, SplitMixSource& s) {
  const Pool<D> pool = draw_pool<D>(s);
  std::array<std::array<double, D>, NA + NB> pts{};
  for (auto& q : pts) q = pool[s.below(kPool)];
  if (s.below(32) == 0) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double special[] = {std::numeric_limits<double>::quiet_NaN(), inf, -inf};
    pts[s.below(NA + NB)][s.below(D)] = special[s.below(3)];
  }
  return check(k, t, pts);
}

template <std::size_t D, std::size_t NA, std::size_t NB>
std::optional<Finding> replay_test(const IntersectionKernel& k, const Test<D, NA, NB>& t, PayloadReader& in) {
  std::array<std::array<double, D>, NA + NB> pts{};
  for (auto& q : pts)
    for (auto& v : q) v = in.next_double();
  in.expect_end();
  return check(k, t, pts);
}

class IntersectionTarget final : public KernelTarget<IntersectionKernel> {
 public:
  using KernelTarget::KernelTarget;
  std::optional<Finding> run_case(std::uint64_t seed) const override {
    SplitMixSource s(seed);
    switch (s.below(5)) {
      case 0: return run_test(kernel_, kSegSeg2, s);
      case 1: return run_test(kernel_, kTriSeg2, s);
      case 2: return run_test(kernel_, kTriSeg3, s);
      case 3: return run_test(kernel_, kTetTri, s);
      default: return run_test(kernel_, kTriTri3, s);
    }
  }
  std::optional<Finding> replay(std::string_view payload) const override {
    PayloadReader in(payload);
    const std::string test = in.next_word();
    if (test == kSegSeg2.name) return replay_test(kernel_, kSegSeg2, in);
    if (test == kTriSeg2.name) return replay_test(kernel_, kTriSeg2, in);
    if (test == kTriSeg3.name) return replay_test(kernel_, kTriSeg3, in);
    if (test == kTetTri.name) return replay_test(kernel_, kTetTri, in);
    if (test == kTriTri3.name) return replay_test(kernel_, kTriTri3, in);
    throw MalformedPayload("unknown intersection test '" + test + "' (seg_seg2d, tri_seg2d, tri_seg3d, tet_tri, tri_tri3d)");
  }

};

}  // namespace

IntersectionKernel certimesh_intersection_kernel() {
  return {pr::segment_segment_2d, pr::triangle_segment_2d, pr::triangle_segment_3d, pr::tetrahedron_triangle,
          pr::triangle_triangle_3d};
}

std::unique_ptr<Target> make_intersection_target(const IntersectionKernel& kernel, std::string name,
                                                 std::string description) {
  return std::make_unique<IntersectionTarget>(kernel, std::move(name), std::move(description));
}

std::unique_ptr<Target> make_intersection_target() {
  return make_intersection_target(
      certimesh_intersection_kernel(), "intersection",
      "seg_seg2d/tri_seg2d/tri_seg3d/tet_tri/tri_tri3d: exact mode against an exact rational LP oracle, "
      "conservative mode never disjoint for an intersecting pair");
}

}  // namespace certimesh::fuzz::campaign
