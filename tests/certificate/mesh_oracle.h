// Independent facts about a test mesh, from the GMP rational oracle and plain sorting: the
// exact orientation sign of every element and whether two vertices coincide. The mutation
// tests use them to confirm what a mutation did before asking the certificate.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "certimesh/fuzz/mesh_mutations.h"
#include "certimesh/io/mesh_data.h"
#include "rational_oracle.h"

namespace certimesh::testing {

/// Sign of det[b - a, c - a (, d - a)]: +1 for a counterclockwise triangle or a positive
/// (Medit-convention) tetrahedron, exactly, by rational elimination.
inline int oracle_element_sign(const io::MeshData& m, const fuzz::Simplex& s) {
  const fuzz::Point3 a = fuzz::point(m, s[0]);
  std::vector<std::vector<mpq_class>> rows;
  for (std::size_t i = 1; i < s.size(); ++i) {
    const fuzz::Point3 p = fuzz::point(m, s[i]);
    std::vector<mpq_class> row;
    for (std::size_t c = 0; c < static_cast<std::size_t>(m.dimension); ++c)
      row.push_back(mpq_class(p[c]) - mpq_class(a[c]));
    rows.push_back(std::move(row));
  }
  return rational_determinant_sign(std::move(rows));
}

inline std::vector<int> oracle_element_signs(const io::MeshData& m) {
  std::vector<int> signs;
  for (std::size_t e = 0; e < fuzz::element_count(m); ++e)
    signs.push_back(oracle_element_sign(m, fuzz::element(m, e)));
  return signs;
}

/// Indices of the elements whose exact sign is `sign`.
inline std::vector<std::int64_t> elements_with_sign(const io::MeshData& m, int sign) {
  std::vector<std::int64_t> found;
  const std::vector<int> signs = oracle_element_signs(m);
  for (std::size_t e = 0; e < signs.size(); ++e)
    if (signs[e] == sign) found.push_back(static_cast<std::int64_t>(e));
  return found;
}

inline bool all_elements_positive(const io::MeshData& m) {
  const std::vector<int> signs = oracle_element_signs(m);
  return std::all_of(signs.begin(), signs.end(), [](int s) { return s > 0; });
}

/// True when two vertices have identical coordinates.
inline bool has_coincident_vertices(const io::MeshData& m) {
  std::vector<fuzz::Point3> points;
  for (io::Index v = 0; v < m.point_count(); ++v) points.push_back(fuzz::point(m, v));
  std::sort(points.begin(), points.end());
  return std::adjacent_find(points.begin(), points.end()) != points.end();
}

}  // namespace certimesh::testing
