// Adversarial inputs for the predicate kernel, as plain C++ (no RapidCheck, no GMP).
//
// Every recipe is a function template over a *draw source* `D` with two members:
//   std::uint64_t below(std::uint64_t n);   // uniform in [0, n), n >= 1
//   std::uint64_t bits();                   // 64 random bits
// RapidCheck plugs in a source whose draws are shrinkable `*gen::inRange` picks
// (rc_generators.h); a libFuzzer target plugs in ByteSource (below), which decodes the
// fuzzer's bytes. Both therefore produce the same families of configurations.
//
// Families (the `family` string of a Config names the one that built it):
//   exactly degenerate by construction (all arithmetic exact, checked where not obvious):
//     lattice-line       collinear points a + k*d on an integer lattice, scaled by 2^e
//     dyadic-affine      c = a + k(b - a), k in {+-1/4, +-1/2, +-2, 3, ...}, every op checked exact
//     mirrored           p, -p and 0 / a multiple of p (and q, -q in 3D)
//     duplicate          a repeated point
//     lattice-plane      a + i*u + j*v (orient3d, insphere)
//     pythagorean-circle integer points on one circle from two Pythagorean triples,
//                        translated by an integer centre and scaled by 2^e (incircle)
//     pythagorean-sphere signed permutations of Pythagorean quadruples on one sphere (insphere)
//   near-degenerate:
//     nextafter          an exact configuration with one coordinate moved 1..4 ulps
//     bartels-rounded    pc = pa + c(pb - pa) (and pd = pa + s(pb - pa) + t(pc - pa)) in double
//                        (Bartels, Fisikopoulos, Weiser 2023 / GEOS PR #1184)
//     decimal-line       integer collinear points divided by 1000 ("rounded decimal input")
//     classroom-grid     Kettner et al.: a base triple with the first point moved on the ulp grid
//     rounded-circle     points r(cos t, sin t) + c rounded to double (incircle, insphere)
//   generic:
//     bit-pattern        coordinates from random bit patterns of one class
//     mixed-scale        coordinates mantissa * 2^k, k spread over the whole exponent range
//
// Scales (Binade): unit (|x| ~ 2^-40..2^40), tiny (~2^-1000: products underflow), subnormal,
// huge (just below DBL_MAX), overflow-threshold (the binade where the predicate's products
// overflow: 2^512 for orient2d, 2^341 orient3d, 2^256 incircle, 2^205 insphere, and 1e155),
// mixed (one axis scaled differently from the other: orient only, where it keeps degeneracy).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>

namespace certimesh::fuzz {

enum class Kind : std::uint8_t { exact_degenerate, near_degenerate, generic };
enum class Binade : std::uint8_t { unit, tiny, subnormal, huge, overflow_threshold, mixed };

inline const char* kind_name(Kind k) {
  switch (k) {
    case Kind::exact_degenerate: return "exact-degenerate";
    case Kind::near_degenerate: return "near-degenerate";
    default: return "generic";
  }
}

inline const char* binade_name(Binade b) {
  switch (b) {
    case Binade::unit: return "unit";
    case Binade::tiny: return "tiny";
    case Binade::subnormal: return "subnormal";
    case Binade::huge: return "huge";
    case Binade::overflow_threshold: return "overflow-threshold";
    default: return "mixed";
  }
}

/// N points of dimension Dim, how they were built and at which scale.
template <std::size_t N, std::size_t Dim>
struct Config {
  std::array<std::array<double, Dim>, N> p{};
  Kind kind = Kind::generic;         // what the construction guarantees / aims at
  Binade binade = Binade::unit;
  const char* family = "bit-pattern";
};

/// True when every coordinate is finite (no NaN, no infinity).
template <std::size_t N, std::size_t Dim>
bool all_finite(const std::array<std::array<double, Dim>, N>& p) {
  for (const auto& q : p)
    for (double v : q)
      if (!std::isfinite(v)) return false;
  return true;
}

/// True when no two points are equal (coordinate-wise ==, so -0.0 equals 0.0).
template <std::size_t N, std::size_t Dim>
bool distinct(const std::array<std::array<double, Dim>, N>& p) {
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j)
      if (p[i] == p[j]) return false;
  return true;
}

using Orient2dInput = Config<3, 2>;
using Orient3dInput = Config<4, 3>;
using IncircleInput = Config<4, 2>;
using InsphereInput = Config<5, 3>;

// ------------------------------------------------------------------------------------------
// Exactness helpers (error-free transformations; valid without FMA contraction, which the
// users of this header must not enable: fuzz/ and tests/ build with -ffp-contract=off).

/// True when a + b is computed exactly (and finitely) in double: Knuth's TwoSum error is 0.
inline bool sum_is_exact(double a, double b) {
  const volatile double s = a + b;
  if (!std::isfinite(s)) return false;
  const double bv = s - a;
  const double av = s - bv;
  return (a - av) + (b - bv) == 0.0;
}

/// x * 2^k when that is exact and finite, with `ok` cleared otherwise.
inline double scale2(double x, int k, bool& ok) {
  const double y = std::ldexp(x, k);
  if (!std::isfinite(y) || std::ldexp(y, -k) != x) ok = false;
  return y;
}

/// Moves x by `steps` representable numbers (towards +inf when steps > 0).
inline double ulp_steps(double x, int steps) {
  const double to = steps > 0 ? std::numeric_limits<double>::infinity()
                              : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(steps); ++i) x = std::nextafter(x, to);
  return x;
}

// ------------------------------------------------------------------------------------------
// Draw helpers

template <class D>
std::int64_t draw_int(D& d, std::int64_t lo, std::int64_t hi) {  // uniform in [lo, hi]
  return lo + static_cast<std::int64_t>(d.below(static_cast<std::uint64_t>(hi - lo) + 1u));
}

template <class D>
std::int64_t draw_nonzero(D& d, std::int64_t mag) {  // in [-mag, mag] \ {0}
  const std::int64_t v = draw_int(d, 1, mag);
  return d.below(2) ? v : -v;
}

template <class D>
double draw_sign(D& d) { return d.below(2) ? 1.0 : -1.0; }

/// A double of the given class from random bits (mantissa uniform, exponent in the class).
enum class DoubleClass : std::uint8_t { normal, subnormal, huge, tiny, overflow2, overflow3, anything };

template <class D>
double draw_double(D& d, DoubleClass c) {
  const std::uint64_t mant = d.bits() & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t sign = std::uint64_t{d.below(2)} << 63;
  std::uint64_t biased = 0;
  switch (c) {
    case DoubleClass::normal: biased = static_cast<std::uint64_t>(1023 + draw_int(d, -40, 40)); break;
    case DoubleClass::subnormal: biased = 0; break;
    case DoubleClass::huge: biased = static_cast<std::uint64_t>(2046 - draw_int(d, 0, 24)); break;
    case DoubleClass::tiny: biased = static_cast<std::uint64_t>(draw_int(d, 1, 60)); break;
    case DoubleClass::overflow2: biased = static_cast<std::uint64_t>(1023 + 512 + draw_int(d, -6, 6)); break;
    case DoubleClass::overflow3: biased = static_cast<std::uint64_t>(1023 + 341 + draw_int(d, -6, 6)); break;
    case DoubleClass::anything: return std::bit_cast<double>(d.bits());  // NaN and Inf included
  }
  double v = std::bit_cast<double>(sign | (biased << 52) | mant);
  if (c == DoubleClass::subnormal && v == 0.0) v = std::numeric_limits<double>::denorm_min();
  return v;
}

/// Bit length of |v|.
inline int bit_length(std::int64_t v) {
  return static_cast<int>(std::bit_width(static_cast<std::uint64_t>(v < 0 ? -v : v)));
}

/// The exponent e for integer coordinates of at most `bits` bits so that n * 2^e lands in
/// `binade`. `degree` is the predicate's polynomial degree (2 orient2d, 3 orient3d, 4
/// incircle, 5 insphere): it places the overflow-threshold binade.
template <class D>
int scale_exponent(D& d, Binade binade, int bits, int degree) {
  switch (binade) {
    case Binade::unit: return static_cast<int>(draw_int(d, -40, 10)) - bits / 2;
    case Binade::tiny: return static_cast<int>(draw_int(d, -1010, -960)) - bits;
    case Binade::subnormal: return -1074 + static_cast<int>(draw_int(d, 0, 8));
    case Binade::huge: return 1022 - bits - static_cast<int>(draw_int(d, 0, 6));
    case Binade::overflow_threshold: {
      // 1e155 ~ 2^515 for orient2d as an extra target (the case of predicates.md section 4).
      const int top = (degree == 2 && d.below(2)) ? 515 : 1024 / degree;
      return top + static_cast<int>(draw_int(d, -3, 3)) - bits;
    }
    case Binade::mixed: return static_cast<int>(draw_int(d, -60, 60)) - bits / 2;
  }
  return 0;
}

template <class D>
Binade draw_binade(D& d, bool allow_mixed) {
  // unit 35 %, tiny 10 %, subnormal 15 %, huge 15 %, overflow threshold 20 %, mixed 5 %
  const std::uint64_t r = d.below(100);
  if (r < 35) return Binade::unit;
  if (r < 45) return Binade::tiny;
  if (r < 60) return Binade::subnormal;
  if (r < 75) return Binade::huge;
  if (r < 95 || !allow_mixed) return Binade::overflow_threshold;
  return Binade::mixed;
}

/// Integer points -> doubles n * 2^e (exact: |n| < 2^53, e >= -1074, below overflow).
/// With Binade::mixed the axes get different exponents (a linear map: keeps collinearity and
/// coplanarity, so use it only for orient families).
template <class D, std::size_t N, std::size_t Dim>
Config<N, Dim> from_integers(D& d, const std::array<std::array<std::int64_t, Dim>, N>& q,
                             Binade binade, int degree, const char* family) {
  int bits = 1;
  for (const auto& pt : q)
    for (std::int64_t v : pt) bits = std::max(bits, bit_length(v));
  Config<N, Dim> c;
  c.kind = Kind::exact_degenerate;
  c.binade = binade;
  c.family = family;
  std::array<int, Dim> e{};
  e[0] = scale_exponent(d, binade, bits, degree);
  for (std::size_t k = 1; k < Dim; ++k)
    e[k] = binade == Binade::mixed ? scale_exponent(d, binade, bits, degree) : e[0];
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t k = 0; k < Dim; ++k)
      c.p[i][k] = std::ldexp(static_cast<double>(q[i][k]), e[k]);
  return c;
}

template <class D, std::size_t N, std::size_t Dim>
void shuffle_points(D& d, Config<N, Dim>& c) {
  for (std::size_t i = N - 1; i > 0; --i) std::swap(c.p[i], c.p[d.below(i + 1)]);
}

// ------------------------------------------------------------------------------------------
// Exactly degenerate families

/// N collinear lattice points a + k_i d (|a| < 2^30, |d| < 2^10, |k| <= 2^10), Dim = 2 or 3.
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> lattice_line(D& d, int degree, bool allow_mixed) {
  std::array<std::int64_t, Dim> a{}, dir{};
  for (std::size_t k = 0; k < Dim; ++k) {
    a[k] = draw_int(d, -(std::int64_t{1} << 30), std::int64_t{1} << 30);
    dir[k] = draw_int(d, -1024, 1024);
  }
  if (std::all_of(dir.begin(), dir.end(), [](std::int64_t v) { return v == 0; })) dir[0] = 1;
  std::array<std::array<std::int64_t, Dim>, N> q{};
  for (std::size_t i = 0; i < N; ++i) {
    const std::int64_t t = draw_int(d, -1024, 1024);
    for (std::size_t k = 0; k < Dim; ++k) q[i][k] = a[k] + t * dir[k];
  }
  return from_integers(d, q, draw_binade(d, allow_mixed), degree, "lattice-line");
}

/// N coplanar lattice points a + i u + j v in 3D.
template <std::size_t N, class D>
Config<N, 3> lattice_plane(D& d, int degree) {
  std::array<std::int64_t, 3> a{}, u{}, v{};
  for (std::size_t k = 0; k < 3; ++k) {
    a[k] = draw_int(d, -(std::int64_t{1} << 28), std::int64_t{1} << 28);
    u[k] = draw_int(d, -256, 256);
    v[k] = draw_int(d, -256, 256);
  }
  std::array<std::array<std::int64_t, 3>, N> q{};
  for (std::size_t i = 0; i < N; ++i) {
    const std::int64_t s = draw_int(d, -512, 512), t = draw_int(d, -512, 512);
    for (std::size_t k = 0; k < 3; ++k) q[i][k] = a[k] + s * u[k] + t * v[k];
  }
  return from_integers(d, q, draw_binade(d, degree <= 3), degree, "lattice-plane");
}

template <std::size_t Dim, class D>
std::array<double, Dim> draw_point(D& d, DoubleClass c) {
  std::array<double, Dim> p{};
  for (auto& v : p) v = draw_double(d, c);
  return p;
}

template <class D>
DoubleClass draw_class(D& d) {
  switch (d.below(6)) {
    case 0: return DoubleClass::subnormal;
    case 1: return DoubleClass::huge;
    case 2: return DoubleClass::tiny;
    case 3: return DoubleClass::overflow2;
    default: return DoubleClass::normal;
  }
}

inline Binade binade_of(DoubleClass c) {
  switch (c) {
    case DoubleClass::subnormal: return Binade::subnormal;
    case DoubleClass::huge: return Binade::huge;
    case DoubleClass::tiny: return Binade::tiny;
    case DoubleClass::overflow2: case DoubleClass::overflow3: return Binade::overflow_threshold;
    default: return Binade::unit;
  }
}

/// Three collinear points a, b, a + k(b - a) with a dyadic k, every operation checked exact;
/// falls back to lattice_line when some operation would round.
template <std::size_t Dim, class D>
Config<3, Dim> dyadic_affine(D& d, int degree) {
  const DoubleClass cls = draw_class(d);
  const auto a = draw_point<Dim>(d, cls);
  auto b = a;
  // b close to a so that b - a is exact (Sterbenz) in most cases: b = a * (1 + small).
  for (std::size_t k = 0; k < Dim; ++k)
    b[k] = d.below(4) == 0 ? draw_double(d, cls) : a[k] * (1.0 + std::ldexp(static_cast<double>(draw_int(d, -64, 64)), -static_cast<int>(draw_int(d, 1, 30))));
  // Powers of two (and -1): kk * diff is exact unless it over- or underflows, which the
  // division back detects.
  static constexpr double ks[] = {0.5, -0.5, 0.25, -0.25, 2.0, -1.0, -2.0, 4.0, 0.125};
  const double kk = ks[d.below(std::size(ks))];
  Config<3, Dim> c;
  c.p[0] = a;
  c.p[1] = b;
  bool ok = true;
  for (std::size_t k = 0; k < Dim && ok; ++k) {
    if (!sum_is_exact(b[k], -a[k])) { ok = false; break; }
    const double diff = b[k] - a[k];
    const double step = kk * diff;
    if (!std::isfinite(step) || step / kk != diff) { ok = false; break; }
    if (!sum_is_exact(a[k], step)) { ok = false; break; }
    c.p[2][k] = a[k] + step;
  }
  if (!ok) return lattice_line<3, Dim>(d, degree, degree <= 3);
  c.kind = Kind::exact_degenerate;
  c.binade = binade_of(cls);
  c.family = "dyadic-affine";
  shuffle_points(d, c);
  return c;
}

/// Points p, -p, q, -q, ... and 0 or 2p: always on a line (2D, N = 3) or a plane through 0
/// (3D, N <= 5: p, -p, q, -q, 0).
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> mirrored(D& d) {
  const DoubleClass cls = draw_class(d);
  Config<N, Dim> c;
  const auto p = draw_point<Dim>(d, cls);
  const auto q = draw_point<Dim>(d, cls);
  std::array<std::array<double, Dim>, 5> pool{};
  for (std::size_t k = 0; k < Dim; ++k) {
    pool[0][k] = p[k];
    pool[1][k] = -p[k];
    pool[2][k] = q[k];
    pool[3][k] = -q[k];
    pool[4][k] = 0.0;
  }
  if (Dim == 2 || N == 3) {
    // On one line: p, -p, 0 and p/2 (p itself again when p/2 would round).
    bool ok = true;
    std::array<double, Dim> h{};
    for (std::size_t k = 0; k < Dim; ++k) h[k] = scale2(p[k], -1, ok);
    pool[2] = std::array<double, Dim>{};
    pool[3] = ok ? h : p;
    if (N == 3 && d.below(2)) std::swap(pool[2], pool[3]);
  }
  for (std::size_t i = 0; i < N; ++i) c.p[i] = pool[i];
  c.kind = Kind::exact_degenerate;
  c.binade = binade_of(cls);
  c.family = "mirrored";
  shuffle_points(d, c);
  return c;
}

/// A configuration with one point repeated (any predicate is zero).
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> duplicate(D& d) {
  const DoubleClass cls = draw_class(d);
  Config<N, Dim> c;
  for (auto& pt : c.p) pt = draw_point<Dim>(d, cls);
  const std::size_t i = d.below(N), j = (i + 1 + d.below(N - 1)) % N;
  c.p[j] = c.p[i];
  c.kind = Kind::exact_degenerate;
  c.binade = binade_of(cls);
  c.family = "duplicate";
  return c;
}

/// A Pythagorean triple (m^2 - n^2, 2mn, m^2 + n^2) with 1 <= n < m <= 64.
template <class D>
std::array<std::int64_t, 3> pythagorean_triple(D& d) {
  const std::int64_t m = draw_int(d, 2, 64), n = draw_int(d, 1, m - 1);
  return {m * m - n * n, 2 * m * n, m * m + n * n};
}

/// Four integer points on one circle: the circle of radius R = r1 * r2 carries the
/// scaled triples (a1 r2, b1 r2), (a2 r1, b2 r1) with every sign and swap, and (+-R, 0),
/// (0, +-R). Translated by an integer centre, scaled by 2^e.
template <class D>
IncircleInput pythagorean_circle(D& d) {
  const auto t1 = pythagorean_triple(d), t2 = pythagorean_triple(d);
  const std::int64_t R = t1[2] * t2[2];
  std::array<std::array<std::int64_t, 2>, 20> pool{};
  std::size_t n = 0;
  for (const auto& [x, y] : {std::pair{t1[0] * t2[2], t1[1] * t2[2]}, std::pair{t2[0] * t1[2], t2[1] * t1[2]}})
    for (int s = 0; s < 8; ++s) {
      std::int64_t u = (s & 4) ? y : x, v = (s & 4) ? x : y;
      if (s & 1) u = -u;
      if (s & 2) v = -v;
      pool[n++] = {u, v};
    }
  pool[n++] = {R, 0};
  pool[n++] = {-R, 0};
  pool[n++] = {0, R};
  pool[n++] = {0, -R};
  const std::int64_t cx = draw_int(d, -(std::int64_t{1} << 26), std::int64_t{1} << 26);
  const std::int64_t cy = draw_int(d, -(std::int64_t{1} << 26), std::int64_t{1} << 26);
  // Four distinct pool entries (a partial Fisher-Yates shuffle).
  std::array<std::array<std::int64_t, 2>, 4> q{};
  for (std::size_t i = 0; i < 4; ++i) {
    std::swap(pool[i], pool[i + d.below(n - i)]);
    q[i] = {pool[i][0] + cx, pool[i][1] + cy};
  }
  return from_integers(d, q, draw_binade(d, false), 4, "pythagorean-circle");
}

/// A Pythagorean quadruple (a, b, c) with a^2 + b^2 + c^2 = r^2 (Euler's parametrisation
/// from m, n, p, q in [0, 8]); r > 0.
template <class D>
std::array<std::int64_t, 4> pythagorean_quadruple(D& d) {
  std::int64_t m = draw_int(d, 0, 8);
  const std::int64_t n = draw_int(d, 0, 8), p = draw_int(d, 0, 8), q = draw_int(d, 0, 8);
  if (m == 0 && n == 0 && p == 0 && q == 0) m = 1;  // r > 0 without a retry loop
  const std::int64_t r = m * m + n * n + p * p + q * q;
  return {m * m + n * n - p * p - q * q, 2 * (m * q + n * p), 2 * (n * q - m * p), r};
}

/// Five integer points on one sphere: signed permutations of two quadruples scaled to the
/// common radius r1 r2, translated by an integer centre and scaled by 2^e.
template <class D>
InsphereInput pythagorean_sphere(D& d) {
  const auto a = pythagorean_quadruple(d), b = pythagorean_quadruple(d);
  const std::array<std::array<std::int64_t, 3>, 2> base{{{a[0] * b[3], a[1] * b[3], a[2] * b[3]},
                                                          {b[0] * a[3], b[1] * a[3], b[2] * a[3]}}};
  static constexpr int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  std::array<std::int64_t, 3> centre{};
  for (auto& v : centre) v = draw_int(d, -(std::int64_t{1} << 24), std::int64_t{1} << 24);
  std::array<std::array<std::int64_t, 3>, 5> q{};
  for (std::size_t i = 0; i < 5; ++i) {
    auto& pt = q[i];
    const auto& s = base[d.below(2)];
    const int* pm = perms[d.below(6)];
    const std::uint64_t signs = d.below(8);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t v = s[static_cast<std::size_t>(pm[k])];
      pt[k] = ((signs >> k) & 1u ? -v : v) + centre[k];
    }
    // Redraw (a few times) a point that repeats an earlier one.
    for (std::size_t j = 0; j < i; ++j)
      if (q[j] == pt && d.below(8) != 0) {
        --i;
        break;
      }
  }
  return from_integers(d, q, draw_binade(d, false), 5, "pythagorean-sphere");
}

// ------------------------------------------------------------------------------------------
// Near-degenerate families

/// Moves one coordinate of an exact configuration by 1..4 ulps (twice with probability 1/4).
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> nextafter_perturbation(const Config<N, Dim>& base, D& d) {
  Config<N, Dim> c = base;
  const std::size_t moves = d.below(4) == 0 ? 2 : 1;
  for (std::size_t m = 0; m < moves; ++m) {
    const std::size_t i = d.below(N), k = d.below(Dim);
    const int steps = static_cast<int>(draw_nonzero(d, 4));
    const double moved = ulp_steps(c.p[i][k], steps);
    if (std::isfinite(moved)) c.p[i][k] = moved;
  }
  c.kind = Kind::near_degenerate;
  c.family = "nextafter";
  return c;
}

template <class D>
double draw_unit_interval(D& d) {  // a double in [-1, 1] with a full random mantissa
  return draw_sign(d) * std::ldexp(static_cast<double>(d.bits() >> 11), -53 - static_cast<int>(d.below(4)));
}

/// Bartels et al.: pc = pa + c(pb - pa) with pa, pb in [-1, 1]^Dim, c in [0, 1], all in
/// double, optionally scaled by a power of two (exact). N = 3 in 2D: collinear; N = 4 in 3D:
/// pd = pa + s(pb - pa) + t(pc - pa), coplanar. Extra points (incircle/insphere) are random.
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> bartels_rounded(D& d) {
  Config<N, Dim> c;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t k = 0; k < Dim; ++k) c.p[i][k] = draw_unit_interval(d);
  const std::size_t target = Dim;  // the point made (nearly) dependent on the first Dim
  const double s = std::fabs(draw_unit_interval(d)), t = std::fabs(draw_unit_interval(d));
  for (std::size_t k = 0; k < Dim; ++k) {
    double v = c.p[0][k] + s * (c.p[1][k] - c.p[0][k]);
    if (Dim == 3) v = v + t * (c.p[2][k] - c.p[0][k]);
    c.p[target][k] = v;
  }
  const int e = d.below(3) == 0 ? static_cast<int>(draw_int(d, -1000, 1000)) : 0;
  bool ok = true;
  Config<N, Dim> scaled = c;
  for (auto& pt : scaled.p)
    for (auto& v : pt) v = scale2(v, e, ok);
  if (ok) c = scaled;
  c.binade = e < -900 ? Binade::tiny : (e > 900 ? Binade::huge : Binade::unit);
  c.kind = Kind::near_degenerate;
  c.family = "bartels-rounded";
  shuffle_points(d, c);
  return c;
}

/// Collinear (coplanar) integer points in [-1000, 1000] divided by 1000: exact in decimal,
/// rounded in binary.
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> decimal_line(D& d) {
  Config<N, Dim> c;
  std::array<std::int64_t, Dim> a{}, u{}, v{};
  for (std::size_t k = 0; k < Dim; ++k) {
    a[k] = draw_int(d, -200, 200);
    u[k] = draw_int(d, -40, 40);
    v[k] = draw_int(d, -40, 40);
  }
  for (std::size_t i = 0; i < N; ++i) {
    const std::int64_t s = draw_int(d, -20, 20), t = Dim == 3 ? draw_int(d, -20, 20) : 0;
    for (std::size_t k = 0; k < Dim; ++k)
      c.p[i][k] = static_cast<double>(a[k] + s * u[k] + t * v[k]) / 1000.0;
  }
  c.kind = Kind::near_degenerate;
  c.binade = Binade::unit;
  c.family = "decimal-line";
  return c;
}

/// Kettner et al.: one of the three classroom base triples with the first point moved by
/// (x, y) ulps, x, y in [0, 255].
template <std::size_t N, class D>
Config<N, 2> classroom_grid(D& d) {
  static constexpr double bases[3][3][2] = {
      {{0.5, 0.5}, {12.0, 12.0}, {24.0, 24.0}},
      {{0.50000000000002531, 0.5000000000000171}, {17.300000000000001, 17.300000000000001},
       {24.00000000000005, 24.0000000000000517765}},
      {{0.5, 0.5}, {8.8000000000000007, 8.8000000000000007}, {12.1, 12.1}}};
  const auto& b = bases[d.below(3)];
  Config<N, 2> c;
  for (std::size_t i = 0; i < N; ++i) c.p[i] = {b[i % 3][0], b[i % 3][1]};
  c.p[0][0] = ulp_steps(c.p[0][0], static_cast<int>(d.below(256)));
  c.p[0][1] = ulp_steps(c.p[0][1], static_cast<int>(d.below(256)));
  if (N > 3) c.p[3] = {c.p[3][0] + 1.0, c.p[3][1] - 1.0};
  c.kind = Kind::near_degenerate;
  c.binade = Binade::unit;
  c.family = "classroom-grid";
  shuffle_points(d, c);
  return c;
}

/// Points c + r(cos t, sin t) (resp. on a sphere) rounded to double: near-cocircular.
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> rounded_sphere(D& d) {
  Config<N, Dim> c;
  std::array<double, Dim> centre{};
  for (auto& v : centre) v = draw_unit_interval(d) * 100.0;
  const double r = 1.0 + std::fabs(draw_unit_interval(d)) * 50.0;
  for (std::size_t i = 0; i < N; ++i) {
    const double t = std::ldexp(static_cast<double>(d.bits() >> 11), -53) * 6.283185307179586;
    const double z = draw_unit_interval(d);
    const double rho = Dim == 3 ? std::sqrt(1.0 - z * z) : 1.0;
    c.p[i][0] = centre[0] + r * rho * std::cos(t);
    c.p[i][1] = centre[1] + r * rho * std::sin(t);
    if constexpr (Dim == 3) c.p[i][2] = centre[2] + r * z;
  }
  c.kind = Kind::near_degenerate;
  c.binade = Binade::unit;
  c.family = "rounded-circle";
  return c;
}

// ------------------------------------------------------------------------------------------
// Generic families

template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> bit_pattern(D& d) {
  const DoubleClass cls = draw_class(d);
  Config<N, Dim> c;
  for (auto& pt : c.p) pt = draw_point<Dim>(d, cls);
  c.kind = Kind::generic;
  c.binade = binade_of(cls);
  c.family = "bit-pattern";
  return c;
}

/// Coordinates mantissa * 2^k with k uniform in [-span, span] (clamped to the double range);
/// span = 1074 covers every binade, subnormals included.
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> mixed_scale(D& d, int span) {
  Config<N, Dim> c;
  for (auto& pt : c.p)
    for (auto& v : pt)
      v = draw_sign(d) * std::ldexp(1.0 + std::ldexp(static_cast<double>(d.bits() >> 12), -52),
                                    static_cast<int>(draw_int(d, -std::min(span, 1074), std::min(span, 1023))));
  c.kind = Kind::generic;
  c.binade = Binade::mixed;
  c.family = "mixed-scale";
  return c;
}

// ------------------------------------------------------------------------------------------
// Per-predicate exact families (the bases that the near families perturb)

template <class D>
Orient2dInput exact_orient2d(D& d) {
  switch (d.below(5)) {
    case 0: case 1: return lattice_line<3, 2>(d, 2, true);
    case 2: return dyadic_affine<2>(d, 2);
    case 3: return mirrored<3, 2>(d);
    default: return d.below(2) ? duplicate<3, 2>(d) : lattice_line<3, 2>(d, 2, true);
  }
}

template <class D>
Orient3dInput exact_orient3d(D& d) {
  switch (d.below(6)) {
    case 0: case 1: case 2: return lattice_plane<4>(d, 3);
    case 3: return lattice_line<4, 3>(d, 3, true);  // collinear, hence coplanar
    case 4: return mirrored<4, 3>(d);
    default: return duplicate<4, 3>(d);
  }
}

template <class D>
IncircleInput exact_incircle(D& d) {
  switch (d.below(6)) {
    case 0: case 1: case 2: case 3: return pythagorean_circle(d);
    case 4: return lattice_line<4, 2>(d, 4, false);
    default: return d.below(2) ? duplicate<4, 2>(d) : mirrored<4, 2>(d);
  }
}

template <class D>
InsphereInput exact_insphere(D& d) {
  switch (d.below(6)) {
    case 0: case 1: case 2: case 3: return pythagorean_sphere(d);
    case 4: return lattice_plane<5>(d, 5);
    default: return d.below(2) ? duplicate<5, 3>(d) : mirrored<5, 3>(d);
  }
}

// The near families other than `nextafter` (which perturbs an exact base; rc_generators.h
// builds that one with gen::mapcat so that shrinking keeps the base degenerate).
template <class D>
Orient2dInput rounded_orient2d(D& d) {
  switch (d.below(3)) {
    case 0: return bartels_rounded<3, 2>(d);
    case 1: return decimal_line<3, 2>(d);
    default: return classroom_grid<3>(d);
  }
}
template <class D>
Orient3dInput rounded_orient3d(D& d) {
  return d.below(2) ? bartels_rounded<4, 3>(d) : decimal_line<4, 3>(d);
}
template <class D>
IncircleInput rounded_incircle(D& d) {
  return d.below(3) ? rounded_sphere<4, 2>(d) : classroom_grid<4>(d);
}
template <class D>
InsphereInput rounded_insphere(D& d) { return rounded_sphere<5, 3>(d); }

template <class D> Orient2dInput near_orient2d(D& d) {
  return d.below(2) ? nextafter_perturbation(exact_orient2d(d), d) : rounded_orient2d(d);
}
template <class D> Orient3dInput near_orient3d(D& d) {
  return d.below(2) ? nextafter_perturbation(exact_orient3d(d), d) : rounded_orient3d(d);
}
template <class D> IncircleInput near_incircle(D& d) {
  return d.below(2) ? nextafter_perturbation(exact_incircle(d), d) : rounded_incircle(d);
}
template <class D> InsphereInput near_insphere(D& d) {
  return d.below(2) ? nextafter_perturbation(exact_insphere(d), d) : rounded_insphere(d);
}

/// Bit patterns (2/3) or exponent-mixed scales over the whole range (1/3).
template <std::size_t N, std::size_t Dim, class D>
Config<N, Dim> generic_config(D& d) {
  if (d.below(3) != 0) return bit_pattern<N, Dim>(d);
  return mixed_scale<N, Dim>(d, 1074);
}

/// The full mixture for one predicate: 40 % exact, 40 % near, 20 % generic.
template <class D> Orient2dInput any_orient2d(D& d) {
  const auto r = d.below(10);
  return r < 4 ? exact_orient2d(d) : r < 8 ? near_orient2d(d) : generic_config<3, 2>(d);
}
template <class D> Orient3dInput any_orient3d(D& d) {
  const auto r = d.below(10);
  return r < 4 ? exact_orient3d(d) : r < 8 ? near_orient3d(d) : generic_config<4, 3>(d);
}
template <class D> IncircleInput any_incircle(D& d) {
  const auto r = d.below(10);
  return r < 4 ? exact_incircle(d) : r < 8 ? near_incircle(d) : generic_config<4, 2>(d);
}
template <class D> InsphereInput any_insphere(D& d) {
  const auto r = d.below(10);
  return r < 4 ? exact_insphere(d) : r < 8 ? near_insphere(d) : generic_config<5, 3>(d);
}

// ------------------------------------------------------------------------------------------
// Plain decoder for libFuzzer: bytes -> draws. Exhausted input reads as zeros, so every
// byte string decodes to a valid configuration and short inputs give simple ones.

class ByteSource {
 public:
  ByteSource(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint64_t bits() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | next_byte();
    return v;
  }

  std::uint64_t below(std::uint64_t n) {
    if (n <= 1) return 0;
    // Fewest bytes that cover n: keeps the fuzzer's byte-level mutations local.
    std::uint64_t v = 0;
    for (std::uint64_t range = 1; range < n && range != 0; range <<= 8) v = (v << 8) | next_byte();
    return v % n;
  }

  bool exhausted() const { return pos_ >= size_; }

 private:
  std::uint64_t next_byte() { return pos_ < size_ ? data_[pos_++] : 0u; }
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

/// Which predicate a fuzz input exercises, and its points.
struct DecodedInput {
  int predicate = 0;  // 0 orient2d, 1 orient3d, 2 incircle, 3 insphere
  Orient2dInput o2;
  Orient3dInput o3;
  IncircleInput ic;
  InsphereInput is;
  bool raw_non_finite = false;  // one coordinate replaced by NaN, +-Inf or raw bits
};

inline DecodedInput decode(const std::uint8_t* data, std::size_t size) {
  ByteSource src(data, size);
  DecodedInput in;
  in.predicate = static_cast<int>(src.below(4));
  switch (in.predicate) {
    case 0: in.o2 = any_orient2d(src); break;
    case 1: in.o3 = any_orient3d(src); break;
    case 2: in.ic = any_incircle(src); break;
    default: in.is = any_insphere(src); break;
  }
  // 1 in 32: overwrite one coordinate with NaN, +Inf, -Inf or a raw bit pattern. (31, not
  // 0, so that exhausted input -- all zeros -- leaves the configuration alone.)
  if (src.below(32) == 31) {
    in.raw_non_finite = true;
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double special[] = {std::numeric_limits<double>::quiet_NaN(), inf, -inf,
                              draw_double(src, DoubleClass::anything)};
    const double v = special[src.below(4)];
    const std::size_t i = src.below(5), k = src.below(3);
    switch (in.predicate) {
      case 0: in.o2.p[i % 3][k % 2] = v; break;
      case 1: in.o3.p[i % 4][k] = v; break;
      case 2: in.ic.p[i % 4][k % 2] = v; break;
      default: in.is.p[i][k] = v; break;
    }
  }
  return in;
}

}  // namespace certimesh::fuzz
