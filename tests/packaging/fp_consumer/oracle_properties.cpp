// The consumer's oracle properties: adversarial near-degenerate orient2d, orient3d,
// incircle and insphere queries through kernel_calls.cpp (compiled with the consumer's
// flags), checked against the suite's GMP rational oracle (fuzz/oracles), which shares no
// code with the kernel. For every query: the exact sign equals the oracle's, and the
// filtered sign is uncertain or equal to it (O2.6, O3.6, IC.6, IS.6).
// usage: fp_oracle_properties [queries per predicate]
#include <rational_oracle.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "kernel_calls.h"

namespace {

using Rng = std::mt19937_64;

template <std::size_t D>
using Pt = std::array<double, D>;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Moves x by about k ulps of x: exactly k steps when |k| is small, the perturbations that
// break a degeneracy by the least; a rounded k * ulp beyond.
double nudge(double x, double k) {
  if (std::fabs(k) > 8) return x + k * (std::nextafter(x, HUGE_VAL) - x);
  for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
  for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

// Sizes from 0 to 2^40 ulps, log-uniform: from exactly degenerate, through the filters'
// threshold (where a contracted filter would err), to plainly certain.
template <std::size_t D>
void nudge_point(Rng& rng, Pt<D>& p) {
  const double size = std::ldexp(1.0, static_cast<int>(rng() % 41)) - 1;
  for (double& x : p) x = nudge(x, std::round(uniform(rng, -size, size)));
}

// N = D + 1 points on a hyperplane (a line in 2D, a plane in 3D): the last one is a rounded
// affine combination of the others, then nudged by a few ulps; the filters' worst case.
// Every fourth query uses small integers and integer weights: exactly degenerate.
template <std::size_t D>
std::array<Pt<D>, D + 1> flat(Rng& rng) {
  std::array<Pt<D>, D + 1> p{};
  const bool integer = rng() % 4 == 0;
  for (std::size_t i = 0; i < D; ++i)
    for (double& x : p[i]) x = integer ? std::floor(uniform(rng, -64, 64)) : uniform(rng, -1, 1);
  p[D] = p[0];
  for (std::size_t j = 1; j < D; ++j) {
    const double t = integer ? std::floor(uniform(rng, -3, 4)) : uniform(rng, -2, 2);
    for (std::size_t k = 0; k < D; ++k) p[D][k] += t * (p[j][k] - p[0][k]);
  }
  if (!integer) nudge_point(rng, p[D]);
  return p;
}

// Integer points on the circle x^2 + y^2 = 25 and the sphere x^2 + y^2 + z^2 = 9.
std::array<Pt<2>, 12> circle_points() {
  return {{{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4},
           {4, 3}, {-4, 3}, {4, -3}, {-4, -3}}};
}
std::array<Pt<3>, 30> sphere_points() {
  std::array<Pt<3>, 30> s{};
  std::size_t n = 0;
  for (std::size_t axis = 0; axis < 3; ++axis)
    for (const double v : {3.0, -3.0}) {
      s[n] = {0, 0, 0};
      s[n++][axis] = v;
    }
  for (std::size_t one = 0; one < 3; ++one)  // (+-1, +-2, +-2) with the 1 on any axis
    for (int signs = 0; signs < 8; ++signs) {
      for (std::size_t k = 0; k < 3; ++k)
        s[n][k] = (k == one ? 1.0 : 2.0) * ((signs >> k) & 1 ? -1.0 : 1.0);
      ++n;
    }
  return s;
}

// N = D + 2 points on a circle or sphere: rounded points of random directions, nudged, or
// (every fourth query) integer points exactly on it, translated by an integer vector.
template <std::size_t D, std::size_t M>
std::array<Pt<D>, D + 2> on_sphere(Rng& rng, const std::array<Pt<D>, M>& exact) {
  std::array<Pt<D>, D + 2> p{};
  const bool integer = rng() % 4 == 0;
  Pt<D> centre{};
  for (double& x : centre) x = integer ? std::floor(uniform(rng, -32, 32)) : uniform(rng, -1, 1);
  const double radius = uniform(rng, 0.25, 2);
  std::normal_distribution<double> gauss;
  for (auto& q : p) {
    const Pt<D>& e = exact[rng() % M];
    Pt<D> u{};
    double norm = 0;
    for (double& x : u) {
      x = gauss(rng);
      norm += x * x;
    }
    for (std::size_t k = 0; k < D; ++k)
      q[k] = integer ? centre[k] + e[k] : centre[k] + radius * u[k] / std::sqrt(norm);
    if (!integer) nudge_point(rng, q);
  }
  return p;
}

// Multiplying by 2^e is exact (no overflow or underflow here) and moves the query across
// the filters' exponent range.
template <std::size_t D, std::size_t N>
void scale(Rng& rng, std::array<Pt<D>, N>& p) {
  const int e = static_cast<int>(rng() % 3) * 30 - 30;
  for (auto& q : p)
    for (double& x : q) x = std::ldexp(x, e);
}

struct Tally {
  const char* name;
  long wrong_exact = 0, wrong_filter = 0, certain = 0, uncertain = 0, zero = 0;

  void record(int oracle, int exact, int filtered) {
    wrong_exact += exact != oracle;
    wrong_filter += filtered != 2 && filtered != oracle;
    (filtered == 2 ? uncertain : certain) += 1;
    zero += oracle == 0;
  }
  // Both filter outcomes and exact zeros must occur, or the run proved nothing.
  bool ok() const {
    std::printf("%-9s certain %6ld uncertain %6ld zero %6ld wrong exact %ld wrong filter %ld\n",
                name, certain, uncertain, zero, wrong_exact, wrong_filter);
    return wrong_exact == 0 && wrong_filter == 0 && certain > 0 && uncertain > 0 && zero > 0;
  }
};

template <std::size_t D, std::size_t N>
int oracle(const std::array<Pt<D>, N>& p) {
  return certimesh::testing::oracle_sign<D, N>(p, N == D + 2);
}

bool run(long n) {
  namespace fc = fp_consumer;
  Rng rng(20240612);  // fixed: the same queries on every run (design decision 5)
  Tally o2{"orient2d"}, o3{"orient3d"}, ic{"incircle"}, is{"insphere"};
  const auto circle = circle_points();
  const auto sphere = sphere_points();
  for (long i = 0; i < n; ++i) {
    auto a = flat<2>(rng);
    scale(rng, a);
    o2.record(oracle(a), fc::orient2d(a[0].data(), a[1].data(), a[2].data()),
              fc::orient2d_filtered(a[0].data(), a[1].data(), a[2].data()));
    auto b = flat<3>(rng);
    scale(rng, b);
    o3.record(oracle(b), fc::orient3d(b[0].data(), b[1].data(), b[2].data(), b[3].data()),
              fc::orient3d_filtered(b[0].data(), b[1].data(), b[2].data(), b[3].data()));
    auto c = on_sphere(rng, circle);
    scale(rng, c);
    ic.record(oracle(c), fc::incircle(c[0].data(), c[1].data(), c[2].data(), c[3].data()),
              fc::incircle_filtered(c[0].data(), c[1].data(), c[2].data(), c[3].data()));
    auto d = on_sphere(rng, sphere);
    scale(rng, d);
    is.record(oracle(d),
              fc::insphere(d[0].data(), d[1].data(), d[2].data(), d[3].data(), d[4].data()),
              fc::insphere_filtered(d[0].data(), d[1].data(), d[2].data(), d[3].data(),
                                    d[4].data()));
  }
  const bool ok[] = {o2.ok(), o3.ok(), ic.ok(), is.ok()};  // all four print
  return ok[0] && ok[1] && ok[2] && ok[3];
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 1000;
  std::printf("filters %s\n", fp_consumer::filters_out_of_line() ? "out of line" : "inline");
  return run(n) ? EXIT_SUCCESS : EXIT_FAILURE;
}
