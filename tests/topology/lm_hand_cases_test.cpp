// The five 2D local modifications on hand-made configurations whose answer is known: convex
// and non-convex flips, a collapse that would invert a triangle, node deletion at 5- and
// 6-valent vertices, a node shift inside the kernel of a non-convex star, insertion on
// interior and boundary edges, and the boundary trace. Orientation and area are checked with
// the GMP rational oracle (fuzz/oracles), independent of the predicates under test.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "certimesh/topology/local_modifications_2.h"
#include "certimesh/topology/quality.h"
#include "rational_oracle.h"

namespace certimesh::topology {
namespace {

LocalModificationOptions2 shape_quality() {
  LocalModificationOptions2 options;
  options.quality = [](const Point2d& a, const Point2d& b, const Point2d& c) { return triangle_quality(a, b, c); };
  return options;
}

// A quality that prefers large triangles (their perimeter): makes collapses attractive, so
// that only the validity check can refuse one.
LocalModificationOptions2 perimeter_quality() {
  LocalModificationOptions2 options;
  options.quality = [](const Point2d& a, const Point2d& b, const Point2d& c) {
    return std::hypot(b[0] - a[0], b[1] - a[1]) + std::hypot(c[0] - b[0], c[1] - b[1]) +
           std::hypot(a[0] - c[0], a[1] - c[1]);
  };
  return options;
}

struct Built {
  TriangleMesh2 mesh;
  std::vector<VertexId> v;
};

Built build(const std::vector<Point2d>& points, const std::vector<std::array<int, 3>>& triangles) {
  Built b;
  for (const auto& p : points) b.v.push_back(b.mesh.add_vertex(p));
  for (const auto& t : triangles) b.mesh.add_element({b.v[static_cast<std::size_t>(t[0])], b.v[static_cast<std::size_t>(t[1])], b.v[static_cast<std::size_t>(t[2])]});
  return b;
}

std::vector<ElementId> live(const TriangleMesh2& mesh) {
  std::vector<ElementId> out;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s)
    if (mesh.is_live(ElementId{s})) out.push_back(ElementId{s});
  return out;
}

// Every element counterclockwise by the oracle; returns twice the summed area, exactly.
mpq_class checked_twice_area(const TriangleMesh2& mesh) {
  mpq_class sum = 0;
  for (const ElementId e : live(mesh)) {
    const auto v = mesh.vertices(e);
    const auto a = mesh.point(v[0]), b = mesh.point(v[1]), c = mesh.point(v[2]);
    EXPECT_EQ(testing::oracle_orient2d(a[0], a[1], b[0], b[1], c[0], c[1]), 1) << "element " << e.value;
    sum += (mpq_class(b[0]) - a[0]) * (mpq_class(c[1]) - a[1]) - (mpq_class(c[0]) - a[0]) * (mpq_class(b[1]) - a[1]);
  }
  return sum;
}

double worst(const TriangleMesh2& mesh, const LocalModificationOptions2& o) {
  double q = 2.0;
  for (const ElementId e : live(mesh)) {
    const auto v = mesh.vertices(e);
    q = std::min(q, o.quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])));
  }
  return q;
}

// The element of `mesh` holding edge (a, b), and the local index of that edge in it.
std::pair<ElementId, int> edge_of(const TriangleMesh2& mesh, VertexId a, VertexId b) {
  const auto ref = mesh.find_facet({a, b});
  EXPECT_TRUE(ref.has_value());
  return {ref->element, ref->local};
}

// Quad L, B, R, T with the long diagonal L-R: flipping to T-B improves the shape.
TEST(lm_Flip, ConvexQuadFlipsToTheBetterDiagonal) {
  auto b = build({{-3, 0}, {0, -1}, {3, 0}, {0, 1}}, {{0, 2, 3}, {2, 0, 1}});
  const auto o = shape_quality();
  const double q0 = worst(b.mesh, o);
  const mpq_class area = checked_twice_area(b.mesh);
  const auto [e, i] = edge_of(b.mesh, b.v[0], b.v[2]);
  ASSERT_TRUE(try_flip(b.mesh, e, i, o));
  EXPECT_TRUE(b.mesh.find_facet({b.v[1], b.v[3]}));
  EXPECT_FALSE(b.mesh.find_facet({b.v[0], b.v[2]}));
  EXPECT_EQ(checked_twice_area(b.mesh), area);
  EXPECT_GT(worst(b.mesh, o), q0);
  // Flipping back would lower the quality: refused, mesh unchanged.
  const auto [e2, i2] = edge_of(b.mesh, b.v[1], b.v[3]);
  EXPECT_FALSE(try_flip(b.mesh, e2, i2, o));
  EXPECT_TRUE(b.mesh.find_facet({b.v[1], b.v[3]}));
}

TEST(lm_Flip, NonConvexAndDegenerateQuadsAreRefused) {
  // B = (-4, -0.1) lies beyond L: the quad is reflex at L. B = (-6, -1) is on the line T-L:
  // the quad is not strictly convex (a flipped triangle would be flat).
  for (const Point2d bottom : {Point2d{-4, -0.1}, Point2d{-6, -1}}) {
    auto b = build({{-3, 0}, bottom, {3, 0}, {0, 1}}, {{0, 2, 3}, {2, 0, 1}});
    const auto [e, i] = edge_of(b.mesh, b.v[0], b.v[2]);
    // With the perimeter quality the flip would "improve": only convexity refuses it.
    EXPECT_FALSE(try_flip(b.mesh, e, i, perimeter_quality()));
    EXPECT_TRUE(b.mesh.find_facet({b.v[0], b.v[2]}));
    EXPECT_EQ(b.mesh.element_count(), 2u);
  }
}

// The arrow: a free vertex at the origin whose star's link is non-convex (reflex at p1, p4).
const std::vector<Point2d> arrow_points{{0, 0}, {2, 0}, {0.25, 0.25}, {-1, 1}, {-1, -1}, {0.25, -0.25}};
const std::vector<std::array<int, 3>> arrow_triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1}};

TEST(lm_Collapse, CollapseThatWouldInvertATriangleIsRefused) {
  auto b = build(arrow_points, arrow_triangles);
  // Merging the centre into w = (2, 0) (a boundary vertex, which stays put) turns
  // (centre, p1, p2) into (w, p1, p2): clockwise, as the oracle confirms.
  ASSERT_EQ(testing::oracle_orient2d(2, 0, 0.25, 0.25, -1, 1), -1);
  const auto [e, i] = edge_of(b.mesh, b.v[0], b.v[1]);
  EXPECT_FALSE(try_edge_collapse(b.mesh, e, i, perimeter_quality()));
  EXPECT_EQ(b.mesh.element_count(), 5u);
  EXPECT_TRUE(b.mesh.is_live(b.v[0]));
  EXPECT_EQ(b.mesh.point(b.v[0]), (Point2d{0, 0}));
}

TEST(lm_Collapse, InteriorVertexMergesIntoTheBoundaryVertexWhichStaysPut) {
  // A square 4 x 4 with free vertices v = (1, 1) and u = (3, 3).
  auto b = build({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 3}},
                 {{0, 1, 4}, {1, 2, 5}, {2, 3, 5}, {3, 0, 4}, {4, 1, 5}, {4, 5, 3}});
  const mpq_class area = checked_twice_area(b.mesh);
  ASSERT_EQ(area, 32);
  const auto [e, i] = edge_of(b.mesh, b.v[4], b.v[0]);
  ASSERT_TRUE(try_edge_collapse(b.mesh, e, i, perimeter_quality()));
  EXPECT_FALSE(b.mesh.is_live(b.v[4]));
  EXPECT_EQ(b.mesh.point(b.v[0]), (Point2d{0, 0}));
  EXPECT_EQ(b.mesh.element_count(), 4u);
  EXPECT_EQ(checked_twice_area(b.mesh), area);
  // An edge between two boundary vertices through the interior is never collapsed.
  auto c = build({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}});
  const auto [e2, i2] = edge_of(c.mesh, c.v[0], c.v[2]);
  EXPECT_FALSE(try_edge_collapse(c.mesh, e2, i2, perimeter_quality()));
}

TEST(lm_Collapse, LinkConditionRefusesAThirdCommonNeighbour) {
  // Square ring around the triangle v = (1,1), w = (3,1), x = (2,3), with y = (2,1.5) inside it
  // joined to all three: v and w have the common neighbours y, z (below) and x.
  auto b = build({{0, -2}, {4, -2}, {5, 4}, {-1, 4}, {1, 1}, {3, 1}, {2, 3}, {2, 1.5}, {2, -1}},
                 {{4, 5, 7}, {5, 6, 7}, {6, 4, 7}, {5, 4, 8}, {0, 8, 4}, {8, 1, 5}, {0, 1, 8},
                  {1, 2, 5}, {5, 2, 6}, {2, 3, 6}, {6, 3, 4}, {3, 0, 4}});
  const mpq_class area = checked_twice_area(b.mesh);
  const auto [e, i] = edge_of(b.mesh, b.v[4], b.v[5]);
  EXPECT_FALSE(try_edge_collapse(b.mesh, e, i, perimeter_quality()));
  EXPECT_EQ(b.mesh.element_count(), 12u);
  EXPECT_EQ(checked_twice_area(b.mesh), area);
}

TEST(lm_Collapse, StraightBoundaryVertexMergesAlongItsEdgeOnlyWhenAllowed) {
  // The strip [0,4] x [0,1]: bottom (0,0), (1,0), (2,0), (4,0); top (0,1), (4,1). The bottom
  // vertices (1,0) and (2,0) are exactly on the bottom side; (0,0) and (4,0) are corners.
  auto b = build({{0, 0}, {1, 0}, {2, 0}, {4, 0}, {0, 1}, {4, 1}},
                 {{0, 1, 4}, {1, 2, 4}, {2, 5, 4}, {2, 3, 5}});
  const mpq_class area = checked_twice_area(b.mesh);
  auto o = perimeter_quality();
  const auto [e, i] = edge_of(b.mesh, b.v[1], b.v[2]);
  EXPECT_FALSE(try_edge_collapse(b.mesh, e, i, o));  // the trace is kept by default
  o.coarsen_straight_boundary = true;
  ASSERT_TRUE(try_edge_collapse(b.mesh, e, i, o));
  EXPECT_EQ(b.mesh.element_count(), 3u);
  EXPECT_EQ(b.mesh.vertex_count(), 5u);
  EXPECT_EQ(checked_twice_area(b.mesh), area);
  // The corner (0,0) is not on a straight line with its boundary neighbours: it stays.
  const auto [e2, i2] = edge_of(b.mesh, b.v[0], b.v[4]);
  EXPECT_FALSE(try_edge_collapse(b.mesh, e2, i2, o));
  EXPECT_TRUE(b.mesh.is_live(b.v[0]));
  EXPECT_TRUE(b.mesh.is_live(b.v[4]));
}

// A free centre near link vertex 0 of a regular n-gon: its star has slivers; the fan from
// vertex 0 is better, so node deletion removes the centre and leaves n - 2 triangles.
void deletion_case(int n) {
  std::vector<Point2d> points{{0.8, 0.05}};
  std::vector<std::array<int, 3>> triangles;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * std::numbers::pi * k / n;
    points.push_back({std::cos(angle), std::sin(angle)});
    triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
  }
  auto b = build(points, triangles);
  const auto o = shape_quality();
  const mpq_class area = checked_twice_area(b.mesh);
  const double q0 = worst(b.mesh, o);
  ASSERT_TRUE(try_node_deletion(b.mesh, b.v[0], o));
  EXPECT_FALSE(b.mesh.is_live(b.v[0]));
  EXPECT_EQ(b.mesh.element_count(), static_cast<std::size_t>(n - 2));
  EXPECT_EQ(checked_twice_area(b.mesh), area);
  EXPECT_GT(worst(b.mesh, o), q0);
}

TEST(lm_NodeDeletion, FiveValentVertex) { deletion_case(5); }
TEST(lm_NodeDeletion, SixValentVertex) { deletion_case(6); }

TEST(lm_NodeDeletion, WellPlacedCentreIsKept) {
  // The centre of a regular hexagon: six equilateral triangles beat every fan.
  std::vector<Point2d> points{{0, 0}};
  std::vector<std::array<int, 3>> triangles;
  for (int k = 0; k < 6; ++k) {
    points.push_back({std::cos(std::numbers::pi * k / 3), std::sin(std::numbers::pi * k / 3)});
    triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  }
  auto b = build(points, triangles);
  EXPECT_FALSE(try_node_deletion(b.mesh, b.v[0], shape_quality()));
  EXPECT_EQ(b.mesh.element_count(), 6u);
}

TEST(lm_NodeShift, StaysInTheKernelOfANonConvexStar) {
  auto b = build(arrow_points, arrow_triangles);
  const auto o = shape_quality();
  const mpq_class area = checked_twice_area(b.mesh);
  double q0 = worst(b.mesh, o);
  int moves = 0;
  for (int round = 0; round < 20; ++round) {
    if (!try_node_shift(b.mesh, b.v[0], o)) break;
    ++moves;
    const double q1 = worst(b.mesh, o);
    EXPECT_GT(q1, q0);
    q0 = q1;
    EXPECT_EQ(checked_twice_area(b.mesh), area);  // also: every star triangle counterclockwise
  }
  EXPECT_GT(moves, 0);
  // Boundary vertices never move.
  for (std::size_t k = 1; k < 6; ++k) EXPECT_FALSE(try_node_shift(b.mesh, b.v[k], o));
  EXPECT_EQ(b.mesh.point(b.v[1]), (Point2d{2, 0}));
}

TEST(lm_Insert, InteriorEdgeSplitsFourWays) {
  // Two flat triangles on the long edge (0,0)-(8,0), apexes (4, 1) and (4, -1): splitting the
  // edge at its midpoint gives four better triangles.
  auto b = build({{0, 0}, {8, 0}, {4, 1}, {4, -1}}, {{0, 1, 2}, {1, 0, 3}});
  const auto o = shape_quality();
  const mpq_class area = checked_twice_area(b.mesh);
  const auto [e, i] = edge_of(b.mesh, b.v[0], b.v[1]);
  ASSERT_TRUE(try_insert_on_edge(b.mesh, e, i, o));
  EXPECT_EQ(b.mesh.element_count(), 4u);
  EXPECT_EQ(b.mesh.vertex_count(), 5u);
  EXPECT_EQ(checked_twice_area(b.mesh), area);
}

TEST(lm_Insert, BoundaryEdgeOnlyWithAProjectionAndLabelsFollow) {
  auto b = build({{0, 0}, {8, 0}, {4, 1}}, {{0, 1, 2}});
  b.mesh.set_facet_label({b.v[0], b.v[1]}, 3);
  auto o = shape_quality();
  auto [e, i] = edge_of(b.mesh, b.v[0], b.v[1]);
  EXPECT_FALSE(try_insert_on_edge(b.mesh, e, i, o));
  int calls = 0;
  o.boundary_projection = [&](VertexId, VertexId, const Point2d& m) {
    ++calls;
    return m;  // a straight boundary: the midpoint (4, 0) is on it exactly
  };
  ASSERT_TRUE(try_insert_on_edge(b.mesh, e, i, o));
  EXPECT_EQ(calls, 1);
  const auto m = VertexId{3};
  ASSERT_TRUE(b.mesh.is_live(m));
  EXPECT_EQ(b.mesh.point(m), (Point2d{4, 0}));
  EXPECT_EQ(b.mesh.facet_label({b.v[0], m}), 3);
  EXPECT_EQ(b.mesh.facet_label({m, b.v[1]}), 3);
  EXPECT_EQ(b.mesh.facet_label({b.v[0], b.v[1]}), 0);
  // A projection that would invert a half (Lemma 5.2.2) is refused.
  auto c = build({{0, 0}, {8, 0}, {4, 1}}, {{0, 1, 2}});
  o.boundary_projection = [](VertexId, VertexId, const Point2d&) { return Point2d{4, 2}; };
  std::tie(e, i) = edge_of(c.mesh, c.v[0], c.v[1]);
  EXPECT_FALSE(try_insert_on_edge(c.mesh, e, i, o));
  EXPECT_EQ(c.mesh.element_count(), 1u);
}

TEST(lm_Trace, ConstrainedEdgesAndTheirVerticesStay) {
  auto b = build({{-3, 0}, {0, -1}, {3, 0}, {0, 1}}, {{0, 2, 3}, {2, 0, 1}});
  b.mesh.set_facet_label({b.v[0], b.v[2]}, 5);  // a cut along the long diagonal
  const auto [e, i] = edge_of(b.mesh, b.v[0], b.v[2]);
  EXPECT_TRUE(is_constrained_edge(b.mesh, e, i));
  EXPECT_FALSE(try_flip(b.mesh, e, i, shape_quality()));
  b.mesh.set_facet_label({b.v[0], b.v[2]}, 0);
  b.mesh.set_label(e, 7);  // different materials: an interface without a facet label
  EXPECT_TRUE(is_constrained_edge(b.mesh, e, i));
  EXPECT_FALSE(try_flip(b.mesh, e, i, shape_quality()));
  for (const VertexId v : b.v) EXPECT_TRUE(is_trace_vertex(b.mesh, v));
}

}  // namespace
}  // namespace certimesh::topology
