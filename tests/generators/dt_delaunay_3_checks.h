// The exact checks of a 3D Delaunay tetrahedralization of a point set, independent of the
// code under test: every tetrahedron positive by exact orient3d; every face in one or two
// tetrahedra, oppositely oriented in two; every interior face locally Delaunay under the
// kernel's insphere_sos (locally Delaunay everywhere is globally Delaunay, the perturbed
// signs being those of one generic point set); the hull faces a closed surface (every
// directed hull edge once), convex at every edge by exact orient3d; every input point a
// vertex. Also the exact volume, 6 V as a rational sum, for comparison with a hull volume
// computed elsewhere.
#pragma once

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient3d.h"
#include "certimesh/predicates/volume_sign.h"

namespace certimesh::testing {

using Tet = std::array<std::uint32_t, 4>;
using P3 = predicates::Point3;

inline Tet sorted_tet(Tet t) {
  std::sort(t.begin(), t.end());
  return t;
}

inline std::vector<Tet> canonical_set(const std::vector<Tet>& tets) {
  std::vector<Tet> out;
  out.reserve(tets.size());
  for (const Tet& t : tets) out.push_back(sorted_tet(t));
  std::sort(out.begin(), out.end());
  return out;
}

/// 6 times the exact volume of the union of the tetrahedra.
inline mpq_class six_volume(const std::vector<P3>& p, const std::vector<Tet>& tets) {
  mpq_class sum = 0;
  for (const Tet& t : tets) {
    const P3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]], &d = p[t[3]];
    const mpq_class ax(a.x), ay(a.y), az(a.z);
    const mpq_class bx = mpq_class(b.x) - ax, by = mpq_class(b.y) - ay, bz = mpq_class(b.z) - az;
    const mpq_class cx = mpq_class(c.x) - ax, cy = mpq_class(c.y) - ay, cz = mpq_class(c.z) - az;
    const mpq_class dx = mpq_class(d.x) - ax, dy = mpq_class(d.y) - ay, dz = mpq_class(d.z) - az;
    sum += bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
  }
  return sum;
}

/// Runs every exact check; returns the number of hull faces.
inline std::size_t check_delaunay_3(const std::vector<P3>& p, const std::vector<Tet>& tets) {
  static constexpr int face[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
  struct Face {
    std::array<std::uint32_t, 3> key;  // sorted corners
    std::uint32_t tet;
    int local;
  };
  std::vector<Face> faces;
  faces.reserve(4 * tets.size());
  std::vector<char> used(p.size(), 0);
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    const Tet& q = tets[t];
    EXPECT_EQ(predicates::volume_sign(p[q[0]], p[q[1]], p[q[2]], p[q[3]]), predicates::Sign::positive)
        << "tetrahedron " << t << " is not positive";
    for (int i = 0; i < 4; ++i) {
      used[q[i]] = 1;
      std::array<std::uint32_t, 3> k{q[face[i][0]], q[face[i][1]], q[face[i][2]]};
      std::sort(k.begin(), k.end());
      faces.push_back({k, t, i});
    }
  }
  for (std::size_t v = 0; v < p.size(); ++v) EXPECT_TRUE(used[v]) << "point " << v << " is not a vertex";
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<std::uint32_t, 2>> hull_edges;  // directed -> (face a, b, c) apex
  std::size_t hull_faces = 0;
  int delaunay_failures = 0;
  for (std::size_t k = 0; k < faces.size();) {
    std::size_t e = k + 1;
    while (e < faces.size() && faces[e].key == faces[k].key) ++e;
    EXPECT_LE(e - k, 2u) << "a face in more than two tetrahedra";
    if (e - k == 2) {
      const Tet &t1 = tets[faces[k].tet], &t2 = tets[faces[k + 1].tet];
      const std::uint32_t apex2 = t2[faces[k + 1].local];
      // Oppositely oriented: the apex of t2 is strictly beyond t1's face (positive orient3d).
      const int i = faces[k].local;
      EXPECT_EQ(predicates::orient3d(p[t1[face[i][0]]], p[t1[face[i][1]]], p[t1[face[i][2]]], p[apex2]),
                predicates::Sign::positive);
      // Locally Delaunay: the apex of t2 outside t1's perturbed sphere ((t1[1], t1[0], ...) has
      // orient3d > 0, where insphere > 0 means inside).
      if (predicates::insphere_sos(p[t1[1]], p[t1[0]], p[t1[2]], p[t1[3]], p[apex2]) != predicates::Sign::negative)
        ++delaunay_failures;
    } else if (e - k == 1) {
      ++hull_faces;
      const Tet& t = tets[faces[k].tet];
      const int i = faces[k].local;
      // The hull face seen from outside: reversed.
      const std::uint32_t a = t[face[i][0]], b = t[face[i][2]], c = t[face[i][1]];
      for (auto [u, w, x] : {std::array{a, b, c}, std::array{b, c, a}, std::array{c, a, b}}) {
        const bool fresh = hull_edges.insert({{u, w}, {x, faces[k].tet}}).second;
        EXPECT_TRUE(fresh) << "hull edge " << u << "-" << w << " twice";
      }
    }
    k = e;
  }
  EXPECT_EQ(delaunay_failures, 0) << "interior faces not locally Delaunay";
  // Closed: every directed hull edge has its reverse; convex: the apex of the face across
  // the edge is not strictly outside this face (orient3d of the outward-seen face < 0 outside).
  int concave = 0, open = 0;
  for (const auto& [edge, value] : hull_edges) {
    const auto twin = hull_edges.find({edge.second, edge.first});
    if (twin == hull_edges.end()) {
      ++open;
      continue;
    }
    // Face (u, w, x) counterclockwise from outside: a point q outside has orient3d(u, w, x, q) < 0.
    if (predicates::orient3d(p[edge.first], p[edge.second], p[value[0]], p[twin->second[0]]) == predicates::Sign::negative)
      ++concave;
  }
  EXPECT_EQ(open, 0) << "hull edges without a twin";
  EXPECT_EQ(concave, 0) << "hull edges where the hull is not convex";
  return hull_faces;
}

}  // namespace certimesh::testing
