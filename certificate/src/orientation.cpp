// Condition 3: every element has positive area / volume, decided exactly. orient2d and
// volume_sign run their floating-point filter inline and reach the exact stage only when the
// filter is uncertain, which is what keeps this pass fast. The quality measures are computed
// alongside in double: they are reported, never used for a decision.
#include <algorithm>
#include <cmath>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/volume_sign.h"
#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

// 12√3·|S|/P² (triangle) or 6⁴√2·|V|/P³ (tetrahedron), P the sum of the edge lengths. It is
// scale-invariant: huge or tiny elements are scaled first, where squares would overflow/underflow.
double quality(const MeshView& m, const Index* c) {
  double x[4][3] = {}, scale = 0, perimeter = 0;
  for (int v = 1; v <= m.dim; ++v)
    for (int k = 0; k < m.dim; ++k) scale = std::max(scale, std::abs(x[v][k] = m.coord(c[v], k) - m.coord(c[0], k)));
  for (int v = 1; (scale > 0x1p300 || scale < 0x1p-300) && v <= m.dim; ++v)
    for (int k = 0; k < m.dim; ++k) x[v][k] /= scale;
  for (int i = 0; i <= m.dim; ++i)
    for (int j = i + 1; j <= m.dim; ++j)
      perimeter += std::sqrt((x[i][0] - x[j][0]) * (x[i][0] - x[j][0]) + (x[i][1] - x[j][1]) * (x[i][1] - x[j][1]) +
                             (x[i][2] - x[j][2]) * (x[i][2] - x[j][2]));
  if (m.dim == 2) return 6.0 * std::sqrt(3.0) * std::abs(x[1][0] * x[2][1] - x[1][1] * x[2][0]) / (perimeter * perimeter);
  const double det = x[1][0] * (x[2][1] * x[3][2] - x[2][2] * x[3][1]) - x[1][1] * (x[2][0] * x[3][2] - x[2][2] * x[3][0]) +
                     x[1][2] * (x[2][0] * x[3][1] - x[2][1] * x[3][0]);
  return 216.0 * std::sqrt(2.0) * std::abs(det) / (perimeter * perimeter * perimeter);
}

predicates::Sign element_sign(const MeshView& m, const Index* c) {
  if (m.dim == 2) return predicates::orient2d(m.p2(c[0]), m.p2(c[1]), m.p2(c[2]));
  return predicates::volume_sign(m.p3(c[0]), m.p3(c[1]), m.p3(c[2]), m.p3(c[3]));
}

}  // namespace

Finding check_orientation(const MeshView& m, Statistics& stats) {
  std::int64_t first_inverted = -1;
  stats.worst_quality = 1.0;
  for (std::size_t e = 0; e < m.element_count; ++e) {
    const predicates::Sign s = element_sign(m, m.cell(e));
    if (s == predicates::Sign::zero)
      return finding(Defect::flat_element, static_cast<std::int64_t>(e), -1, -1,
                     "element " + std::to_string(e) + (m.dim == 2 ? " has zero area" : " has zero volume"));
    if (s == predicates::Sign::negative && first_inverted < 0) first_inverted = static_cast<std::int64_t>(e);
    const double q = quality(m, m.cell(e));
    if (q < stats.worst_quality || stats.worst_element < 0) {
      stats.worst_quality = q;
      stats.worst_element = static_cast<std::int64_t>(e);
    }
  }
  if (first_inverted >= 0)
    return finding(Defect::inverted_element, first_inverted, -1, -1,
                   "element " + std::to_string(first_inverted) +
                       (m.dim == 2 ? " is clockwise (negative area)" : " has negative volume"));
  return {};
}

}  // namespace certimesh::certificate::detail
