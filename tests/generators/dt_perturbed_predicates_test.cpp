// The GMP-free shortcuts of perturbed_predicates.h against the kernel's orient2d_sos and
// incircle_sos (the independent reference: GMP minors of the full perturbation scheme) on
// degenerate inputs: collinear triples, cocircular and collinear quadruples, in every
// argument order.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "certimesh/generators/delaunay/perturbed_predicates.h"

namespace certimesh::generators::detail {
namespace {

using predicates::to_int;

TEST(dt_perturbed_predicates, CollinearOrientMatchesTheKernelSoS) {
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<int> coord(-4, 4);
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // Points on a line through an integer point with an integer direction (incl. axes).
    const Point2 o{double(coord(rng)), double(coord(rng))};
    const Point2 d{double(coord(rng)), double(coord(rng))};
    if (d.x == 0 && d.y == 0) continue;
    std::array<Point2, 3> p;
    for (auto& q : p) {
      const double k = coord(rng);
      q = {o.x + k * d.x, o.y + k * d.y};
    }
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2]) continue;
    std::sort(p.begin(), p.end(), [](auto a, auto b) { return lexicographically_less(a, b); });
    do {
      ASSERT_EQ(orient_perturbed(p[0], p[1], p[2]), to_int(predicates::orient2d_sos(p[0], p[1], p[2])));
      ++compared;
    } while (std::next_permutation(p.begin(), p.end(), [](auto a, auto b) { return lexicographically_less(a, b); }));
  }
  EXPECT_GT(compared, 5000);
}

TEST(dt_perturbed_predicates, CocircularIncircleMatchesTheKernelSoS) {
  // Integer points on circles x^2 + y^2 = 25, 65, 325 (many representations), shifted, and
  // corners of unit squares; every argument order.
  std::vector<std::vector<Point2>> circles;
  for (int r2 : {25, 65, 325}) {
    std::vector<Point2> c;
    for (int x = -20; x <= 20; ++x)
      for (int y = -20; y <= 20; ++y)
        if (x * x + y * y == r2) c.push_back({x + 0.5, y - 3.0});
    circles.push_back(c);
  }
  circles.push_back({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  std::mt19937_64 rng(2);
  int compared = 0;
  for (const auto& c : circles) {
    for (int trial = 0; trial < 200; ++trial) {
      std::array<Point2, 4> p;
      std::vector<Point2> pool = c;
      std::shuffle(pool.begin(), pool.end(), rng);
      std::copy_n(pool.begin(), 4, p.begin());
      std::sort(p.begin(), p.end(), [](auto a, auto b) { return lexicographically_less(a, b); });
      do {
        ASSERT_EQ(incircle_perturbed(p[0], p[1], p[2], p[3]),
                  to_int(predicates::incircle_sos(p[0], p[1], p[2], p[3])));
        ++compared;
      } while (std::next_permutation(p.begin(), p.end(), [](auto a, auto b) { return lexicographically_less(a, b); }));
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(dt_perturbed_predicates, FourCollinearPointsMatchTheKernelSoS) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coord(-4, 4);
  int compared = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Point2 o{double(coord(rng)), double(coord(rng))};
    // Every third line horizontal or vertical: the cases where a monomial family vanishes.
    Point2 d{double(coord(rng)), double(coord(rng))};
    if (trial % 3 == 1) d.y = 0;
    if (trial % 3 == 2) d.x = 0;
    if (d.x == 0 && d.y == 0) continue;
    std::array<Point2, 4> p;
    for (auto& q : p) {
      const double k = coord(rng);
      q = {o.x + 0.5 * k * d.x, o.y + 0.5 * k * d.y};
    }
    std::sort(p.begin(), p.end(), [](auto a, auto b) { return lexicographically_less(a, b); });
    if (std::adjacent_find(p.begin(), p.end()) != p.end()) continue;
    do {
      ASSERT_EQ(incircle_perturbed(p[0], p[1], p[2], p[3]), to_int(predicates::incircle_sos(p[0], p[1], p[2], p[3])));
      ++compared;
    } while (std::next_permutation(p.begin(), p.end(), [](auto a, auto b) { return lexicographically_less(a, b); }));
  }
  EXPECT_GT(compared, 2000);
}

}  // namespace
}  // namespace certimesh::generators::detail
