// Closed surfaces for the surface validation tests, built by hand so that the expected answer
// is known without running the code under test: boxes (12 triangles, outward unless asked),
// tetrahedra, and a builder that welds equal coordinates into one vertex (as a file would
// name one vertex), so that shells sharing a corner share its index.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "certimesh/generators/domain/surface_3.h"

namespace certimesh::generators::test {

using predicates::Point3;

class SurfaceBuilder {
 public:
  std::uint32_t vertex(const Point3& p) {
    const auto [it, inserted] = index_.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<std::uint32_t>(s_.points.size()));
    if (inserted) s_.points.push_back(p);
    return it->second;
  }
  void triangle(const Point3& a, const Point3& b, const Point3& c, bool outward = true) {
    std::array<std::uint32_t, 3> t{vertex(a), vertex(b), vertex(c)};
    if (!outward) std::swap(t[1], t[2]);
    s_.triangles.push_back(t);
    s_.labels.push_back(0);
    s_.facet_of.push_back(static_cast<std::uint32_t>(s_.facet_of.size()));
  }
  // The box [lo, hi], each face two triangles, normals outward (or all inward).
  void box(const Point3& lo, const Point3& hi, bool outward = true) {
    auto P = [&](int i, int j, int k) { return Point3{i ? hi.x : lo.x, j ? hi.y : lo.y, k ? hi.z : lo.z}; };
    // Each face as a counterclockwise quad seen from outside.
    const int faces[6][4][3] = {
        {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}},  // z = lo
        {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},  // z = hi
        {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},  // y = lo
        {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},  // y = hi
        {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},  // x = lo
        {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},  // x = hi
    };
    for (const auto& f : faces) {
      const Point3 a = P(f[0][0], f[0][1], f[0][2]), b = P(f[1][0], f[1][1], f[1][2]), c = P(f[2][0], f[2][1], f[2][2]),
                   d = P(f[3][0], f[3][1], f[3][2]);
      triangle(a, b, c, outward);
      triangle(a, c, d, outward);
    }
  }
  // The tetrahedron a b c d with its faces outward (the builder decides the sense exactly by
  // the sign of det[b - a, c - a, d - a], computed here in doubles: callers give small integers).
  void tetrahedron(const Point3& a, const Point3& b, const Point3& c, const Point3& d, bool outward = true) {
    const double det = (b.x - a.x) * ((c.y - a.y) * (d.z - a.z) - (c.z - a.z) * (d.y - a.y)) -
                       (b.y - a.y) * ((c.x - a.x) * (d.z - a.z) - (c.z - a.z) * (d.x - a.x)) +
                       (b.z - a.z) * ((c.x - a.x) * (d.y - a.y) - (c.y - a.y) * (d.x - a.x));
    const bool positive = det > 0;  // then (a, c, b) faces away from d, etc.
    const bool o = positive == outward;
    triangle(a, c, b, o);
    triangle(a, b, d, o);
    triangle(a, d, c, o);
    triangle(b, c, d, o);
  }
  Surface3& surface() { return s_; }

 private:
  Surface3 s_;
  std::map<std::tuple<double, double, double>, std::uint32_t> index_;
};

}  // namespace certimesh::generators::test
