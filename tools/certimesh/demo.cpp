// `certimesh demo`: the classroom failures of naive floating-point geometry, side by side with
// certimesh's exact answers, each certimesh answer re-checked by an independent exact
// evaluation with GMP rationals (mpq_class holds every double exactly).
//
// Sources: Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems
// in geometric computations", CGTA 40(1), 2008; and the counterexamples to the monograph's
// printed filter bounds (docs: design notes, predicates.md sections 0 and 5).
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "cli.h"

namespace certimesh::cli {
namespace {

namespace cp = certimesh::predicates;

int sign_of(double v) { return (v > 0) - (v < 0); }

constexpr const char* kSignName[3] = {"-1", "0", "+1"};

// The textbook formula everyone writes first: orientation of (p, q, r).
int naive_orient2d(const cp::Point2& p, const cp::Point2& q, const cp::Point2& r) {
  return sign_of((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
}

// Independent exact check: the same determinant in GMP rationals.
int gmp_orient2d(const cp::Point2& p, const cp::Point2& q, const cp::Point2& r) {
  const mpq_class px(p.x), py(p.y), qx(q.x), qy(q.y), rx(r.x), ry(r.y);
  const mpq_class d = (qx - px) * (ry - py) - (qy - py) * (rx - px);
  return sgn(d);
}

int gmp_orient3d(const cp::Point3& a, const cp::Point3& b, const cp::Point3& c, const cp::Point3& d) {
  const mpq_class m[3][3] = {{mpq_class(a.x) - d.x, mpq_class(a.y) - d.y, mpq_class(a.z) - d.z},
                             {mpq_class(b.x) - d.x, mpq_class(b.y) - d.y, mpq_class(b.z) - d.z},
                             {mpq_class(c.x) - d.x, mpq_class(c.y) - d.y, mpq_class(c.z) - d.z}};
  const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

struct Tally {
  int checks = 0;
  int certimesh_wrong = 0;  // certimesh disagrees with the GMP evaluation: must stay 0
};

// Kettner et al.'s orientation grid: p + (i, j) ulp steps, 256 x 256, against fixed q, r.
void grid(const char* label, cp::Point2 p, cp::Point2 q, cp::Point2 r, Tally& tally) {
  const double ux = std::nextafter(p.x, 1e300) - p.x;
  const double uy = std::nextafter(p.y, 1e300) - p.y;
  int naive_wrong = 0, naive_zero = 0, exact_zero = 0, filter_uncertain = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const cp::Point2 pij{p.x + i * ux, p.y + j * uy};
      // certimesh orient2d(a, b, c) is the orientation of the triangle a, b, c.
      const int exact = cp::to_int(cp::orient2d(pij, q, r));
      const int naive = naive_orient2d(pij, q, r);
      const int gmp = gmp_orient2d(pij, q, r);
      ++tally.checks;
      if (exact != gmp) ++tally.certimesh_wrong;
      if (naive != exact) ++naive_wrong;
      if (naive == 0) ++naive_zero;
      if (exact == 0) ++exact_zero;
      if (!cp::is_certain(cp::orient2d_filtered(pij, q, r))) ++filter_uncertain;
    }
  }
  std::printf("  grid %s: naive double wrong on %5d of 65536 (%4.1f %%), naive zero on %5d;\n"
              "          certimesh: exact zero on %d (the truly collinear points), "
              "filter escalated %d, wrong 0 of 65536 vs GMP\n",
              label, naive_wrong, 100.0 * naive_wrong / 65536.0, naive_zero, exact_zero,
              filter_uncertain);
}

// Every orientation triple of a point set: naive sign against the exact one.
void hull_set(const char* label, const char* effect, const std::vector<cp::Point2>& pts, Tally& tally) {
  int triples = 0, naive_wrong = 0;
  std::string examples;
  const int n = static_cast<int>(pts.size());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        if (i == j || j == k || i == k) continue;
        const auto& a = pts[static_cast<std::size_t>(i)];
        const auto& b = pts[static_cast<std::size_t>(j)];
        const auto& c = pts[static_cast<std::size_t>(k)];
        const int exact = cp::to_int(cp::orient2d(a, b, c));
        ++tally.checks;
        if (exact != gmp_orient2d(a, b, c)) ++tally.certimesh_wrong;
        ++triples;
        const int naive = naive_orient2d(a, b, c);
        if (naive != exact) {
          ++naive_wrong;
          if (naive_wrong <= 3) {
            char buf[96];
            std::snprintf(buf, sizeof buf, " orient(p%d,p%d,p%d): naive %s, exact %s;", i + 1, j + 1,
                          k + 1, kSignName[naive + 1], kSignName[exact + 1]);
            examples += buf;
          }
        }
      }
    }
  }
  std::printf("  %-9s %s\n            naive wrong on %d of %d ordered triples:%s%s\n", label, effect,
              naive_wrong, triples, examples.c_str(), naive_wrong > 3 ? " ..." : "");
}

}  // namespace

int run_demo() {
  Tally tally;
  std::printf("certimesh demo: naive double arithmetic against certimesh's exact predicates\n"
              "(every certimesh answer below is re-checked by an independent GMP rational "
              "evaluation)\n\n");

  std::printf("1. Kettner et al. orientation grids (CGTA 2008): p + (i, j) ulps, i, j < 256\n");
  grid("(a)", {0.5, 0.5}, {12, 12}, {24, 24}, tally);
  grid("(b)", {0.50000000000002531, 0.5000000000000171}, {17.300000000000001, 17.300000000000001},
       {24.00000000000005, 24.0000000000000517765}, tally);
  grid("(c)", {0.5, 0.5}, {8.8000000000000007, 8.8000000000000007}, {12.1, 12.1}, tally);

  std::printf("\n2. Convex-hull failure sets (same paper): what naive orientation gets wrong\n");
  hull_set("A1", "an outside point that sees no edge",
           {{7.3000000000000194, 7.3000000000000167}, {24.000000000000068, 24.000000000000071},
            {24.00000000000005, 24.000000000000053}, {0.50000000000001621, 0.50000000000001243},
            {8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}},
           tally);
  hull_set("A1 global", "the same failure with a far-away point",
           {{0.1, 0.1}, {0.2, 0.20000000000000004}, {0.79999999999999993, 0.80000000000000004},
            {1.267650600228229e30, 1.2676506002282291e30}},
           tally);
  hull_set("A2", "an inside point that sees an edge",
           {{27.643564356435643, -21.881188118811881}, {83.366336633663366, 15.544554455445542},
            {4, 4}, {73.415841584158414, 8.8613861386138595}},
           tally);
  hull_set("B1", "a point that sees all edges",
           {{200, 49.200000000000003}, {100, 49.600000000000001},
            {-233.33333333333334, 50.93333333333333}, {166.66666666666669, 49.333333333333336}},
           tally);
  hull_set("B2", "a non-contiguous visible set",
           {{0.50000000000001243, 0.50000000000000189}, {0.50000000000001243, 0.50000000000000333},
            {24.00000000000005, 24.000000000000053}, {24.000000000000068, 24.000000000000071},
            {17.300000000000001, 17.300000000000001}},
           tally);

  std::printf("\n3. The monograph's printed filter bounds certify wrong signs\n");
  {
    // 2D: d() with r = eps (|a|+|b|+|c|+|d| + 2|ad| + 2|bc|), eps = 2^-53, rows v2-v1, v3-v1.
    const cp::Point2 v1{182.77170981294643, 403.68866801506164};
    const cp::Point2 v2{771.92835113580475, 974.08982576763151};
    const cp::Point2 v3{773.53783630239855, 975.64807384296398};
    const double a = v2.x - v1.x, b = v2.y - v1.y, c = v3.x - v1.x, d = v3.y - v1.y;
    const double det = a * d - b * c;
    const double eps = std::ldexp(1.0, -53);
    const double r = eps * (std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d) +
                            2 * std::fabs(a * d) + 2 * std::fabs(b * c));
    const int printed = std::fabs(det) > r ? sign_of(det) : 0;
    const int exact = cp::to_int(cp::orient2d(v1, v2, v3));
    const cp::FilteredSign filtered = cp::orient2d_filtered(v1, v2, v3);
    ++tally.checks;
    if (exact != gmp_orient2d(v1, v2, v3)) ++tally.certimesh_wrong;
    std::printf("  2D, eps = 2^-53: float D = %.4g, printed bound r = %.4g, so d() certifies %+d;\n"
                "      exact sign %+d; certimesh's proven filter says %s\n",
                det, r, printed, exact,
                cp::is_certain(filtered) ? (cp::to_int(filtered) > 0 ? "+1" : "-1") : "uncertain (escalates)");
  }
  {
    // 3D: r = eps (sum |entries| + sum |6 triple products|), eps = 2^-52, rows vi - v4,
    // D summed as aei - ceg + bfg - afh + cdh - bdi.
    const cp::Point3 v1{35472.868317357534, 3499.4805511462346, 48723.740481790053};
    const cp::Point3 v2{23576.189596565688, -17559.419569371272, 76052.766231461836};
    const cp::Point3 v3{3207.2992062130597, 44557.537132935824, 18380.254590067627};
    const cp::Point3 v4{37046.662608412546, 44015.035394505234, 4960.9910725431764};
    const double a = v1.x - v4.x, b = v1.y - v4.y, c = v1.z - v4.z;
    const double d = v2.x - v4.x, e = v2.y - v4.y, f = v2.z - v4.z;
    const double g = v3.x - v4.x, h = v3.y - v4.y, i = v3.z - v4.z;
    const double det = a * e * i - c * e * g + b * f * g - a * f * h + c * d * h - b * d * i;
    const double entries = std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d) + std::fabs(e) +
                           std::fabs(f) + std::fabs(g) + std::fabs(h) + std::fabs(i);
    const double eps = std::ldexp(1.0, -52);
    const double r = eps * (entries + std::fabs(a * e * i) + std::fabs(c * e * g) + std::fabs(b * f * g) +
                            std::fabs(a * f * h) + std::fabs(c * d * h) + std::fabs(b * d * i));
    const int printed = std::fabs(det) > r ? sign_of(det) : 0;
    const int exact = cp::to_int(cp::orient3d(v1, v2, v3, v4));
    const cp::FilteredSign filtered = cp::orient3d_filtered(v1, v2, v3, v4);
    ++tally.checks;
    if (exact != gmp_orient3d(v1, v2, v3, v4)) ++tally.certimesh_wrong;
    std::printf("  3D, eps = 2^-52: float D = %.4g, printed bound r = %.4g, so d() certifies %+d;\n"
                "      exact sign %+d; certimesh's proven filter says %s\n",
                det, r, printed, exact,
                cp::is_certain(filtered) ? (cp::to_int(filtered) > 0 ? "+1" : "-1") : "uncertain (escalates)");
  }

  std::printf("\ncertimesh: %d of %d answers agree with the independent GMP evaluation%s\n",
              tally.checks - tally.certimesh_wrong, tally.checks,
              tally.certimesh_wrong == 0 ? "." : "  <-- DISAGREEMENT");
  return tally.certimesh_wrong == 0 ? 0 : 1;
}

}  // namespace certimesh::cli
