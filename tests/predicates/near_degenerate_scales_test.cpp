// Near-degenerate tuples at many scales against the rational oracle: the inputs on which
// the orient2d filter's underflow term and the compensated stages of orient3d and
// incircle (proofs/README.md sections 10 to 12) decide, which uniform RapidCheck inputs rarely
// reach with tails in every difference. Deterministic (seeded std::mt19937_64).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "certimesh/predicates/incircle.h"
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
int oracle_incircle(const std::array<std::array<double, 2>, 4>& p) {
  return certimesh::testing::oracle_sign<2, 4>(p, true);
}

// Four points of a circle, every coordinate rounded once: the centre at an offset of about
// 3 * scale (so the differences have tails), the radius in [0.1, 1] * scale.
std::array<std::array<double, 2>, 4> near_cocircular(NearDegenerate& g) {
  const double cx = g.coordinate(), cy = g.coordinate();
  const double rad = (0.55 + 0.45 * g.parameter()) * g.scale;
  std::array<std::array<double, 2>, 4> pts;
  for (auto& pt : pts) {
    const double th = 3.14159265358979 * g.parameter();
    pt = {cx + rad * std::cos(th), cy + rad * std::sin(th)};
  }
  return pts;
}

// Four points of the circle x^2 + y^2 = 25 (integer points), scaled by a power of two and
// moved by a dyadic centre: exactly cocircular, so only the expansion stages may answer
// (zero), and one coordinate moved by one ulp: a sign decided at the last bit.
std::array<std::array<double, 2>, 4> exactly_cocircular(NearDegenerate& g, int i) {
  static constexpr std::array<std::array<double, 2>, 12> on_circle{
      {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5},
       {3, -4}, {4, -3}}};
  const double cx = std::ldexp(std::round(g.coordinate() / g.scale * 1024.0), -10) * g.scale;
  const double cy = std::ldexp(std::round(g.coordinate() / g.scale * 1024.0), -10) * g.scale;
  std::array<std::array<double, 2>, 4> pts;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& q = on_circle[(static_cast<std::size_t>(i) * 5 + k * 3) % 12];
    pts[k] = {cx + q[0] * g.scale / 8.0, cy + q[1] * g.scale / 8.0};
  }
  if (i % 2 == 1) pts[3][0] = std::nextafter(pts[3][0], INFINITY);
  return pts;
}

// Integer points of the circle x^2 + y^2 = N, N the product of the 18 primes 5, 13, ...,
// 173 (all 1 mod 4), about 2^105.7: each prime is a Gaussian integer times its conjugate,
// so each choice of conjugates gives a point (coordinates below 2^53, exact doubles).
// Points on opposite sides have differences of 54 bits: rounded differences with tails,
// and an exactly zero determinant that a stage must not mistake for a sign.
std::array<double, 2> gaussian_circle_point(std::mt19937_64& rng) {
  static constexpr std::array<std::array<std::int64_t, 2>, 18> primes{
      {{2, 1}, {3, 2}, {4, 1}, {5, 2}, {6, 1}, {5, 4}, {7, 2}, {6, 5}, {8, 3}, {8, 5}, {9, 4},
       {10, 1}, {10, 3}, {8, 7}, {11, 4}, {10, 7}, {11, 6}, {13, 2}}};
  std::int64_t x = 1, y = 0;
  for (const auto& g : primes) {
    const std::int64_t gy = (rng() & 1u) != 0 ? g[1] : -g[1];  // the prime or its conjugate
    const std::int64_t nx = x * g[0] - y * gy, ny = x * gy + y * g[0];
    x = nx;
    y = ny;
  }
  // one of the eight symmetries of the circle
  const unsigned k = static_cast<unsigned>(rng() % 8u);
  if ((k & 1u) != 0) std::swap(x, y);
  return {static_cast<double>((k & 2u) != 0 ? -x : x), static_cast<double>((k & 4u) != 0 ? -y : y)};
}

void expect_incircle_matches_oracle(const std::array<std::array<double, 2>, 4>& pts, int e, int i) {
  const pr::Point2 a{pts[0][0], pts[0][1]}, b{pts[1][0], pts[1][1]}, c{pts[2][0], pts[2][1]},
      d{pts[3][0], pts[3][1]};
  ASSERT_EQ(pr::to_int(pr::incircle(a, b, c, d)), oracle_incircle(pts))
      << "scale 2^" << e << " case " << i;
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

TEST(NearDegenerateScales, IncircleNearCocircularMatchesOracle) {
  // Inside the guards [2^-240, 2^250] of the compensated stage, at both ends of them, and
  // outside them (the stage declines, the expansion stages answer).
  int nonzero = 0, total = 0;
  for (int e : {-300, -238, -100, -20, 0, 20, 100, 246, 260}) {
    NearDegenerate g{std::mt19937_64(0x5eed0004u + static_cast<unsigned>(e + 1000)), std::ldexp(1.0, e)};
    for (int i = 0; i < cases_per_scale; ++i) {
      const auto pts = near_cocircular(g);
      ASSERT_NO_FATAL_FAILURE(expect_incircle_matches_oracle(pts, e, i));
      nonzero += oracle_incircle(pts) != 0;
      ++total;
    }
    for (int i = 0; i < cases_per_scale / 10; ++i)
      ASSERT_NO_FATAL_FAILURE(expect_incircle_matches_oracle(exactly_cocircular(g, i), e, i));
  }
  // The generator must produce near-cocircular, not exactly cocircular, tuples.
  EXPECT_GT(nonzero, total * 9 / 10);
}

TEST(NearDegenerateScales, IncircleExactlyCocircularIsZero) {
  // The oracle agreeing is not enough: the unmoved tuples must be exactly cocircular.
  NearDegenerate g{std::mt19937_64(0x5eed0005u), 1.0};
  for (int i = 0; i < 40; i += 2) {
    const auto pts = exactly_cocircular(g, i);
    ASSERT_EQ(oracle_incircle(pts), 0) << "case " << i;
    ASSERT_NO_FATAL_FAILURE(expect_incircle_matches_oracle(pts, 0, i));
  }
}

TEST(NearDegenerateScales, IncircleCocircularWithTailsMatchesOracle) {
  // Exactly cocircular integer points (zero) and the same moved by one ulp (a sign at the
  // last bit), scaled by powers of two inside and outside the compensated stage's guards.
  int zeros = 0, total = 0;
  for (int e : {-290, -240, -100, 0, 100, 190}) {
    std::mt19937_64 rng(0x5eed0006u + static_cast<unsigned>(e + 1000));
    for (int i = 0; i < cases_per_scale / 3; ++i) {
      std::array<std::array<double, 2>, 4> pts;
      for (auto& pt : pts) {
        const auto q = gaussian_circle_point(rng);
        pt = {std::ldexp(q[0], e), std::ldexp(q[1], e)};
      }
      if (i % 3 == 2) pts[i % 4][i % 2] = std::nextafter(pts[i % 4][i % 2], (i % 5 < 2) ? -INFINITY : INFINITY);
      ASSERT_NO_FATAL_FAILURE(expect_incircle_matches_oracle(pts, e, i));
      zeros += oracle_incircle(pts) == 0;
      ++total;
    }
  }
  // Mostly exact zeros (a repeated point also gives zero): the case the stage must leave.
  EXPECT_GT(zeros, total / 2);
}

// The small-integer stage of the exact incircle (proofs/README.md section 13): integer
// coordinates up to 2^51, differences up to 2^12 evaluated in plain double. Called under
// the filter (detail::incircle_exact_stage), on lattice points of circles x^2 + y^2 = R
// with many representations (exact zeros), moved by one unit (signs decided by a few units
// of a determinant of order 2^48), around centres from 0 to beyond 2^51, with radii below
// and above the 2^12 limit (there the other stages answer; a limit raised past 2^12 makes
// the double evaluation round and these cases fail), and at half-integer positions (not
// integers: the stage must decline).
TEST(NearDegenerateScales, IncircleSmallIntegerStageMatchesOracle) {
  std::mt19937_64 rng(0x5eed0007u);
  int zeros = 0, total = 0;
  // R = 25, 5 * 13 * 17 * 29 (radius ~179), * 37 (~1089), 2 * 5 * 13 * 17 * 29 * 41 (~1621):
  // differences below 2^12; 5^2 * 13 * 17 * 29 * 37 (~2435): some above; 5 * 13 * 17 * 29 *
  // 37 * 41 (~6972): differences up to ~13944; * 53 * 61 (~396,400): up to ~2^19.6, where
  // the double evaluation rounds (the stage with its limit raised to 2^20 fails here).
  for (const std::int64_t r2 : {std::int64_t{25}, std::int64_t{32045}, std::int64_t{1185665}, std::int64_t{2627690},
                                std::int64_t{5928325}, std::int64_t{48612265}, std::int64_t{157163452745}}) {
    std::vector<std::array<std::int64_t, 2>> lattice;
    for (std::int64_t x = 0; x * x <= r2; ++x) {
      const auto y = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(r2 - x * x))));
      for (std::int64_t yy = std::max<std::int64_t>(0, y - 1); yy <= y + 1; ++yy)
        if (x * x + yy * yy == r2)
          for (int k = 0; k < 4; ++k) lattice.push_back({(k & 1) ? -x : x, (k & 2) ? -yy : yy});
    }
    ASSERT_GE(lattice.size(), 8u) << r2;
    for (const double base : {0.0, 1000.0, -123456789.0, 0x1p40, 0x1p51 - 20000.0, 0x1p51 + 4096.0, 0x1p52}) {
      for (int i = 0; i < 200; ++i) {
        const double cx = base + static_cast<double>(rng() % 2001) - 1000.0;
        const double cy = -base + static_cast<double>(rng() % 2001) - 1000.0;
        std::array<std::array<double, 2>, 4> pts;
        for (auto& pt : pts) {
          const auto& q = lattice[rng() % lattice.size()];
          pt = {cx + static_cast<double>(q[0]), cy + static_cast<double>(q[1])};
        }
        const int move = static_cast<int>(i % 6);
        if (move == 1 || move == 2) pts[i % 4][i % 2] += move == 1 ? 1.0 : -1.0;
        if (move == 3) pts[i % 4][i % 2] += 0.5;  // a half-integer: not for this stage
        const pr::Point2 a{pts[0][0], pts[0][1]}, b{pts[1][0], pts[1][1]}, c{pts[2][0], pts[2][1]},
            d{pts[3][0], pts[3][1]};
        const int want = oracle_incircle(pts);
        ASSERT_EQ(pr::to_int(pr::detail::incircle_exact_stage(a, b, c, d)), want)
            << "R " << r2 << " base " << base << " case " << i;
        ASSERT_EQ(pr::to_int(pr::incircle(a, b, c, d)), want) << "R " << r2 << " base " << base << " case " << i;
        zeros += want == 0;
        ++total;
      }
    }
  }
  // Random small-integer tuples (mostly far from cocircular) and the limit itself: every
  // difference exactly +-2^12, and one of them 2^12 + 1.
  for (int i = 0; i < 3000; ++i) {
    std::array<std::array<double, 2>, 4> pts;
    for (auto& pt : pts)
      for (double& v : pt) v = static_cast<double>(static_cast<std::int64_t>(rng() % 8193) - 4096);
    if (i % 3 == 0)
      for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < 2; ++j) pts[k][j] = pts[3][j] + ((rng() & 1u) != 0 ? 4096.0 : -4096.0);
    if (i % 3 == 1) pts[0][0] = pts[3][0] + 4097.0;
    const pr::Point2 a{pts[0][0], pts[0][1]}, b{pts[1][0], pts[1][1]}, c{pts[2][0], pts[2][1]},
        d{pts[3][0], pts[3][1]};
    const int want = oracle_incircle(pts);
    ASSERT_EQ(pr::to_int(pr::detail::incircle_exact_stage(a, b, c, d)), want) << "random case " << i;
    zeros += want == 0;
    ++total;
  }
  // Points of x^2 + y^2 = 25 around the origin, one coordinate moved by 2^-50: exact
  // coordinates, not integers (the stage must decline: in double the determinant, of order
  // 2^-47, drowns in the rounding of terms of order 2^10).
  static constexpr std::array<std::array<double, 2>, 12> on25{
      {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}}};
  for (int i = 0; i < 400; ++i) {
    std::array<std::array<double, 2>, 4> pts;
    for (auto& pt : pts) pt = on25[rng() % 12];
    pts[i % 4][(i / 4) % 2] += (i % 3 == 0) ? 0x1p-50 : -0x1p-50;
    const pr::Point2 a{pts[0][0], pts[0][1]}, b{pts[1][0], pts[1][1]}, c{pts[2][0], pts[2][1]},
        d{pts[3][0], pts[3][1]};
    ASSERT_EQ(pr::to_int(pr::detail::incircle_exact_stage(a, b, c, d)), oracle_incircle(pts)) << "moved case " << i;
  }
  // The lattice cases are mostly exact zeros (the moved ones are not).
  EXPECT_GT(zeros, total / 4);
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
