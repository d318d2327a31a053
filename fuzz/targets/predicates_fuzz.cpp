// Differential libFuzzer target for the predicate kernel.
//
// The input bytes decode (fuzz/generators recipes.h, decode()) into one predicate and its
// points -- exactly degenerate, near-degenerate or generic configurations at every scale,
// and 1 in 32 with a raw bit-pattern coordinate (NaN, Inf, anything). For every input:
//   - finite input: the filter never contradicts the rational oracle (fuzz/oracles), the
//     exact predicate and the bare exact stage equal the oracle, and the SoS variant equals
//     the oracle when that is non-zero and is non-zero for pairwise distinct points;
//   - non-finite input: X and X_sos throw NonFiniteInput, X_filtered is uncertain.
// Any violation prints the points as hex floats and aborts (a libFuzzer crash artifact).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "certimesh/fuzz/recipes.h"
#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/non_finite_input.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "rational_oracle.h"

namespace {

namespace pr = certimesh::predicates;
namespace fz = certimesh::fuzz;

pr::Point2 pt(const std::array<double, 2>& p) { return {p[0], p[1]}; }
pr::Point3 pt(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }

template <std::size_t N, std::size_t Dim>
[[noreturn]] void fail(const char* predicate, const char* what,
                       const std::array<std::array<double, Dim>, N>& p) {
  std::fprintf(stderr, "\n*** %s: %s\n", predicate, what);
  for (const auto& q : p) {
    std::fprintf(stderr, "  (");
    for (std::size_t k = 0; k < Dim; ++k) std::fprintf(stderr, "%s%a", k ? ", " : "", q[k]);
    std::fprintf(stderr, ")\n");
  }
  std::abort();
}

// exact(), exact_stage(), filtered(), sos() on the array form, per predicate.
struct O2 {
  static constexpr const char* name = "orient2d";
  static constexpr bool lifted = false;
  using A = std::array<std::array<double, 2>, 3>;
  static pr::Sign exact(const A& p) { return pr::orient2d(pt(p[0]), pt(p[1]), pt(p[2])); }
  static pr::Sign stage(const A& p) { return pr::detail::orient2d_exact_stage(pt(p[0]), pt(p[1]), pt(p[2])); }
  static pr::FilteredSign filtered(const A& p) { return pr::orient2d_filtered(pt(p[0]), pt(p[1]), pt(p[2])); }
  static pr::Sign sos(const A& p) { return pr::orient2d_sos(pt(p[0]), pt(p[1]), pt(p[2])); }
};
struct O3 {
  static constexpr const char* name = "orient3d";
  static constexpr bool lifted = false;
  using A = std::array<std::array<double, 3>, 4>;
  static pr::Sign exact(const A& p) { return pr::orient3d(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
  static pr::Sign stage(const A& p) { return pr::detail::orient3d_exact_stage(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
  static pr::FilteredSign filtered(const A& p) { return pr::orient3d_filtered(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
  static pr::Sign sos(const A& p) { return pr::orient3d_sos(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
};
struct IC {
  static constexpr const char* name = "incircle";
  static constexpr bool lifted = true;
  using A = std::array<std::array<double, 2>, 4>;
  static pr::Sign exact(const A& p) { return pr::incircle(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
  static pr::Sign stage(const A& p) { return pr::detail::incircle_exact_stage(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
  static pr::FilteredSign filtered(const A& p) { return pr::incircle_filtered(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
  static pr::Sign sos(const A& p) { return pr::incircle_sos(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])); }
};
struct IS {
  static constexpr const char* name = "insphere";
  static constexpr bool lifted = true;
  using A = std::array<std::array<double, 3>, 5>;
  static pr::Sign exact(const A& p) { return pr::insphere(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])); }
  static pr::Sign stage(const A& p) { return pr::detail::insphere_exact_stage(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])); }
  static pr::FilteredSign filtered(const A& p) { return pr::insphere_filtered(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])); }
  static pr::Sign sos(const A& p) { return pr::insphere_sos(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])); }
};

template <class T, std::size_t N, std::size_t Dim>
void check(const std::array<std::array<double, Dim>, N>& p) {
  if (!fz::all_finite(p)) {
    if (T::filtered(p) != pr::FilteredSign::uncertain) fail(T::name, "filter certified a sign for non-finite input", p);
    bool threw = false;
    try { (void)T::exact(p); } catch (const pr::NonFiniteInput&) { threw = true; }
    if (!threw) fail(T::name, "exact predicate accepted non-finite input", p);
    threw = false;
    try { (void)T::sos(p); } catch (const pr::NonFiniteInput&) { threw = true; }
    if (!threw) fail(T::name, "sos predicate accepted non-finite input", p);
    return;
  }
  const int o = certimesh::testing::oracle_sign<Dim, N>(p, T::lifted);
  const int f = pr::to_int(T::filtered(p));
  if (f != 0 && f != o) fail(T::name, "WRONG SIGN: filter contradicts the rational oracle", p);
  if (pr::to_int(T::exact(p)) != o) fail(T::name, "WRONG SIGN: exact predicate differs from the oracle", p);
  if (pr::to_int(T::stage(p)) != o) fail(T::name, "WRONG SIGN: exact stage differs from the oracle", p);
  const int s = pr::to_int(T::sos(p));
  if (o != 0 && s != o) fail(T::name, "sos differs from the non-zero exact sign", p);
  if (s == 0 && fz::distinct(p)) fail(T::name, "sos is zero for distinct points", p);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fz::DecodedInput in = fz::decode(data, size);
  switch (in.predicate) {
    case 0: check<O2>(in.o2.p); break;
    case 1: check<O3>(in.o3.p); break;
    case 2: check<IC>(in.ic.p); break;
    default: check<IS>(in.is.p); break;
  }
  return 0;
}
