// Seeded generators of intersection test cases: a pool of points per case, elements
// picked from it by index (the index is the vertex id, so picking the same index twice
// shares a vertex; a copied point under another index is a distinct id at the same
// coordinates).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::testing {

enum class PoolKind : int {
  random_unit,    // uniform doubles in [-1, 1]: generic position
  small_integer,  // coordinates in {-2..2}: coplanar, collinear, coincident galore
  derived,        // small integers plus exact midpoints, quarter points, reflections, copies
  nudged,         // derived, then some points moved by one ulp (near-degenerate)
  planar,         // derived, all in the plane z = x + y (exact): coplanar pairs in 3D
  offset_random,  // uniform in [-1, 1] around (1000, 1000, 1000): filters less certain
  line,           // exact points of one line (and one point off it): degenerate elements
  few_points,     // three small-integer points and copies: repeated coordinates everywhere
  scaled,         // derived, times 2^600 or 2^-600: the kernel's range fallbacks
  count
};

inline const char* name(PoolKind k) {
  static const char* names[] = {"random_unit",   "small_integer", "derived",    "nudged", "planar",
                                "offset_random", "line",          "few_points", "scaled"};
  return names[static_cast<int>(k)];
}

class CaseGenerator {
 public:
  explicit CaseGenerator(std::uint64_t seed) : rng_(seed) {}

  std::vector<predicates::Point3> pool(PoolKind kind) {
    using predicates::Point3;
    std::vector<Point3> p;
    switch (kind) {
      case PoolKind::random_unit:
      case PoolKind::offset_random: {
        const double o = kind == PoolKind::offset_random ? 1000.0 : 0.0;
        for (int i = 0; i < 8; ++i) p.push_back({o + unit(), o + unit(), o + unit()});
        return p;
      }
      case PoolKind::small_integer:
        for (int i = 0; i < 7; ++i) p.push_back({small(), small(), small()});
        return p;
      case PoolKind::line: {
        const Point3 a{small(), small(), small()}, b{small(), small(), small()};
        for (double t : {-1.0, 0.0, 0.25, 0.5, 1.0, 2.0, 0.5})
          p.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)});
        p.push_back({small(), small(), small()});
        return p;
      }
      case PoolKind::few_points:
        for (int i = 0; i < 3; ++i) p.push_back({small(), small(), small()});
        for (int i = 0; i < 5; ++i) p.push_back(p[index(3)]);
        return p;
      default:
        break;
    }
    for (int i = 0; i < 4; ++i) p.push_back({small(), small(), small()});
    for (int i = 0; i < 5; ++i) p.push_back(derived_point(p));
    if (kind == PoolKind::planar)
      for (Point3& q : p) q.z = q.x + q.y;
    if (kind == PoolKind::nudged)
      for (int i = 0; i < 3; ++i) nudge(p[index(p.size())]);
    if (kind == PoolKind::scaled) {
      const int e = chance(0.5) ? 600 : -600;
      for (Point3& q : p) q = {std::ldexp(q.x, e), std::ldexp(q.y, e), std::ldexp(q.z, e)};
    }
    return p;
  }

  /// Indices of two elements of sizes na, nb sharing `shared` vertices (when possible).
  std::array<std::vector<int>, 2> pick(std::size_t pool_size, int na, int nb, int shared) {
    std::vector<int> all(pool_size);
    std::iota(all.begin(), all.end(), 0);
    std::shuffle(all.begin(), all.end(), rng_);
    std::vector<int> a(all.begin(), all.begin() + na);
    std::vector<int> b(a.begin(), a.begin() + std::min(shared, std::min(na, nb)));
    for (std::size_t i = static_cast<std::size_t>(na); b.size() < static_cast<std::size_t>(nb); ++i)
      b.push_back(all[i % pool_size]);
    repeated_id_ = chance(0.03);
    if (repeated_id_) a[0] = a[a.size() - 1];  // the same id twice within one element
    std::shuffle(a.begin(), a.end(), rng_);
    std::shuffle(b.begin(), b.end(), rng_);
    return {a, b};
  }

  /// Whether the last pick repeated an id within the first element.
  bool repeated_id() const { return repeated_id_; }

  int shared_count(int max) { return std::uniform_int_distribution<int>(0, max)(rng_); }
  bool chance(double p) { return std::bernoulli_distribution(p)(rng_); }
  PoolKind kind() {
    return static_cast<PoolKind>(
        std::uniform_int_distribution<int>(0, static_cast<int>(PoolKind::count) - 1)(rng_));
  }

 private:
  double unit() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_); }
  double small() { return static_cast<double>(std::uniform_int_distribution<int>(-2, 2)(rng_)); }
  std::size_t index(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
  }

  // Exact points on edges, faces and lines of earlier points, or a copy of one.
  predicates::Point3 derived_point(const std::vector<predicates::Point3>& p) {
    const auto& a = p[index(p.size())];
    const auto& b = p[index(p.size())];
    const auto& c = p[index(p.size())];
    const auto mix = [](double x, double y, double z, double wx, double wy, double wz) {
      return wx * x + wy * y + wz * z;
    };
    switch (std::uniform_int_distribution<int>(0, 3)(rng_)) {
      case 0:
        return {mix(a.x, b.x, 0, 0.5, 0.5, 0), mix(a.y, b.y, 0, 0.5, 0.5, 0),
                mix(a.z, b.z, 0, 0.5, 0.5, 0)};
      case 1:
        return {mix(a.x, b.x, c.x, 0.5, 0.25, 0.25), mix(a.y, b.y, c.y, 0.5, 0.25, 0.25),
                mix(a.z, b.z, c.z, 0.5, 0.25, 0.25)};
      case 2:
        return {2 * b.x - a.x, 2 * b.y - a.y, 2 * b.z - a.z};  // beyond b on line ab
      default:
        return a;  // distinct id, same point
    }
  }

  void nudge(predicates::Point3& q) {
    double* c[3] = {&q.x, &q.y, &q.z};
    double& x = *c[index(3)];
    x = std::nextafter(x, chance(0.5) ? HUGE_VAL : -HUGE_VAL);
  }

  std::mt19937_64 rng_;
  bool repeated_id_ = false;
};

template <std::size_t N>
std::array<predicates::Vertex3, N> element3(const std::vector<predicates::Point3>& pool,
                                            const std::vector<int>& idx) {
  std::array<predicates::Vertex3, N> e;
  for (std::size_t i = 0; i < N; ++i) e[i] = {pool[static_cast<std::size_t>(idx[i])], 100 + idx[i]};
  return e;
}

template <std::size_t N>
std::array<predicates::Vertex2, N> element2(const std::vector<predicates::Point3>& pool,
                                            const std::vector<int>& idx) {
  std::array<predicates::Vertex2, N> e;
  for (std::size_t i = 0; i < N; ++i) {
    const auto& p = pool[static_cast<std::size_t>(idx[i])];
    e[i] = {{p.x, p.y}, 100 + idx[i]};
  }
  return e;
}

}  // namespace certimesh::testing
