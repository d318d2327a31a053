#include "certimesh/fuzz/campaign/predicates_target.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string_view>

#include "certimesh/fuzz/campaign/case_seed.h"
#include "certimesh/fuzz/campaign/named_target.h"
#include "certimesh/fuzz/recipes.h"
#include "certimesh/predicates/detail/exact_stages.h"
#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/non_finite_input.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "payload_text.h"
#include "rational_oracle.h"
#include "scaled_integer_oracle.h"

namespace certimesh::fuzz::campaign {

namespace {

namespace pr = certimesh::predicates;
using P2 = pr::Point2;
using P3 = pr::Point3;

P2 pt(const std::array<double, 2>& p) { return {p[0], p[1]}; }
P3 pt(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }

// One predicate's kernel entry points on the array form.
template <std::size_t N, std::size_t Dim>
struct Calls {
  using A = std::array<std::array<double, Dim>, N>;
  const char* name;
  bool lifted;
  pr::FilteredSign (*filtered)(const PredicateKernel&, const A&);
  pr::FilteredSign (*filtered_copy)(const PredicateKernel&, const A&);
  pr::Sign (*exact)(const PredicateKernel&, const A&);
  pr::Sign (*stage)(const PredicateKernel&, const A&);
  pr::Sign (*sos)(const PredicateKernel&, const A&);
};

#define CERTIMESH_CALL3(F) [](const PredicateKernel& k, const A& p) { return k.F(pt(p[0]), pt(p[1]), pt(p[2])); }
#define CERTIMESH_CALL4(F) [](const PredicateKernel& k, const A& p) { return k.F(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
#define CERTIMESH_CALL5(F) [](const PredicateKernel& k, const A& p) { return k.F(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])); }

using A2 = std::array<std::array<double, 2>, 3>;
using A3 = std::array<std::array<double, 3>, 4>;
using AC = std::array<std::array<double, 2>, 4>;
using AS = std::array<std::array<double, 3>, 5>;

const Calls<3, 2>& orient2d_calls() {
  using A = A2;
  static const Calls<3, 2> c{"orient2d", false, CERTIMESH_CALL3(orient2d_filtered), CERTIMESH_CALL3(orient2d_filtered_copy),
                             CERTIMESH_CALL3(orient2d), CERTIMESH_CALL3(orient2d_exact_stage), CERTIMESH_CALL3(orient2d_sos)};
  return c;
}
const Calls<4, 3>& orient3d_calls() {
  using A = A3;
  static const Calls<4, 3> c{"orient3d", false, CERTIMESH_CALL4(orient3d_filtered), CERTIMESH_CALL4(orient3d_filtered_copy),
                             CERTIMESH_CALL4(orient3d), CERTIMESH_CALL4(orient3d_exact_stage), CERTIMESH_CALL4(orient3d_sos)};
  return c;
}
const Calls<4, 2>& incircle_calls() {
  using A = AC;
  static const Calls<4, 2> c{"incircle", true, CERTIMESH_CALL4(incircle_filtered), CERTIMESH_CALL4(incircle_filtered_copy),
                             CERTIMESH_CALL4(incircle), CERTIMESH_CALL4(incircle_exact_stage), CERTIMESH_CALL4(incircle_sos)};
  return c;
}
const Calls<5, 3>& insphere_calls() {
  using A = AS;
  static const Calls<5, 3> c{"insphere", true, CERTIMESH_CALL5(insphere_filtered), CERTIMESH_CALL5(insphere_filtered_copy),
                             CERTIMESH_CALL5(insphere), CERTIMESH_CALL5(insphere_exact_stage), CERTIMESH_CALL5(insphere_sos)};
  return c;
}
#undef CERTIMESH_CALL3
#undef CERTIMESH_CALL4
#undef CERTIMESH_CALL5

template <std::size_t N, std::size_t Dim>
std::string payload_of(const char* name, const std::array<std::array<double, Dim>, N>& p) {
  std::string s = name;
  for (const auto& q : p)
    for (double v : q) {
      s.push_back(' ');
      s.append(hex_double(v));
    }
  return s;
}

template <class F>
bool throws_non_finite(F&& f) {
  try {
    (void)f();
  } catch (const pr::NonFiniteInput&) {
    return true;
  }
  return false;
}

// The first violated property, or nullopt. `o` is the exact sign of p.
template <std::size_t N, std::size_t Dim>
std::optional<std::string> violation(const PredicateKernel& k, const Calls<N, Dim>& c,
                                     const std::array<std::array<double, Dim>, N>& p, int o) {
  const int f = pr::to_int(c.filtered(k, p));
  if (f != 0 && f != o) return "the filter contradicts the exact sign";
  const int fc = pr::to_int(c.filtered_copy(k, p));
  if (fc != 0 && fc != o) return "the kernel-compiled filter contradicts the exact sign";
  if (pr::to_int(c.exact(k, p)) != o) return "the exact predicate differs from the exact sign";
  if (pr::to_int(c.stage(k, p)) != o) return "the exact stage differs from the exact sign";
  const int s = pr::to_int(c.sos(k, p));
  if (o != 0 && s != o) return "SoS differs from the non-zero exact sign";
  const bool apart = distinct(p);
  if (s == 0 && apart) return "SoS is zero for distinct points";
  // Permutation consistency: det of the swapped rows is -det, and SoS is a sign of a
  // (perturbed) determinant, so it must flip as well. One transposition per case (all of
  // them would cost N(N-1)/2 more exact and SoS calls: 10 for insphere, whose exact stage
  // is most of a campaign's time), picked from the coordinates' bits so that replaying the
  // payload picks the same one.
  std::uint64_t h = 0;
  for (const auto& q : p)
    for (double v : q) h = h * 0x100000001b3ull + std::bit_cast<std::uint64_t>(v);
  std::size_t pair = static_cast<std::size_t>((h ^ (h >> 29)) % (N * (N - 1) / 2));
  std::size_t i = 0, j = 1;
  while (pair > 0) {
    --pair;
    if (++j == N) j = ++i + 1;
  }
  auto q = p;
  std::swap(q[i], q[j]);
  const std::string swapped = "after swapping points " + std::to_string(i) + " and " + std::to_string(j);
  const int fq = pr::to_int(c.filtered(k, q));
  if (fq != 0 && fq != -o) return "the filter contradicts the exact sign " + swapped;
  if (pr::to_int(c.exact(k, q)) != -o) return "the exact sign is not negated " + swapped;
  if (apart && pr::to_int(c.sos(k, q)) != -s) return "SoS is not negated " + swapped;
  return std::nullopt;
}

template <std::size_t N, std::size_t Dim>
std::optional<Finding> check(const PredicateKernel& k, const Calls<N, Dim>& c,
                             const std::array<std::array<double, Dim>, N>& p) {
  const auto found = [&](const std::string& what) {
    return Finding{std::string(c.name) + ": " + what, payload_of(c.name, p)};
  };
  if (!all_finite(p)) {
    if (c.filtered(k, p) != pr::FilteredSign::uncertain) return found("the filter certified a sign for non-finite input");
    if (c.filtered_copy(k, p) != pr::FilteredSign::uncertain) return found("the kernel-compiled filter certified a sign for non-finite input");
    if (!throws_non_finite([&] { return c.exact(k, p); })) return found("the exact predicate accepted non-finite input");
    if (!throws_non_finite([&] { return c.sos(k, p); })) return found("SoS accepted non-finite input");
    return std::nullopt;
  }
  const int fast = certimesh::testing::scaled_integer_sign<Dim, N>(p, c.lifted);
  auto v = violation(k, c, p, fast);
  if (!v) return std::nullopt;
  // A disagreement: the rational oracle decides, and an oracle that erred is a finding too.
  const int rational = certimesh::testing::oracle_sign<Dim, N>(p, c.lifted);
  if (rational != fast)
    return found("the scaled-integer oracle (" + std::to_string(fast) + ") and the rational oracle (" +
                 std::to_string(rational) + ") disagree");
  return found(*v);
}

std::optional<Finding> run_predicate_case(const PredicateKernel& k, std::uint64_t seed) {
  SplitMixSource src(seed);
  const auto predicate = src.below(4);
  A2 o2{};
  A3 o3{};
  AC ic{};
  AS is{};
  switch (predicate) {
    case 0: o2 = any_orient2d(src).p; break;
    case 1: o3 = any_orient3d(src).p; break;
    case 2: ic = any_incircle(src).p; break;
    default: is = any_insphere(src).p; break;
  }
  // 1 case in 32: one coordinate NaN, +-Inf or a raw bit pattern (as decode() does).
  if (src.below(32) == 0) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double special[] = {std::numeric_limits<double>::quiet_NaN(), inf, -inf,
                              draw_double(src, DoubleClass::anything)};
    const double v = special[src.below(4)];
    const std::size_t i = src.below(5), axis = src.below(3);
    switch (predicate) {
      case 0: o2[i % 3][axis % 2] = v; break;
      case 1: o3[i % 4][axis] = v; break;
      case 2: ic[i % 4][axis % 2] = v; break;
      default: is[i][axis] = v; break;
    }
  }
  switch (predicate) {
    case 0: return check(k, orient2d_calls(), o2);
    case 1: return check(k, orient3d_calls(), o3);
    case 2: return check(k, incircle_calls(), ic);
    default: return check(k, insphere_calls(), is);
  }
}

template <std::size_t N, std::size_t Dim>
std::optional<Finding> replay_points(const PredicateKernel& k, const Calls<N, Dim>& c, PayloadReader& in) {
  std::array<std::array<double, Dim>, N> p{};
  for (auto& q : p)
    for (auto& v : q) v = in.next_double();
  in.expect_end();
  return check(k, c, p);
}

class PredicatesTarget final : public KernelTarget<PredicateKernel> {
 public:
  using KernelTarget::KernelTarget;
  std::optional<Finding> run_case(std::uint64_t seed) const override { return run_predicate_case(kernel_, seed); }
  std::optional<Finding> replay(std::string_view payload) const override {
    PayloadReader in(payload);
    const std::string predicate = in.next_word();
    if (predicate == "orient2d") return replay_points(kernel_, orient2d_calls(), in);
    if (predicate == "orient3d") return replay_points(kernel_, orient3d_calls(), in);
    if (predicate == "incircle") return replay_points(kernel_, incircle_calls(), in);
    if (predicate == "insphere") return replay_points(kernel_, insphere_calls(), in);
    throw MalformedPayload("unknown predicate '" + predicate + "' (orient2d, orient3d, incircle, insphere)");
  }

};

}  // namespace

PredicateKernel certimesh_predicate_kernel() {
  PredicateKernel k{};
  k.orient2d_filtered = [](const P2& a, const P2& b, const P2& c) { return pr::orient2d_filtered(a, b, c); };
  k.orient2d_filtered_copy = [](const P2& a, const P2& b, const P2& c) { return pr::detail::orient2d_filter_out_of_line(a, b, c); };
  k.orient2d = [](const P2& a, const P2& b, const P2& c) { return pr::orient2d(a, b, c); };
  k.orient2d_exact_stage = [](const P2& a, const P2& b, const P2& c) { return pr::detail::orient2d_exact_stage(a, b, c); };
  k.orient2d_sos = [](const P2& a, const P2& b, const P2& c) { return pr::orient2d_sos(a, b, c); };
  k.orient3d_filtered = [](const P3& a, const P3& b, const P3& c, const P3& d) { return pr::orient3d_filtered(a, b, c, d); };
  k.orient3d_filtered_copy = [](const P3& a, const P3& b, const P3& c, const P3& d) { return pr::detail::orient3d_filter_out_of_line(a, b, c, d); };
  k.orient3d = [](const P3& a, const P3& b, const P3& c, const P3& d) { return pr::orient3d(a, b, c, d); };
  k.orient3d_exact_stage = [](const P3& a, const P3& b, const P3& c, const P3& d) { return pr::detail::orient3d_exact_stage(a, b, c, d); };
  k.orient3d_sos = [](const P3& a, const P3& b, const P3& c, const P3& d) { return pr::orient3d_sos(a, b, c, d); };
  k.incircle_filtered = [](const P2& a, const P2& b, const P2& c, const P2& d) { return pr::incircle_filtered(a, b, c, d); };
  k.incircle_filtered_copy = [](const P2& a, const P2& b, const P2& c, const P2& d) { return pr::detail::incircle_filter_out_of_line(a, b, c, d); };
  k.incircle = [](const P2& a, const P2& b, const P2& c, const P2& d) { return pr::incircle(a, b, c, d); };
  k.incircle_exact_stage = [](const P2& a, const P2& b, const P2& c, const P2& d) { return pr::detail::incircle_exact_stage(a, b, c, d); };
  k.incircle_sos = [](const P2& a, const P2& b, const P2& c, const P2& d) { return pr::incircle_sos(a, b, c, d); };
  k.insphere_filtered = [](const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) { return pr::insphere_filtered(a, b, c, d, e); };
  k.insphere_filtered_copy = [](const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) { return pr::detail::insphere_filter_out_of_line(a, b, c, d, e); };
  k.insphere = [](const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) { return pr::insphere(a, b, c, d, e); };
  k.insphere_exact_stage = [](const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) { return pr::detail::insphere_exact_stage(a, b, c, d, e); };
  k.insphere_sos = [](const P3& a, const P3& b, const P3& c, const P3& d, const P3& e) { return pr::insphere_sos(a, b, c, d, e); };
  return k;
}

std::unique_ptr<Target> make_predicates_target(const PredicateKernel& kernel, std::string name, std::string description) {
  return std::make_unique<PredicatesTarget>(kernel, std::move(name), std::move(description));
}

std::unique_ptr<Target> make_predicates_target() {
  return make_predicates_target(
      certimesh_predicate_kernel(), "predicates",
      "orient2d/orient3d/incircle/insphere: filter, exact and SoS against exact integer and rational oracles, "
      "swaps negate signs, non-finite input refused");
}

}  // namespace certimesh::fuzz::campaign
