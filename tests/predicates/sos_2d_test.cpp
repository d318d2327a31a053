// orient2d_sos and incircle_sos (the comparison-and-orient2d path of predicates/src/sos_2d.cpp)
// against the generic monomial search over GMP minors, detail::perturbed_sign, which
// implements the scheme of symbolic_perturbation.h literally and stays the oracle (it is
// itself checked against the perturbed determinant in sos_oracle_test.cpp).
//
// Only exactly degenerate inputs are compared (elsewhere _sos is the exact sign, which the
// other suites check), in every argument order, and on each the algebraic properties hold:
// never zero for distinct points, a transposition negates the sign, so every permutation
// gives its parity times the sign of the identity order.
//
// Inputs: every collinear triple and every degenerate quadruple of the 5x5 grid [-2, 2]^2
// (also mirrored, which brings -0.0, and scaled by powers of two to both ends of the
// exponent range, per axis for orient2d); collinear points on random lines through exactly
// representable positions (any slope, horizontal, vertical, through the origin with
// magnitudes from 2^-1000 to 2^1000); integer points of the circles x^2 + y^2 = 25, 625,
// 4225 around random centres; rectangles and coordinate-swapped quadruples of arbitrary
// doubles (cocircular for any values: coordinates duplicated on one axis).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/symbolic_perturbation.h"

namespace certimesh::test {
namespace {

namespace pr = certimesh::predicates;
using pr::Point2;

#if defined(__SANITIZE_ADDRESS__)
constexpr int kWorkDivisor = 8;  // the GMP oracle is ~10x slower under ASan
#else
constexpr int kWorkDivisor = 1;
#endif

std::string describe(const std::vector<Point2>& p) {
  std::string s;
  char buf[96];
  for (const Point2& q : p) {
    std::snprintf(buf, sizeof buf, "(%a, %a) ", q.x, q.y);
    s += buf;
  }
  return s;
}

int permutation_parity(const std::vector<std::size_t>& perm) {
  int inversions = 0;
  for (std::size_t i = 0; i < perm.size(); ++i)
    for (std::size_t j = i + 1; j < perm.size(); ++j) inversions += perm[i] > perm[j];
  return (inversions & 1) ? -1 : 1;
}

// Counts the degenerate orderings checked; records the first few mismatches.
class SosChecker {
 public:
  SosChecker() = default;
  SosChecker(const SosChecker&) = delete;
  SosChecker& operator=(const SosChecker&) = delete;
  // The count shows in the XML report: the suite's reach, not a pass criterion.
  ~SosChecker() { ::testing::Test::RecordProperty("degenerate_orderings", std::to_string(checked_)); }

  // Checks every ordering of `pts` (3 points: orient2d, 4: incircle) when the points are
  // distinct and exactly degenerate; returns whether they were.
  bool check_all_orders(const std::vector<Point2>& pts) {
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j)
        if (pts[i] == pts[j]) return false;
    if (exact(pts) != pr::Sign::zero) return false;
    std::vector<std::size_t> perm(pts.size());
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    const int identity = pr::to_int(fast(pts));
    std::vector<Point2> q(pts.size());
    do {
      for (std::size_t i = 0; i < pts.size(); ++i) q[i] = pts[perm[i]];
      check_one(q, permutation_parity(perm) * identity);
    } while (std::next_permutation(perm.begin(), perm.end()));
    return true;
  }

  long checked() const { return checked_; }

 private:
  static pr::Sign exact(const std::vector<Point2>& p) {
    return p.size() == 3 ? pr::orient2d(p[0], p[1], p[2]) : pr::incircle(p[0], p[1], p[2], p[3]);
  }
  static pr::Sign fast(const std::vector<Point2>& p) {
    return p.size() == 3 ? pr::orient2d_sos(p[0], p[1], p[2])
                         : pr::incircle_sos(p[0], p[1], p[2], p[3]);
  }
  static pr::Sign generic(const std::vector<Point2>& p) {
    std::vector<double> raw;
    for (const Point2& q : p) raw.insert(raw.end(), {q.x, q.y});
    return pr::detail::perturbed_sign(raw, 2, p.size() == 4);
  }

  void check_one(const std::vector<Point2>& p, int by_parity) {
    ++checked_;
    const int got = pr::to_int(fast(p)), expected = pr::to_int(generic(p));
    if (got == expected && got != 0 && got == by_parity) return;
    if (++failures_ <= 10)
      ADD_FAILURE() << (p.size() == 3 ? "orient2d_sos " : "incircle_sos ") << describe(p)
                    << "= " << got << ", generic search " << expected
                    << ", parity times identity order " << by_parity;
  }

  long checked_ = 0;
  int failures_ = 0;
};

// Affine images of the grid: x' = sx * 2^ex * x, y' = sy * 2^ey * y. Scaling an axis keeps
// collinearity (and cocircularity only when both scale alike: the quadruples that stay
// degenerate are checked, the others skipped).
struct GridImage {
  double sx, sy;
  int ex, ey;
  Point2 operator()(int x, int y) const {
    return {sx * std::ldexp(static_cast<double>(x), ex), sy * std::ldexp(static_cast<double>(y), ey)};
  }
};

std::vector<GridImage> grid_images() {
  return {{1, 1, 0, 0},        {-1, 1, 0, 0},       {1, -1, 0, 0},     {-1, -1, 0, 0},
          {1, 1, -1072, -1072}, {1, 1, 1000, 1000}, {1, 1, 600, -600}, {-1, 1, -900, 900}};
}

std::vector<Point2> grid_points(const GridImage& image) {
  std::vector<Point2> pts;
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y) pts.push_back(image(x, y));
  return pts;
}

TEST(sos_2d, EveryCollinearTripleOfTheGridInEveryOrder) {
  SosChecker checker;
  for (const GridImage& image : grid_images()) {
    const std::vector<Point2> g = grid_points(image);
    long degenerate = 0;
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = i + 1; j < g.size(); ++j)
        for (std::size_t k = j + 1; k < g.size(); ++k) degenerate += checker.check_all_orders({g[i], g[j], g[k]});
    // Collinear triples of a 5x5 grid: 10 lines of 5 points (rows, columns) x C(5,3) = 100,
    // slope +-1 diagonals of 3, 4, 5, 4, 3 points: 2 x (1 + 4 + 10 + 4 + 1) = 40, and
    // 12 lines of 3 points of slopes +-2, +-1/2: 152. Axis scalings keep collinearity.
    EXPECT_EQ(degenerate, 152);
  }
  EXPECT_EQ(checker.checked(), 8 * 152 * 6);
}

// det[x y x^2+y^2 1] of small integer points, in 64-bit integers (|entries| <= 8): the
// independent count of the grid's degenerate quadruples.
long long integer_incircle(const std::array<std::array<long long, 2>, 4>& p) {
  long long m[3][3];
  for (std::size_t i = 0; i < 3; ++i) {
    const long long dx = p[i][0] - p[3][0], dy = p[i][1] - p[3][1];
    m[i][0] = dx;
    m[i][1] = dy;
    m[i][2] = dx * dx + dy * dy;
  }
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

TEST(sos_2d, EveryDegenerateQuadrupleOfTheGridInEveryOrder) {
  long expected_degenerate = 0;
  for (int a = 0; a < 25; ++a)
    for (int b = a + 1; b < 25; ++b)
      for (int c = b + 1; c < 25; ++c)
        for (int d = c + 1; d < 25; ++d)
          expected_degenerate += integer_incircle({{{a / 5, a % 5}, {b / 5, b % 5}, {c / 5, c % 5},
                                                    {d / 5, d % 5}}}) == 0;
  ASSERT_GT(expected_degenerate, 64);  // more than the 64 collinear quadruples
  SosChecker checker;
  const std::vector<GridImage> images = grid_images();
  for (std::size_t n = 0; n < images.size(); n += static_cast<std::size_t>(kWorkDivisor > 1 ? 3 : 1)) {
    const std::vector<Point2> g = grid_points(images[n]);
    long degenerate = 0;
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = i + 1; j < g.size(); ++j)
        for (std::size_t k = j + 1; k < g.size(); ++k)
          for (std::size_t l = k + 1; l < g.size(); ++l)
            degenerate += checker.check_all_orders({g[i], g[j], g[k], g[l]});
    const GridImage& im = images[n];
    if (im.ex == im.ey && std::fabs(im.sx) == std::fabs(im.sy))  // a similarity: same set
      EXPECT_EQ(degenerate, expected_degenerate);
    else  // rectangles and collinear quadruples stay degenerate
      EXPECT_GE(degenerate, 64);
  }
  EXPECT_GT(checker.checked(), 0);
}

// A random double with `bits` significant bits and exponent in [emin, emax].
double random_dyadic(std::mt19937_64& rng, int bits, int emin, int emax) {
  const auto mantissa = static_cast<std::int64_t>(rng() >> (64 - bits));
  const int e = std::uniform_int_distribution<int>(emin, emax)(rng);
  return std::ldexp(static_cast<double>(mantissa) * ((rng() & 1) ? 1.0 : -1.0), e);
}

// n distinct points P + t D on one line, every coordinate exact: P has 30-bit integer
// coordinates, D up to 10 bits (a zero component a quarter of the time each), t in
// [-16, 16], all scaled by one power of two.
std::vector<Point2> random_collinear(std::mt19937_64& rng, std::size_t n) {
  const auto coord = [&](int bits) { return static_cast<double>(static_cast<std::int64_t>(rng() >> (64 - bits)) - (std::int64_t{1} << (bits - 1))); };
  const double px = coord(30), py = coord(30);
  double dx = coord(10), dy = coord(10);
  const unsigned axis = static_cast<unsigned>(rng() % 4);
  if (axis == 0) dx = 0;
  if (axis == 1) dy = 0;
  if (dx == 0 && dy == 0) dx = 1;
  const int scale = std::uniform_int_distribution<int>(-1000, 950)(rng);
  std::vector<double> ts;
  while (ts.size() < n) {
    const auto t = static_cast<double>(std::uniform_int_distribution<int>(-16, 16)(rng));
    if (std::find(ts.begin(), ts.end(), t) == ts.end()) ts.push_back(t);
  }
  std::vector<Point2> pts;
  for (double t : ts) pts.push_back({std::ldexp(px + t * dx, scale), std::ldexp(py + t * dy, scale)});
  return pts;
}

// n distinct points t D on a line through the origin, the t of every magnitude.
std::vector<Point2> random_collinear_through_origin(std::mt19937_64& rng, std::size_t n) {
  const double dx = (rng() % 4 == 0) ? 0.0 : random_dyadic(rng, 20, 0, 0);
  const double dy = (rng() % 4 == 1 || dx == 0.0) ? (dx == 0.0 ? 1.0 : 0.0) : random_dyadic(rng, 20, 0, 0);
  std::vector<Point2> pts;
  while (pts.size() < n) {
    const double t = random_dyadic(rng, 8, -1000, 980);
    const Point2 p{t * dx, t * dy};
    if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
  }
  return pts;
}

TEST(sos_2d, CollinearPointsOnRandomLines) {
  std::mt19937_64 rng(20261130);
  SosChecker checker;
  const int lines = 4000 / kWorkDivisor;
  long degenerate = 0;
  for (int i = 0; i < lines; ++i) {
    const auto line = (i & 1) ? random_collinear(rng, 4) : random_collinear_through_origin(rng, 4);
    degenerate += checker.check_all_orders({line[0], line[1], line[2]});
    degenerate += checker.check_all_orders(line);
  }
  EXPECT_EQ(degenerate, 2 * lines);  // collinear points are always exactly degenerate
}

// The integer points of x^2 + y^2 = r2.
std::vector<std::array<int, 2>> circle_points(int r2) {
  std::vector<std::array<int, 2>> pts;
  for (int x = -100; x <= 100; ++x)
    for (int y = -100; y <= 100; ++y)
      if (x * x + y * y == r2) pts.push_back({x, y});
  return pts;
}

TEST(sos_2d, IntegerPointsOfCirclesAroundRandomCentres) {
  std::mt19937_64 rng(5);
  SosChecker checker;
  // r2(n) = 4 (d1(n) - d3(n)): 12 points on 25 = 5^2, 20 on 625 = 5^4, 36 on 4225 = 65^2.
  const std::array<std::pair<int, std::size_t>, 3> circles{{{25, 12}, {625, 20}, {4225, 36}}};
  for (const auto& [r2, count] : circles) {
    const auto ring = circle_points(r2);
    ASSERT_EQ(ring.size(), count);
    for (int i = 0; i < 1500 / kWorkDivisor; ++i) {
      const double cx = std::uniform_int_distribution<int>(-1 << 20, 1 << 20)(rng);
      const double cy = std::uniform_int_distribution<int>(-1 << 20, 1 << 20)(rng);
      const int scale = std::uniform_int_distribution<int>(-1040, 960)(rng);
      std::vector<std::size_t> pick(ring.size());
      std::iota(pick.begin(), pick.end(), std::size_t{0});
      std::shuffle(pick.begin(), pick.end(), rng);
      std::vector<Point2> quad;
      for (std::size_t k = 0; k < 4; ++k)
        quad.push_back({std::ldexp(cx + ring[pick[k]][0], scale), std::ldexp(cy + ring[pick[k]][1], scale)});
      EXPECT_TRUE(checker.check_all_orders(quad)) << describe(quad);
    }
  }
}

TEST(sos_2d, RectanglesAndSwappedCoordinatesOfArbitraryDoubles) {
  std::mt19937_64 rng(1990);
  SosChecker checker;
  for (int i = 0; i < 3000 / kWorkDivisor; ++i) {
    const double x1 = random_dyadic(rng, 53, -1000, 960), x2 = random_dyadic(rng, 53, -1000, 960);
    const double y1 = (i % 3 == 0) ? x1 : random_dyadic(rng, 53, -1000, 960);
    const double y2 = random_dyadic(rng, 53, -1000, 960);
    // Corners of an axis-parallel rectangle: cocircular whatever the values.
    const std::vector<Point2> rectangle{{x1, y1}, {x2, y1}, {x2, y2}, {x1, y2}};
    // (a, b), (b, a), (-a, b), (a, -b): all on the circle of radius sqrt(a^2 + b^2).
    const std::vector<Point2> swapped{{x1, y2}, {y2, x1}, {-x1, y2}, {x1, -y2}};
    EXPECT_TRUE(checker.check_all_orders(rectangle)) << describe(rectangle);
    EXPECT_TRUE(checker.check_all_orders(swapped)) << describe(swapped);
    // Three points of the vertical line x = x1 (skipped when two coincide).
    const std::vector<Point2> column{{x1, y1}, {x1, y2}, {x1, x2}};
    checker.check_all_orders(column);
  }
}

}  // namespace
}  // namespace certimesh::test
