// Delaunay3 on the 40^3 integer grid of issue 13 ("correct, exactly checked, on a 40^3 integer
// grid"), in a binary of its own for its time: the exact checks of dt_delaunay_3_checks.h,
// the cube's volume exactly, every tetrahedron inside one unit cell, 12 hull triangles per unit
// square of the cube's surface.
#include <gtest/gtest.h>

#include "certimesh/generators/delaunay/delaunay_3.h"
#include "dt_delaunay_3_checks.h"

namespace certimesh::testing {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int side = 12;
#else
constexpr int side = 40;
#endif

TEST(Delaunay3Grid, FortyCubedIsExactlyDelaunay) {
  std::vector<P3> p;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < side; ++k) p.push_back({double(i), double(j), double(k)});
  const generators::Delaunay3 dt(p);
  std::vector<Tet> tets;
  for (const auto& t : dt.tetrahedra()) tets.push_back(t);
  const std::size_t hull_faces = check_delaunay_3(p, tets);
  const std::int64_t edge = side - 1;
  EXPECT_EQ(hull_faces, std::size_t(12 * edge * edge));
  std::int64_t six_volume = 0;  // in integers: the coordinates are small
  for (const Tet& t : tets) {
    std::int64_t lo[3], hi[3], d[3][3];
    const P3& a = p[t[0]];
    for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = std::int64_t(axis == 0 ? a.x : (axis == 1 ? a.y : a.z));
    for (int r = 1; r < 4; ++r) {
      const P3& q = p[t[r]];
      const std::int64_t c[3] = {std::int64_t(q.x), std::int64_t(q.y), std::int64_t(q.z)};
      for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = std::min(lo[axis], c[axis]), hi[axis] = std::max(hi[axis], c[axis]);
        d[r - 1][axis] = c[axis] - std::int64_t(axis == 0 ? a.x : (axis == 1 ? a.y : a.z));
      }
    }
    for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(hi[axis] - lo[axis], 1) << "a tetrahedron across cells";
    const std::int64_t v = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                           d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
    EXPECT_TRUE(v == 1 || v == 2) << v;
    six_volume += v;
  }
  EXPECT_EQ(six_volume, 6 * edge * edge * edge);
}

}  // namespace
}  // namespace certimesh::testing
