// Fixed adversarial inputs, each checked against the rational oracle:
//   - the three classroom orientation grids of Kettner et al. (3 x 65,536 triples);
//   - the convex-hull failure sets A1, A1-global, A2, B1, B2 (every ordered triple);
//   - the two counterexamples to the monograph's printed d() bounds (predicates.md section 0);
//   - non-finite input (NaN, +-Inf in every coordinate position);
//   - extreme ranges: 1e+-300, subnormals, the 1e155 overflow case, and degenerate integer
//     configurations scaled over the whole exponent range with +-1 ulp perturbations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "certimesh/predicates/non_finite_input.h"
#include "support.h"

namespace certimesh::test {
namespace {

using P2 = std::array<double, 2>;
using P3 = std::array<double, 3>;

// ------------------------------------------------------------------------------------------
// (a) Classroom grids

struct GridResult {
  long kernel_wrong = 0, filter_contradictions = 0, filter_certified = 0;
  long naive_wrong = 0, naive_zero = 0, exact_zero = 0;
};

GridResult run_grid(P2 p, P2 q, P2 r) {
  GridResult g;
  const double ux = std::nextafter(p[0], INFINITY) - p[0];
  const double uy = std::nextafter(p[1], INFINITY) - p[1];
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) {
      const P2 a{p[0] + x * ux, p[1] + y * uy};
      EXPECT_TRUE(fz::sum_is_exact(p[0], x * ux) && fz::sum_is_exact(p[1], y * uy));
      const Orient2d::Pts pts{a, q, r};
      const int o = Orient2d::oracle(pts);
      const int k = Orient2d::exact(pts);
      const int f = Orient2d::filtered(pts);
      const int n = Orient2d::naive(pts);
      g.kernel_wrong += k != o;
      g.filter_contradictions += f != 0 && f != o;
      g.filter_certified += f != 0;
      g.naive_wrong += n != o;
      g.naive_zero += n == 0;
      g.exact_zero += o == 0;
    }
  return g;
}

void check_grid(const char* name, P2 p, P2 q, P2 r) {
  const GridResult g = run_grid(p, q, r);
  std::cout << "[classroom grid " << name << "] 65536 triples: kernel wrong " << g.kernel_wrong
            << ", filter contradictions " << g.filter_contradictions << ", filter certified "
            << g.filter_certified << ", exact zeros " << g.exact_zero << "; naive double wrong "
            << g.naive_wrong << " (" << 100.0 * static_cast<double>(g.naive_wrong) / 65536.0
            << " %), naive zeros " << g.naive_zero << std::endl;
  EXPECT_EQ(g.kernel_wrong, 0);
  EXPECT_EQ(g.filter_contradictions, 0);
  EXPECT_GT(g.naive_wrong, 0) << "the grid no longer exercises rounding";
}

TEST(ClassroomGrids, GridA) { check_grid("a", {0.5, 0.5}, {12, 12}, {24, 24}); }
TEST(ClassroomGrids, GridB) {
  check_grid("b", {0.50000000000002531, 0.5000000000000171},
             {17.300000000000001, 17.300000000000001}, {24.00000000000005, 24.0000000000000517765});
}
TEST(ClassroomGrids, GridC) {
  check_grid("c", {0.5, 0.5}, {8.8000000000000007, 8.8000000000000007}, {12.1, 12.1});
}

// ------------------------------------------------------------------------------------------
// (b) Convex-hull failure sets: every ordered triple of distinct points.

void check_hull_set(const char* name, const std::vector<P2>& pts) {
  long triples = 0, wrong = 0, contradictions = 0, naive_wrong = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = 0; j < pts.size(); ++j)
      for (std::size_t k = 0; k < pts.size(); ++k) {
        if (i == j || j == k || i == k) continue;
        const Orient2d::Pts t{pts[i], pts[j], pts[k]};
        const int o = Orient2d::oracle(t);
        const int f = Orient2d::filtered(t);
        ++triples;
        wrong += Orient2d::exact(t) != o;
        wrong += Orient2d::exact_stage(t) != o;
        contradictions += f != 0 && f != o;
        naive_wrong += Orient2d::naive(t) != o;
      }
  std::cout << "[hull set " << name << "] " << triples << " ordered triples: kernel wrong "
            << wrong << ", filter contradictions " << contradictions << "; naive wrong "
            << naive_wrong << std::endl;
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(contradictions, 0);
}

TEST(HullFailureSets, A1) {
  check_hull_set("A1", {{7.3000000000000194, 7.3000000000000167},
                        {24.000000000000068, 24.000000000000071},
                        {24.00000000000005, 24.000000000000053},
                        {0.50000000000001621, 0.50000000000001243},
                        {8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}});
}
TEST(HullFailureSets, A1Global) {
  check_hull_set("A1-global", {{0.1, 0.1}, {0.2, 0.20000000000000004},
                               {0.79999999999999993, 0.80000000000000004},
                               {1.267650600228229e30, 1.2676506002282291e30}});
}
TEST(HullFailureSets, A2) {
  check_hull_set("A2", {{27.643564356435643, -21.881188118811881},
                        {83.366336633663366, 15.544554455445542},
                        {4, 4},
                        {73.415841584158414, 8.8613861386138595}});
}
TEST(HullFailureSets, B1) {
  check_hull_set("B1", {{200, 49.200000000000003}, {100, 49.600000000000001},
                        {-233.33333333333334, 50.93333333333333},
                        {166.66666666666669, 49.333333333333336}});
}
TEST(HullFailureSets, B2) {
  check_hull_set("B2", {{0.50000000000001243, 0.50000000000000189},
                        {0.50000000000001243, 0.50000000000000333},
                        {24.00000000000005, 24.000000000000053},
                        {24.000000000000068, 24.000000000000071},
                        {17.300000000000001, 17.300000000000001}});
}

// ------------------------------------------------------------------------------------------
// (c) The monograph's printed filters, as the digests transcribe them, and their
// counterexamples (predicates.md section 0). Regression pins: the printed formula certifies
// a WRONG sign; the kernel answers uncertain or the right sign; the exact sign is the
// oracle's.

// B-3.1-3.5.md section 3.5, Algorithm 12 (L1861-1893):
//   a := x1 - x3; b := y1 - y3; c := x2 - x3; d := y2 - y3
//   r := eps (|a| + |b| + |c| + |d| + 2|ad| + 2|bc|);  D := ad - bc
//   D > r -> +1, D < -r -> -1, else 0
int monograph_d2(const P2& v1, const P2& v2, const P2& v3, double eps) {
  const double a = v1[0] - v3[0], b = v1[1] - v3[1], c = v2[0] - v3[0], d = v2[1] - v3[1];
  const double r = eps * (std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d) +
                          2 * std::fabs(a * d) + 2 * std::fabs(b * c));
  const double D = a * d - b * c;
  return D > r ? 1 : (D < -r ? -1 : 0);
}

// C-3.6-4.5.md section 1.3 (L2505-2516): the 3x3 matrix [a b c; d e f; g h i] of
// v1 - v4, v2 - v4, v3 - v4;  D = aei - ceg + bfg - afh + cdh - bdi;
//   r = eps (|a| + ... + |i| + |aei| + |ceg| + |bfg| + |afh| + |cdh| + |bdi|)
int monograph_d3(const P3& v1, const P3& v2, const P3& v3, const P3& v4, double eps) {
  const double a = v1[0] - v4[0], b = v1[1] - v4[1], c = v1[2] - v4[2];
  const double d = v2[0] - v4[0], e = v2[1] - v4[1], f = v2[2] - v4[2];
  const double g = v3[0] - v4[0], h = v3[1] - v4[1], i = v3[2] - v4[2];
  const double D = a * e * i - c * e * g + b * f * g - a * f * h + c * d * h - b * d * i;
  const double r = eps * (std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d) +
                          std::fabs(e) + std::fabs(f) + std::fabs(g) + std::fabs(h) +
                          std::fabs(i) + std::fabs(a * e * i) + std::fabs(c * e * g) +
                          std::fabs(b * f * g) + std::fabs(a * f * h) + std::fabs(c * d * h) +
                          std::fabs(b * d * i));
  return D > r ? 1 : (D < -r ? -1 : 0);
}

TEST(MonographCounterexamples, Orient2dPrintedBoundWithUnitRoundoffIsUnsound) {
  const P2 v1{182.77170981294643, 403.68866801506164};
  const P2 v2{771.92835113580475, 974.08982576763151};
  const P2 v3{773.53783630239855, 975.64807384296398};
  // d(v2, v3, v1): base vertex v1 (float D = +1.746e-10 > r = 1.499e-10).
  const Orient2d::Pts t{v2, v3, v1};
  const int o = Orient2d::oracle(t);
  ASSERT_EQ(o, -1);
  EXPECT_EQ(monograph_d2(v2, v3, v1, 0x1p-53), +1) << "the pinned counterexample moved";
  EXPECT_EQ(monograph_d2(v2, v3, v1, 0x1p-52), 0);  // eps = 2^-52: uncertain (predicates.md)
  const int f = Orient2d::filtered(t);
  EXPECT_TRUE(f == 0 || f == o) << "kernel filter certified " << f;
  EXPECT_EQ(Orient2d::exact(t), o);
  EXPECT_EQ(Orient2d::exact_stage(t), o);
  // All orderings.
  const std::array<P2, 3> v{v1, v2, v3};
  static constexpr int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  for (const auto& pm : perms) {
    const Orient2d::Pts u{v[pm[0]], v[pm[1]], v[pm[2]]};
    const int ou = Orient2d::oracle(u);
    const int fu = Orient2d::filtered(u);
    EXPECT_TRUE(fu == 0 || fu == ou);
    EXPECT_EQ(Orient2d::exact(u), ou);
  }
}

TEST(MonographCounterexamples, Orient3dPrintedBoundWithMachineEpsilonIsUnsound) {
  const P3 v1{35472.868317357534, 3499.4805511462346, 48723.740481790053};
  const P3 v2{23576.189596565688, -17559.419569371272, 76052.766231461836};
  const P3 v3{3207.2992062130597, 44557.537132935824, 18380.254590067627};
  const P3 v4{37046.662608412546, 44015.035394505234, 4960.9910725431764};
  const Orient3d::Pts t{v1, v2, v3, v4};
  const int o = Orient3d::oracle(t);
  ASSERT_EQ(o, -1);  // exact D = -4.80e-4
  EXPECT_EQ(monograph_d3(v1, v2, v3, v4, 0x1p-52), +1) << "the pinned counterexample moved";
  const int f = Orient3d::filtered(t);
  EXPECT_TRUE(f == 0 || f == o) << "kernel filter certified " << f;
  EXPECT_EQ(Orient3d::exact(t), o);
  EXPECT_EQ(Orient3d::exact_stage(t), o);
}

// ------------------------------------------------------------------------------------------
// (f) Non-finite input: X throws NonFiniteInput, X_filtered is uncertain, X_sos throws, for
// NaN, +Inf and -Inf in every coordinate position.

template <class T>
void check_non_finite(const typename T::Pts& base) {
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  int positions = 0;
  for (std::size_t i = 0; i < T::N; ++i)
    for (std::size_t k = 0; k < T::Dim; ++k)
      for (double v : bad) {
        auto p = base;
        p[i][k] = v;
        ++positions;
        EXPECT_THROW(T::exact(p), pr::NonFiniteInput) << T::name << " point " << i << " axis " << k << " " << v;
        EXPECT_THROW(T::exact_stage(p), pr::NonFiniteInput) << T::name << " point " << i << " axis " << k;
        EXPECT_THROW(T::sos(p), pr::NonFiniteInput) << T::name << " point " << i << " axis " << k;
        EXPECT_EQ(T::filtered(p), 0) << T::name << " point " << i << " axis " << k << " " << v;
      }
  EXPECT_EQ(positions, static_cast<int>(3 * T::N * T::Dim));
}

TEST(NonFiniteInput, Orient2d) { check_non_finite<Orient2d>({{{0, 0}, {1, 0}, {0, 1}}}); }
TEST(NonFiniteInput, Orient3d) {
  check_non_finite<Orient3d>({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
}
TEST(NonFiniteInput, Incircle) { check_non_finite<Incircle>({{{0, 0}, {1, 0}, {0, 1}, {0.25, 0.5}}}); }
TEST(NonFiniteInput, Insphere) {
  check_non_finite<Insphere>({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.5, 0.125}}});
}

// ------------------------------------------------------------------------------------------
// (f) Extreme ranges.

TEST(ExtremeRanges, Overflow1e155Case) {
  const double S = 1e155;
  const P2 A{2 * S, 0}, B{2 * S, 2 * S}, P{S, S};
  // The naive products overflow: dl = +inf, dr = -inf.
  for (const auto& t : {Orient2d::Pts{A, B, P}, Orient2d::Pts{B, P, A}, Orient2d::Pts{P, A, B},
                        Orient2d::Pts{B, A, P}}) {
    const int o = Orient2d::oracle(t);
    ASSERT_NE(o, 0);
    EXPECT_EQ(Orient2d::exact(t), o);
    const int f = Orient2d::filtered(t);
    EXPECT_TRUE(f == 0 || f == o);
    EXPECT_NE(Orient2d::sos(t), 0);
  }
  EXPECT_EQ(Orient2d::exact({A, B, P}), 1);  // A -> B -> P turns left
}

/// A degenerate integer configuration scaled by 2^e for e over the whole exponent range,
/// unperturbed and with every single coordinate moved by +-1 ulp: exact == oracle, the
/// filter never contradicts it.
template <class T>
void check_scaled_family(const typename T::Pts& ints, int max_bits) {
  long cases = 0, zeros = 0;
  for (int e = -1074; e + max_bits + 2 < 1024; e += 37) {
    typename T::Pts base = ints;
    for (auto& p : base)
      for (auto& v : p) v = std::ldexp(v, e);
    std::vector<typename T::Pts> variants{base};
    for (std::size_t i = 0; i < T::N; ++i)
      for (std::size_t k = 0; k < T::Dim; ++k)
        for (int s : {-1, 1}) {
          auto p = base;
          p[i][k] = fz::ulp_steps(p[i][k], s);
          variants.push_back(p);
        }
    for (const auto& p : variants) {
      const int o = T::oracle(p);
      ++cases;
      zeros += o == 0;
      EXPECT_EQ(T::exact(p), o) << T::name << " at scale 2^" << e;
      const int f = T::filtered(p);
      EXPECT_TRUE(f == 0 || f == o) << T::name << " filter at scale 2^" << e;
    }
    EXPECT_EQ(T::oracle(base), 0);
  }
  std::cout << "[extreme ranges " << T::name << "] " << cases << " cases, " << zeros
            << " exact zeros" << std::endl;
}

TEST(ExtremeRanges, Orient2dCollinearOverAllScales) {
  check_scaled_family<Orient2d>({{{3, 7}, {5, 12}, {-7, -18}}}, 5);  // direction (2, 5)
}
TEST(ExtremeRanges, Orient3dCoplanarOverAllScales) {
  // a + s u + t v with a = (1, 2, 3), u = (1, 0, 2), v = (0, 3, 1).
  check_scaled_family<Orient3d>({{{1, 2, 3}, {2, 2, 5}, {1, 5, 4}, {3, 8, 9}}}, 4);
}
TEST(ExtremeRanges, IncircleCocircularOverAllScales) {
  check_scaled_family<Incircle>({{{3, 4}, {-4, 3}, {5, 0}, {0, -5}}}, 3);
}
TEST(ExtremeRanges, InsphereCosphericalOverAllScales) {
  check_scaled_family<Insphere>({{{1, 2, 2}, {-2, 1, 2}, {2, -2, 1}, {0, 0, 3}, {-2, -1, -2}}}, 2);
}

TEST(ExtremeRanges, Near1e300And1eMinus300) {
  for (double s : {1e300, 1e-300, 1e-310, 4.9e-324 * 1024}) {
    // Collinear before rounding: (s, s), (2s, 2s) rounded, and s * 1.5.
    const Orient2d::Pts t{{{s, s}, {3 * s, 3 * s}, {std::nextafter(2 * s, 0.0), 2 * s}}};
    const int o = Orient2d::oracle(t);
    EXPECT_EQ(Orient2d::exact(t), o) << s;
    const int f = Orient2d::filtered(t);
    EXPECT_TRUE(f == 0 || f == o);
    const Orient3d::Pts u{{{s, 0, 0}, {0, s, 0}, {0, 0, s}, {s / 3, s / 3, std::nextafter(s / 3, 0.0)}}};
    const int o3 = Orient3d::oracle(u);
    EXPECT_EQ(Orient3d::exact(u), o3) << s;
    const Incircle::Pts w{{{s, 0}, {0, s}, {-s, 0}, {0, std::nextafter(-s, 0.0)}}};
    EXPECT_EQ(Incircle::exact(w), Incircle::oracle(w)) << s;
    const Insphere::Pts z{{{s, 0, 0}, {0, s, 0}, {0, 0, s}, {-s, 0, 0}, {0, std::nextafter(-s, 0.0), 0}}};
    EXPECT_EQ(Insphere::exact(z), Insphere::oracle(z)) << s;
  }
}

}  // namespace
}  // namespace certimesh::test
