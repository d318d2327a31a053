#include "datasets.h"

#include <cmath>
#include <numbers>
#include <random>

namespace certimesh_bench {
namespace {

struct Rng {
  std::mt19937_64 engine;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};
  std::normal_distribution<double> gauss{0.0, 1.0};
  double u() { return unit(engine); }  // uniform in [-1, 1)
  double u01() { return 0.5 * (unit(engine) + 1.0); }
};

Point2 uniform2(Rng& r) { return {r.u(), r.u()}; }
Point3 uniform3(Rng& r) { return {r.u(), r.u(), r.u()}; }

}  // namespace

DataSet make_dataset(Predicate p, bool near_degenerate, std::size_t ntuples) {
  DataSet d{p, near_degenerate, ntuples, {}, {}};
  const std::size_t k = arity(p);
  Rng r{std::mt19937_64(0x5eed0000u + 16u * static_cast<unsigned>(p) + (near_degenerate ? 1u : 0u)),
        {}, {}};
  for (std::size_t i = 0; i < ntuples; ++i) {
    switch (p) {
      case Predicate::orient2d:
        if (!near_degenerate) {
          for (std::size_t j = 0; j < k; ++j) d.p2.push_back(uniform2(r));
        } else {
          // Near-collinear: three points of the line through two random points,
          // p + t (q - p) with t in [-1, 1], each coordinate rounded.
          const Point2 a = uniform2(r), b = uniform2(r);
          for (std::size_t j = 0; j < k; ++j) {
            const double t = r.u();
            d.p2.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
          }
        }
        break;
      case Predicate::incircle:
        if (!near_degenerate) {
          for (std::size_t j = 0; j < k; ++j) d.p2.push_back(uniform2(r));
        } else {
          // Near-cocircular: four points of a random circle (centre in [-0.5, 0.5]^2,
          // radius in [0.1, 0.5]), rounded.
          const double cx = 0.5 * r.u(), cy = 0.5 * r.u(), rad = 0.1 + 0.4 * r.u01();
          for (std::size_t j = 0; j < k; ++j) {
            const double th = std::numbers::pi * r.u();
            d.p2.push_back({cx + rad * std::cos(th), cy + rad * std::sin(th)});
          }
        }
        break;
      case Predicate::orient3d:
        if (!near_degenerate) {
          for (std::size_t j = 0; j < k; ++j) d.p3.push_back(uniform3(r));
        } else {
          // Near-coplanar: four points p + s (q - p) + t (w - p) of the plane through
          // three random points, s, t in [0, 1], rounded.
          const Point3 a = uniform3(r), b = uniform3(r), c = uniform3(r);
          for (std::size_t j = 0; j < k; ++j) {
            const double s = r.u01(), t = r.u01();
            d.p3.push_back({a.x + s * (b.x - a.x) + t * (c.x - a.x),
                            a.y + s * (b.y - a.y) + t * (c.y - a.y),
                            a.z + s * (b.z - a.z) + t * (c.z - a.z)});
          }
        }
        break;
      case Predicate::insphere:
        if (!near_degenerate) {
          for (std::size_t j = 0; j < k; ++j) d.p3.push_back(uniform3(r));
        } else {
          // Near-cospherical: five points of a random sphere (centre in [-0.5, 0.5]^3,
          // radius in [0.1, 0.5]), rounded.
          const double cx = 0.5 * r.u(), cy = 0.5 * r.u(), cz = 0.5 * r.u();
          const double rad = 0.1 + 0.4 * r.u01();
          for (std::size_t j = 0; j < k; ++j) {
            double gx = r.gauss(r.engine), gy = r.gauss(r.engine), gz = r.gauss(r.engine);
            const double len = std::sqrt(gx * gx + gy * gy + gz * gz);
            d.p3.push_back({cx + rad * gx / len, cy + rad * gy / len, cz + rad * gz / len});
          }
        }
        break;
    }
  }
  return d;
}

}  // namespace certimesh_bench
