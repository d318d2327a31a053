// Closed triangulated surfaces for the boundary-recovery tests, built by hand from their
// definitions (no certimesh code): boxes with V grooves on top (along x) and bottom (along y)
// -- the cube, thin slabs, Chazelle-type notched polyhedra --, Schönhardt's twisted prism,
// thin wedge prisms (small dihedral angles), and star-shaped polyhedra (vertices of a convex
// polyhedron moved along their rays). Triangles are counterclockwise seen from outside.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "certimesh/predicates/point.h"

namespace certimesh::testing {

using P3 = predicates::Point3;
using Tri = std::array<std::uint32_t, 3>;

struct Surface {
  std::vector<P3> points;
  std::vector<Tri> triangles;

  std::uint32_t add(P3 p) {
    points.push_back(p);
    return static_cast<std::uint32_t>(points.size() - 1);
  }
  // Adds the triangle oriented so that its normal has a positive dot product with `out`.
  void add_oriented(std::uint32_t a, std::uint32_t b, std::uint32_t c, P3 out) {
    const P3 &pa = points[a], &pb = points[b], &pc = points[c];
    const double ux = pb.x - pa.x, uy = pb.y - pa.y, uz = pb.z - pa.z;
    const double vx = pc.x - pa.x, vy = pc.y - pa.y, vz = pc.z - pa.z;
    const double d = (uy * vz - uz * vy) * out.x + (uz * vx - ux * vz) * out.y + (ux * vy - uy * vx) * out.z;
    if (d > 0)
      triangles.push_back({a, b, c});
    else
      triangles.push_back({a, c, b});
  }
  // Appends another surface (its orientation reversed when `flip`: a cavity).
  void append(const Surface& s, bool flip) {
    const auto base = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), s.points.begin(), s.points.end());
    for (const Tri& t : s.triangles)
      triangles.push_back(flip ? Tri{base + t[0], base + t[2], base + t[1]} : Tri{base + t[0] + 0, base + t[1], base + t[2]});
  }
  void scale(double k) {
    for (P3& p : points) p = {p.x * k, p.y * k, p.z * k};
  }
  void translate(P3 d) {
    for (P3& p : points) p = {p.x + d.x, p.y + d.y, p.z + d.z};
  }
};

// A profile over [0, length]: the heights at increasing abscissae, `grooves` V grooves of
// width `width` and depth `depth` (signed: into the solid), centred at length (i + 1)/(n + 1),
// flat at `level` elsewhere.
inline std::vector<std::array<double, 2>> grooved_profile(double length, double level, int grooves, double width,
                                                          double depth) {
  std::vector<std::array<double, 2>> p{{0.0, level}};
  for (int i = 0; i < grooves; ++i) {
    const double c = length * (i + 1) / (grooves + 1);
    p.push_back({c - width / 2, level});
    p.push_back({c, level + depth});
    p.push_back({c + width / 2, level});
  }
  p.push_back({length, level});
  return p;
}

// Fan of a convex polygon (given in boundary order) from its corner `apex`; no other
// corner may lie on the polygon's two sides at the apex.
inline void fan(Surface& s, const std::vector<std::uint32_t>& polygon, std::size_t apex, P3 out) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 1; i + 1 < n; ++i)
    s.add_oriented(polygon[apex], polygon[(apex + i) % n], polygon[(apex + i + 1) % n], out);
}

// The box [0, length]^2 x [0, height] with `top` V grooves along x cut from the top face
// (profile in y) and `bottom` V grooves along y cut from the bottom face (profile in x), each
// `width` wide and `depth` deep. top = bottom = 0 is the box; grooves nearly meeting in the
// middle (depth close to height / 2) make a Chazelle-type polyhedron.
inline Surface notched_box(double length, double height, int top, int bottom, double width, double depth) {
  // Bottom grooves alone would put extra points on two opposite sides of the one top strip,
  // which a fan cannot triangulate.
  if (top == 0 && bottom > 0) std::abort();
  Surface s;
  const auto f = grooved_profile(length, height, top, width, -depth);  // z over y
  const auto g = grooved_profile(length, 0.0, bottom, width, depth);   // z over x
  const std::size_t nf = f.size(), ng = g.size();
  // Side faces x = 0 and x = length: the top profile over a straight bottom (z = 0), with
  // a bottom point under every top profile point; quads split into two triangles.
  std::vector<std::uint32_t> side_top[2], side_bottom[2];   // x = 0, x = length
  std::vector<std::uint32_t> front_bottom[2], front_top[2]; // y = 0, y = length
  for (int k = 0; k < 2; ++k) {
    const double x = k == 0 ? 0.0 : length;
    for (const auto& q : f) side_top[k].push_back(s.add({x, q[0], q[1]}));
    side_bottom[k].push_back(s.add({x, 0.0, 0.0}));
    for (std::size_t i = 1; i + 1 < nf; ++i) side_bottom[k].push_back(s.add({x, f[i][0], 0.0}));
    side_bottom[k].push_back(s.add({x, length, 0.0}));
  }
  // Faces y = 0 and y = length: the bottom profile under a straight top (z = height); the
  // corners are the side faces' corners.
  for (int k = 0; k < 2; ++k) {
    const double y = k == 0 ? 0.0 : length;
    const std::size_t end = k == 0 ? 0 : nf - 1;
    front_bottom[k].push_back(side_bottom[0][end]);
    for (std::size_t i = 1; i + 1 < ng; ++i) front_bottom[k].push_back(s.add({g[i][0], y, g[i][1]}));
    front_bottom[k].push_back(side_bottom[1][end]);
    front_top[k].push_back(side_top[0][end]);
    for (std::size_t i = 1; i + 1 < ng; ++i) front_top[k].push_back(s.add({g[i][0], y, height}));
    front_top[k].push_back(side_top[1][end]);
  }
  for (int k = 0; k < 2; ++k) {
    const P3 out_x{k == 0 ? -1.0 : 1.0, 0, 0}, out_y{0, k == 0 ? -1.0 : 1.0, 0};
    for (std::size_t i = 0; i + 1 < nf; ++i) {
      s.add_oriented(side_bottom[k][i], side_bottom[k][i + 1], side_top[k][i + 1], out_x);
      s.add_oriented(side_bottom[k][i], side_top[k][i + 1], side_top[k][i], out_x);
    }
    for (std::size_t i = 0; i + 1 < ng; ++i) {
      s.add_oriented(front_bottom[k][i], front_bottom[k][i + 1], front_top[k][i + 1], out_y);
      s.add_oriented(front_bottom[k][i], front_top[k][i + 1], front_top[k][i], out_y);
    }
  }
  // Top strips (between consecutive top profile points, across x); the first and last also
  // hold the y = 0 / y = length faces' top points.
  for (std::size_t i = 0; i + 1 < nf; ++i) {
    std::vector<std::uint32_t> poly{side_top[0][i]};
    if (i == 0)
      for (std::size_t j = 1; j + 1 < ng; ++j) poly.push_back(front_top[0][j]);
    poly.push_back(side_top[1][i]);
    poly.push_back(side_top[1][i + 1]);
    if (i + 2 == nf)
      for (std::size_t j = ng - 2; j >= 1; --j) poly.push_back(front_top[1][j]);
    poly.push_back(side_top[0][i + 1]);
    fan(s, poly, i == 0 ? poly.size() - 1 : 0, P3{0, 0, 1});  // a corner off the extra points
  }
  // Bottom strips (between consecutive bottom profile points, across y); the first and
  // last also hold the x = 0 / x = length faces' bottom points.
  for (std::size_t i = 0; i + 1 < ng; ++i) {
    std::vector<std::uint32_t> poly{front_bottom[0][i]};
    poly.push_back(front_bottom[0][i + 1]);
    if (i + 2 == ng)
      for (std::size_t j = 1; j + 1 < nf; ++j) poly.push_back(side_bottom[1][j]);
    poly.push_back(front_bottom[1][i + 1]);
    poly.push_back(front_bottom[1][i]);
    if (i == 0)
      for (std::size_t j = nf - 2; j >= 1; --j) poly.push_back(side_bottom[0][j]);
    fan(s, poly, i == 0 ? 1 : 0, P3{0, 0, -1});
  }
  return s;
}

// Schönhardt's twisted prism: a triangle at z = 0 and the same triangle turned by `twist`
// radians at z = 1, each side quad cut by its diagonal that makes a reflex edge. It has no
// tetrahedralization without a Steiner point.
// A box whose six faces are grids (the lines at the given coordinates of each axis, sorted,
// at least two each), every grid square cut by the diagonal `diagonal(face, i, j)` picks (0 or
// 1): flat faces whose triangulation the Delaunay tetrahedralization of the vertices (many of
// them cospherical) generally does not have, so recovery must flip or split on the hull.
template <class Diagonal>
inline Surface gridded_box(const std::array<std::vector<double>, 3>& lines, Diagonal diagonal) {
  Surface s;
  std::map<std::array<std::size_t, 3>, std::uint32_t> index;
  auto vertex = [&](std::array<std::size_t, 3> i) {
    auto [it, added] = index.emplace(i, 0);
    if (added) it->second = s.add({lines[0][i[0]], lines[1][i[1]], lines[2][i[2]]});
    return it->second;
  };
  int face = 0;
  for (std::size_t axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true}) {
      const std::size_t u = (axis + 1) % 3, v = (axis + 2) % 3;
      const std::size_t level = high ? lines[axis].size() - 1 : 0;
      P3 out{0, 0, 0};
      (axis == 0 ? out.x : axis == 1 ? out.y : out.z) = high ? 1 : -1;
      for (std::size_t i = 0; i + 1 < lines[u].size(); ++i)
        for (std::size_t j = 0; j + 1 < lines[v].size(); ++j) {
          auto corner = [&](std::size_t di, std::size_t dj) {
            std::array<std::size_t, 3> c{};
            c[axis] = level, c[u] = i + di, c[v] = j + dj;
            return vertex(c);
          };
          const std::uint32_t a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
          if (diagonal(face, i, j)) {
            s.add_oriented(a, b, c, out), s.add_oriented(a, c, d, out);
          } else {
            s.add_oriented(a, b, d, out), s.add_oriented(b, c, d, out);
          }
        }
      ++face;
    }
  return s;
}

inline Surface schonhardt(double twist = 0.5) {
  Surface s;
  for (int i = 0; i < 3; ++i) s.add({std::cos(2 * M_PI * i / 3), std::sin(2 * M_PI * i / 3), 0.0});
  for (int i = 0; i < 3; ++i) s.add({std::cos(2 * M_PI * i / 3 + twist), std::sin(2 * M_PI * i / 3 + twist), 1.0});
  s.triangles.push_back({0, 2, 1});
  s.triangles.push_back({3, 4, 5});
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t a = i, a1 = (i + 1) % 3, b = 3 + i, b1 = 3 + (i + 1) % 3;
    s.triangles.push_back({a, a1, b1});
    s.triangles.push_back({a, b1, b});
  }
  return s;
}

// A triangular prism over the triangle (0,0), (1,0), (cos a, sin a) in z in [0, 1]: the
// edge along z through the origin has the dihedral angle a.
inline Surface wedge_prism(double angle) {
  Surface s;
  const double cx = std::cos(angle), cy = std::sin(angle);
  for (double z : {0.0, 1.0}) {
    s.add({0, 0, z});
    s.add({1, 0, z});
    s.add({cx, cy, z});
  }
  s.add_oriented(0, 1, 2, {0, 0, -1});
  s.add_oriented(3, 4, 5, {0, 0, 1});
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t j = (i + 1) % 3;
    const P3 &p = s.points[i], &q = s.points[j];
    const P3 out{q.y - p.y, -(q.x - p.x), 0};  // the triangle is counterclockwise
    s.add_oriented(i, j, j + 3, out);
    s.add_oriented(i, j + 3, i + 3, out);
  }
  return s;
}

}  // namespace certimesh::testing
