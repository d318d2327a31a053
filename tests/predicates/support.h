// Shared plumbing of the predicate tests: one traits struct per predicate (kernel entry
// points, the rational oracle, a naive double evaluation, the generator), and a runner for
// RapidCheck properties with a fixed, printed seed and a per-property case count.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include "certimesh/fuzz/rc_generators.h"
#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "rational_oracle.h"

namespace certimesh::test {

namespace pr = certimesh::predicates;
namespace fz = certimesh::fuzz;

inline int sgn(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

inline pr::Point2 pt(const std::array<double, 2>& p) { return {p[0], p[1]}; }
inline pr::Point3 pt(const std::array<double, 3>& p) { return {p[0], p[1], p[2]}; }

// Naive double evaluations: the textbook formulas, no filter, no error bound. They must
// FAIL on the generators (generators_bite_test.cpp). Built with -ffp-contract=off.
inline int naive_orient2d(const std::array<std::array<double, 2>, 3>& p) {
  const double acx = p[0][0] - p[2][0], bcx = p[1][0] - p[2][0];
  const double acy = p[0][1] - p[2][1], bcy = p[1][1] - p[2][1];
  return sgn(acx * bcy - acy * bcx);
}
inline int naive_orient3d(const std::array<std::array<double, 3>, 4>& p) {
  double m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = p[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] - p[3][static_cast<std::size_t>(k)];
  return sgn(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
}
inline int naive_incircle(const std::array<std::array<double, 2>, 4>& p) {
  double m[3][3];
  for (std::size_t i = 0; i < 3; ++i) {
    const double dx = p[i][0] - p[3][0], dy = p[i][1] - p[3][1];
    m[i][0] = dx;
    m[i][1] = dy;
    m[i][2] = dx * dx + dy * dy;
  }
  return sgn(m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));
}
inline double det3(double a, double b, double c, double d, double e, double f, double g, double h,
                   double i) {
  return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
}
inline int naive_insphere(const std::array<std::array<double, 3>, 5>& p) {
  double m[4][4];
  for (std::size_t i = 0; i < 4; ++i) {
    const double dx = p[i][0] - p[4][0], dy = p[i][1] - p[4][1], dz = p[i][2] - p[4][2];
    m[i][0] = dx;
    m[i][1] = dy;
    m[i][2] = dz;
    m[i][3] = dx * dx + dy * dy + dz * dz;
  }
  double det = 0;
  for (int c = 0; c < 4; ++c) {
    double s[3][3];
    for (int r = 1; r < 4; ++r)
      for (int k = 0, kk = 0; k < 4; ++k)
        if (k != c) s[r - 1][kk++] = m[r][k];
    const double minor = det3(s[0][0], s[0][1], s[0][2], s[1][0], s[1][1], s[1][2], s[2][0],
                              s[2][1], s[2][2]);
    det += ((c & 1) ? -1.0 : 1.0) * m[0][c] * minor;
  }
  return sgn(det);
}

struct Orient2d {
  static constexpr const char* name = "orient2d";
  static constexpr std::size_t N = 3, Dim = 2;
  static constexpr bool lifted = false;
  using Input = fz::Orient2dInput;
  using Pts = std::array<std::array<double, 2>, 3>;
  static rc::Gen<Input> gen() { return fz::rcgen::orient2d_input(); }
  static rc::Gen<Input> exact_gen() { return fz::rcgen::exact_orient2d(); }
  static int exact(const Pts& p) { return pr::to_int(pr::orient2d(pt(p[0]), pt(p[1]), pt(p[2]))); }
  static int exact_stage(const Pts& p) {
    return pr::to_int(pr::detail::orient2d_exact_stage(pt(p[0]), pt(p[1]), pt(p[2])));
  }
  static int filtered(const Pts& p) { return pr::to_int(pr::orient2d_filtered(pt(p[0]), pt(p[1]), pt(p[2]))); }
  static int sos(const Pts& p) { return pr::to_int(pr::orient2d_sos(pt(p[0]), pt(p[1]), pt(p[2]))); }
  static int oracle(const Pts& p) { return testing::oracle_sign<2, 3>(p, false); }
  static int naive(const Pts& p) { return naive_orient2d(p); }
};

struct Orient3d {
  static constexpr const char* name = "orient3d";
  static constexpr std::size_t N = 4, Dim = 3;
  static constexpr bool lifted = false;
  using Input = fz::Orient3dInput;
  using Pts = std::array<std::array<double, 3>, 4>;
  static rc::Gen<Input> gen() { return fz::rcgen::orient3d_input(); }
  static rc::Gen<Input> exact_gen() { return fz::rcgen::exact_orient3d(); }
  static int exact(const Pts& p) {
    return pr::to_int(pr::orient3d(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int exact_stage(const Pts& p) {
    return pr::to_int(pr::detail::orient3d_exact_stage(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int filtered(const Pts& p) {
    return pr::to_int(pr::orient3d_filtered(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int sos(const Pts& p) {
    return pr::to_int(pr::orient3d_sos(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int oracle(const Pts& p) { return testing::oracle_sign<3, 4>(p, false); }
  static int naive(const Pts& p) { return naive_orient3d(p); }
};

struct Incircle {
  static constexpr const char* name = "incircle";
  static constexpr std::size_t N = 4, Dim = 2;
  static constexpr bool lifted = true;
  using Input = fz::IncircleInput;
  using Pts = std::array<std::array<double, 2>, 4>;
  static rc::Gen<Input> gen() { return fz::rcgen::incircle_input(); }
  static rc::Gen<Input> exact_gen() { return fz::rcgen::exact_incircle(); }
  static int exact(const Pts& p) {
    return pr::to_int(pr::incircle(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int exact_stage(const Pts& p) {
    return pr::to_int(pr::detail::incircle_exact_stage(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int filtered(const Pts& p) {
    return pr::to_int(pr::incircle_filtered(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int sos(const Pts& p) {
    return pr::to_int(pr::incircle_sos(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3])));
  }
  static int oracle(const Pts& p) { return testing::oracle_sign<2, 4>(p, true); }
  static int naive(const Pts& p) { return naive_incircle(p); }
};

struct Insphere {
  static constexpr const char* name = "insphere";
  static constexpr std::size_t N = 5, Dim = 3;
  static constexpr bool lifted = true;
  using Input = fz::InsphereInput;
  using Pts = std::array<std::array<double, 3>, 5>;
  static rc::Gen<Input> gen() { return fz::rcgen::insphere_input(); }
  static rc::Gen<Input> exact_gen() { return fz::rcgen::exact_insphere(); }
  static int exact(const Pts& p) {
    return pr::to_int(pr::insphere(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])));
  }
  static int exact_stage(const Pts& p) {
    return pr::to_int(
        pr::detail::insphere_exact_stage(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])));
  }
  static int filtered(const Pts& p) {
    return pr::to_int(pr::insphere_filtered(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])));
  }
  static int sos(const Pts& p) {
    return pr::to_int(pr::insphere_sos(pt(p[0]), pt(p[1]), pt(p[2]), pt(p[3]), pt(p[4])));
  }
  static int oracle(const Pts& p) { return testing::oracle_sign<3, 5>(p, true); }
  static int naive(const Pts& p) { return naive_insphere(p); }
};

/// The base seed of every property (printed); CERTIMESH_RC_SEED overrides it.
inline std::uint64_t base_seed() {
  if (const char* s = std::getenv("CERTIMESH_RC_SEED")) return std::strtoull(s, nullptr, 0);
  return 0x6365727469ull;  // "certi"
}

inline std::uint64_t seed_for(const std::string& id) {
  std::uint64_t h = 1469598103934665603ull ^ base_seed();  // FNV-1a of the property id
  for (unsigned char ch : id) h = (h ^ ch) * 1099511628211ull;
  return h;
}

/// Case count scaled by CERTIMESH_RC_SCALE (a float, default 1) for campaigns.
inline int scaled(int cases) {
  double f = 1.0;
  if (const char* s = std::getenv("CERTIMESH_RC_SCALE")) f = std::strtod(s, nullptr);
  return std::max(1, static_cast<int>(cases * f));
}

/// Runs a RapidCheck property with `cases` successes required and a fixed seed (both
/// printed). Returns the result; GTest failure when the property fails or gives up.
template <class Testable>
rc::detail::TestResult run_property(const std::string& id, int cases, Testable&& testable,
                                    bool expect_success = true) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = scaled(cases);
  params.seed = seed_for(id);
  params.maxDiscardRatio = 10;
  std::cout << "[property " << id << "] seed=" << params.seed << " max_success=" << params.maxSuccess
            << " (reproduce: CERTIMESH_RC_SEED=" << base_seed() << ")" << std::endl;
  rc::detail::TestMetadata meta;
  meta.id = id;
  meta.description = id;
  const auto result = rc::detail::checkTestable(std::forward<Testable>(testable), meta, params);
  if (expect_success) {
    if (result.template is<rc::detail::SuccessResult>()) {
      rc::detail::printResultMessage(result, std::cout);
      std::cout << std::endl;
    } else {
      std::ostringstream ss;
      rc::detail::printResultMessage(result, ss);
      ADD_FAILURE() << id << ": " << ss.str();
    }
  }
  return result;
}

/// Share of cases whose tags contain `tag`.
inline double tag_share(const rc::detail::Distribution& dist, const std::string& tag) {
  long total = 0, hit = 0;
  for (const auto& [tags, count] : dist) {
    total += count;
    for (const auto& t : tags)
      if (t == tag || t == "\"" + tag + "\"") {  // RC_TAG quotes string values
        hit += count;
        break;
      }
  }
  return total ? static_cast<double>(hit) / static_cast<double>(total) : 0.0;
}

template <class Pts>
bool has_duplicate(const Pts& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (p[i] == p[j]) return true;
  return false;
}

}  // namespace certimesh::test
