// Boundary nodes on an input segment (local_modifications_2.h, `input_segments`) on a hand-made
// strip whose bottom side is the one input segment (0,0)-(4,0): there every point x·(1,0) with
// a double x is exact, so the test's own segment functions are exact by construction and
// independent of the generators' rounding code. Orientation and area are checked with the GMP
// rational oracle (fuzz/oracles): sliding, collapsing and inserting on the bottom side leave
// the strip's area exactly unchanged.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>

#include "certimesh/topology/local_modifications_2.h"
#include "rational_oracle.h"

namespace certimesh::topology {
namespace {

const InputSegment2 bottom{{0.0, 0.0}, {4.0, 0.0}};

InputSegments2 bottom_side_only() {
  InputSegments2 s;
  s.segment_containing = [](const Point2d& p) -> std::optional<InputSegment2> {
    if (p[1] == 0.0 && p[0] > 0.0 && p[0] < 4.0) return bottom;
    return std::nullopt;
  };
  // Exact on the bottom side (x = 4f, a power-of-two multiple). The operations also probe an
  // edge between two vertices that are on no segment (does it span one whole?): there the
  // answer only has to be a point that segment_containing places on no segment.
  s.point_on = [](const InputSegment2& segment, double f) {
    if (segment == bottom) return Point2d{4.0 * f, 0.0};
    return Point2d{segment.start[0] + f * (segment.end[0] - segment.start[0]),
                   segment.start[1] + f * (segment.end[1] - segment.start[1])};
  };
  return s;
}

LocalModificationOptions2 with_quality(TriangleQualityFunction2 q) {
  LocalModificationOptions2 options;
  options.quality = std::move(q);
  options.minimum_shift_gain = 0.0;
  options.input_segments = bottom_side_only();
  return options;
}

double centroid_x(const Point2d& a, const Point2d& b, const Point2d& c) { return (a[0] + b[0] + c[0]) / 3.0; }
// Rewards triangles further left: a bottom vertex wants to slide left without end.
double prefers_left(const Point2d& a, const Point2d& b, const Point2d& c) { return 10.0 - centroid_x(a, b, c); }
double perimeter(const Point2d& a, const Point2d& b, const Point2d& c) {
  return std::hypot(b[0] - a[0], b[1] - a[1]) + std::hypot(c[0] - b[0], c[1] - b[1]) + std::hypot(a[0] - c[0], a[1] - c[1]);
}

// The strip [0,4] x [0,1.5]: bottom b0..b4 at (i, 0), top t0..t4 at (i, 1.5), two triangles per
// column. Vertex ids: b_i = v[i], t_i = v[5 + i].
struct Strip {
  TriangleMesh2 mesh;
  std::vector<VertexId> v;
  Strip() {
    for (int i = 0; i < 5; ++i) v.push_back(mesh.add_vertex({double(i), 0.0}));
    for (int i = 0; i < 5; ++i) v.push_back(mesh.add_vertex({double(i), 1.5}));
    for (std::size_t i = 0; i < 4; ++i) {
      mesh.add_element({v[i], v[i + 1], v[5 + i + 1]});
      mesh.add_element({v[i], v[5 + i + 1], v[5 + i]});
    }
  }
};

// Every element counterclockwise by the oracle; returns twice the summed area, exactly.
mpq_class checked_twice_area(const TriangleMesh2& mesh) {
  mpq_class sum = 0;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    if (!mesh.is_live(ElementId{s})) continue;
    const auto v = mesh.vertices(ElementId{s});
    const auto a = mesh.point(v[0]), b = mesh.point(v[1]), c = mesh.point(v[2]);
    EXPECT_EQ(testing::oracle_orient2d(a[0], a[1], b[0], b[1], c[0], c[1]), 1) << "element " << s;
    sum += (mpq_class(b[0]) - a[0]) * (mpq_class(c[1]) - a[1]) - (mpq_class(c[0]) - a[0]) * (mpq_class(b[1]) - a[1]);
  }
  return sum;
}

const mpq_class strip_twice_area = 12;  // 2 x 4 x 1.5

TEST(lm_BoundarySlide, SlidesTowardsButNeverOntoOrPastItsNeighbour) {
  Strip s;
  const auto o = with_quality(prefers_left);
  const VertexId b2 = s.v[2];
  for (const double x : {0.5, 0.999, 1.0}) {  // past or onto b1 at x = 1: the quality would rise
    EXPECT_FALSE(try_boundary_slide(s.mesh, b2, {x, 0.0}, o)) << x;
    EXPECT_EQ(s.mesh.point(b2), (Point2d{2.0, 0.0}));
  }
  EXPECT_FALSE(try_boundary_slide(s.mesh, b2, {1.5, 1e-3}, o));  // off the segment
  ASSERT_TRUE(try_boundary_slide(s.mesh, b2, {1.5, 0.0}, o));
  EXPECT_EQ(s.mesh.point(b2), (Point2d{1.5, 0.0}));
  for (int k = 0; k < 5; ++k) try_node_shift(s.mesh, b2, o);
  EXPECT_LT(s.mesh.point(b2)[0], 1.5);
  EXPECT_GT(s.mesh.point(b2)[0], 1.0);
  EXPECT_EQ(s.mesh.point(b2)[1], 0.0);
  EXPECT_EQ(checked_twice_area(s.mesh), strip_twice_area);
}

TEST(lm_BoundarySlide, DomainVerticesAndVerticesOffTheSegmentsStay) {
  Strip s;
  const auto o = with_quality(prefers_left);
  for (const std::size_t i : {std::size_t{0}, std::size_t{4}, std::size_t{6}, std::size_t{7}}) {
    const Point2d p = s.mesh.point(s.v[i]);
    EXPECT_FALSE(try_node_shift(s.mesh, s.v[i], o)) << i;
    EXPECT_EQ(s.mesh.point(s.v[i]), p);
  }
  // Without input segments the bottom Steiner vertex is on the trace and stays too.
  auto fixed = o;
  fixed.input_segments = {};
  EXPECT_FALSE(try_node_shift(s.mesh, s.v[2], fixed));
}

TEST(lm_BoundarySlide, CollapseAlongTheSegmentIntoANeighbour) {
  Strip s;
  auto o = with_quality(perimeter);  // prefers large triangles: collapses are wanted
  const auto ref = s.mesh.find_facet({s.v[1], s.v[2]});
  ASSERT_TRUE(ref);
  auto fixed = o;
  fixed.input_segments = {};
  EXPECT_FALSE(try_edge_collapse(s.mesh, ref->element, ref->local, fixed));  // trace kept vertex for vertex
  ASSERT_TRUE(try_edge_collapse(s.mesh, ref->element, ref->local, o));
  EXPECT_EQ(s.mesh.element_count(), 7u);
  EXPECT_NE(s.mesh.is_live(s.v[1]), s.mesh.is_live(s.v[2]));
  EXPECT_EQ(checked_twice_area(s.mesh), strip_twice_area);
  // The corner b0 never goes: its edge to b1 cannot be collapsed into b1.
  if (s.mesh.is_live(s.v[1])) {
    const auto corner = s.mesh.find_facet({s.v[0], s.v[1]});
    ASSERT_TRUE(corner);
    try_edge_collapse(s.mesh, corner->element, corner->local, o);
    EXPECT_TRUE(s.mesh.is_live(s.v[0]));
    EXPECT_EQ(s.mesh.point(s.v[0]), (Point2d{0.0, 0.0}));
  }
}

TEST(lm_BoundarySlide, InsertOnABoundaryEdgePutsTheNodeOnTheSegment) {
  Strip s;
  const auto o = with_quality([](const Point2d& a, const Point2d& b, const Point2d& c) { return 1.0 / perimeter(a, b, c); });
  const auto ref = s.mesh.find_facet({s.v[1], s.v[2]});
  ASSERT_TRUE(ref);
  auto fixed = o;
  fixed.input_segments = {};
  EXPECT_FALSE(try_insert_on_edge(s.mesh, ref->element, ref->local, fixed));
  ASSERT_TRUE(try_insert_on_edge(s.mesh, ref->element, ref->local, o));
  EXPECT_EQ(s.mesh.vertex_count(), 11u);
  const VertexId added{10};
  EXPECT_EQ(s.mesh.point(added), (Point2d{1.5, 0.0}));
  EXPECT_TRUE(s.mesh.find_facet({s.v[1], added}));
  EXPECT_TRUE(s.mesh.find_facet({added, s.v[2]}));
  EXPECT_EQ(checked_twice_area(s.mesh), strip_twice_area);
  // A top edge is on no input segment: not split.
  const auto top = s.mesh.find_facet({s.v[6], s.v[7]});
  ASSERT_TRUE(top);
  EXPECT_FALSE(try_insert_on_edge(s.mesh, top->element, top->local, o));
}

}  // namespace
}  // namespace certimesh::topology
