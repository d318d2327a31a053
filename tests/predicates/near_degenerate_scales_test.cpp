// Near-degenerate tuples at many scales against the rational oracle: the inputs on which
// the orient2d filter's underflow term and orient3d's compensated stage
// (proofs/README.md sections 10 and 11) decide, which uniform RapidCheck inputs rarely
// reach with tails in every difference. Deterministic (seeded std::mt19937_64).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "rational_oracle.h"

namespace {

namespace pr = certimesh::predicates;

#if defined(__SANITIZE_ADDRESS__)
constexpr int cases_per_scale = 300;
#else
constexpr int cases_per_scale = 3000;
#endif

// Points p + s (q - p) (+ t (r - p)), s, t in [-1, 1], every coordinate rounded once: the
// exact determinant is tiny but rarely zero, and the differences have non-zero tails
// because the base point sits at an offset of 3 * scale from the origin.
struct NearDegenerate {
  std::mt19937_64 rng;
  double scale;
  double coordinate() {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    return (3.0 + u(rng)) * scale;
  }
  double parameter() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng); }
};

int oracle3(const std::array<std::array<double, 3>, 4>& p) {
  return certimesh::testing::oracle_sign<3, 4>(p, false);
}
int oracle2(const std::array<std::array<double, 2>, 3>& p) {
  return certimesh::testing::oracle_sign<2, 3>(p, false);
}

TEST(NearDegenerateScales, Orient3dNearCoplanarMatchesOracle) {
  int decided_nonzero = 0, total = 0;
  for (int e : {-300, -100, -20, 0, 20, 100, 300}) {
    NearDegenerate g{std::mt19937_64(0x5eed0003u + static_cast<unsigned>(e + 1000)), std::ldexp(1.0, e)};
    for (int i = 0; i < cases_per_scale; ++i) {
      std::array<double, 3> p, q, r;
      for (auto* v : {&p, &q, &r})
        for (double& c : *v) c = g.coordinate();
      std::array<std::array<double, 3>, 4> pts;
      for (auto& pt : pts) {
        const double s = g.parameter(), t = g.parameter();
        for (std::size_t k = 0; k < 3; ++k) pt[k] = p[k] + s * (q[k] - p[k]) + t * (r[k] - p[k]);
      }
      const pr::Point3 a{pts[0][0], pts[0][1], pts[0][2]}, b{pts[1][0], pts[1][1], pts[1][2]},
          c{pts[2][0], pts[2][1], pts[2][2]}, d{pts[3][0], pts[3][1], pts[3][2]};
      const int want = oracle3(pts);
      ASSERT_EQ(pr::to_int(pr::orient3d(a, b, c, d)), want) << "scale 2^" << e << " case " << i;
      decided_nonzero += want != 0;
      ++total;
    }
  }
  // The generator must produce near-coplanar, not exactly coplanar, tuples.
  EXPECT_GT(decided_nonzero, total * 9 / 10);
}

TEST(NearDegenerateScales, Orient2dNearCollinearFilterAndExactMatchOracle) {
  // Down to products in the subnormal range (2^-540 squared) and up to near overflow.
  for (int e : {-545, -540, -530, -500, -20, 0, 20, 500, 510}) {
    NearDegenerate g{std::mt19937_64(0x5eed0002u + static_cast<unsigned>(e + 1000)), std::ldexp(1.0, e)};
    for (int i = 0; i < cases_per_scale; ++i) {
      std::array<double, 2> p, q;
      for (auto* v : {&p, &q})
        for (double& c : *v) c = g.coordinate();
      std::array<std::array<double, 2>, 3> pts;
      for (auto& pt : pts) {
        const double s = g.parameter();
        for (std::size_t k = 0; k < 2; ++k) pt[k] = p[k] + s * (q[k] - p[k]);
      }
      const pr::Point2 a{pts[0][0], pts[0][1]}, b{pts[1][0], pts[1][1]}, c{pts[2][0], pts[2][1]};
      const int want = oracle2(pts);
      const int filtered = pr::to_int(pr::orient2d_filtered(a, b, c));
      ASSERT_TRUE(filtered == 0 || filtered == want) << "scale 2^" << e << " case " << i;
      ASSERT_EQ(pr::to_int(pr::orient2d(a, b, c)), want) << "scale 2^" << e << " case " << i;
    }
  }
}

}  // namespace
