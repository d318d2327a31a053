// Boundary nodes on the input segments (local_modifications_2.h, `input_segments`): a
// Steiner vertex slides along its input segment, never past a boundary neighbour; boundary
// vertices are collapsed along and inserted on the segments by Algorithm 35; every result is
// certified against the domain (the independent oracle: each boundary vertex's rounding box
// meets its segment, the mesh tiles the domain), and the runs are deterministic. The domain
// has generic slopes, so the Steiner points are roundings, not exact points, of the segments.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/improvement/input_segments_2.h"
#include "certimesh/generators/improvement/quality_improvement_2.h"
#include "certimesh/generators/mesh_domain_2.h"
#include "certimesh/topology/quality.h"
#include "imp_fixtures.h"

namespace certimesh {
namespace {

using generators::PlanarDomain;
using imp_testing::TriangleMesh2;
using topology::Point2d;
using topology::VertexId;

// A quadrilateral whose four sides have generic slopes.
PlanarDomain slanted_quadrilateral() {
  PlanarDomain d;
  d.points = {{0.0, 0.0}, {1.0, 0.1}, {1.1, 1.05}, {-0.05, 0.9}};
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({i, (i + 1) % 4, 1});
  return d;
}

TriangleMesh2 start_mesh(const PlanarDomain& domain, double h) {
  generators::MeshDomainOptions2 options;
  options.improve = false;
  options.size.uniform_size = h;
  return imp_testing::to_mesh(generators::mesh_domain_2(domain, options).mesh);
}

bool is_domain_vertex(const PlanarDomain& d, const Point2d& p) {
  for (const auto& q : d.points)
    if (q.x == p[0] && q.y == p[1]) return true;
  return false;
}

// The boundary vertices (ends of open facets), in id order.
std::vector<VertexId> boundary_vertices(const TriangleMesh2& mesh) {
  std::set<std::uint32_t> ids;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    const topology::ElementId e{s};
    if (!mesh.is_live(e)) continue;
    for (int i = 0; i < 3; ++i)
      if (mesh.neighbour(e, i) == topology::no_element)
        for (const VertexId v : mesh.facet(e, i)) ids.insert(v.value);
  }
  std::vector<VertexId> out;
  for (const auto id : ids) out.push_back(VertexId{id});
  return out;
}

// The boundary neighbours of v (the other ends of its two open facets).
std::vector<VertexId> boundary_neighbours(const TriangleMesh2& mesh, VertexId v) {
  std::vector<VertexId> out;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    const topology::ElementId e{s};
    if (!mesh.is_live(e)) continue;
    for (int i = 0; i < 3; ++i) {
      if (mesh.neighbour(e, i) != topology::no_element) continue;
      const auto f = mesh.facet(e, i);
      if (f[0] == v) out.push_back(f[1]);
      if (f[1] == v) out.push_back(f[0]);
    }
  }
  return out;
}

topology::LocalModificationOptions2 options_with(const PlanarDomain& domain, topology::TriangleQualityFunction2 q) {
  topology::LocalModificationOptions2 options;
  options.quality = std::move(q);
  options.minimum_shift_gain = 0.0;
  options.input_segments = generators::input_segments_of(domain);
  return options;
}

// A quality that only rewards small x: a boundary vertex on the bottom side wants to slide
// left without end, so only validity and the neighbour rule stop it.
double prefers_left(const Point2d& a, const Point2d& b, const Point2d& c) { return 10.0 - (a[0] + b[0] + c[0]) / 3.0; }

TEST(imp_BoundarySliding, NodeShiftSlidesSteinerVerticesAndKeepsTheCertificate) {
  const PlanarDomain domain = slanted_quadrilateral();
  const io::MeshData domain_data = generators::to_mesh_data(domain);
  TriangleMesh2 mesh = start_mesh(domain, 0.1);
  const auto options = options_with(domain, [](const Point2d& a, const Point2d& b, const Point2d& c) {
    // A size growing along x: the boundary spacing (uniform at the start) is wrong everywhere.
    const double h = 0.03 + 0.3 * (a[0] + b[0] + c[0]) / 3.0;
    return topology::size_aware_triangle_quality(a, b, c, h);
  });
  const auto boundary = boundary_vertices(mesh);
  int slid = 0, domain_vertices = 0;
  for (int sweep = 0; sweep < 3; ++sweep)
    for (const VertexId v : boundary) {
      const Point2d before = mesh.point(v);
      const bool committed = topology::try_node_shift(mesh, v, options).has_value();
      if (is_domain_vertex(domain, before)) {
        domain_vertices += sweep == 0;
        EXPECT_FALSE(committed);
        EXPECT_EQ(mesh.point(v), before);
      }
      slid += committed && mesh.point(v) != before;
    }
  EXPECT_EQ(domain_vertices, 4);
  EXPECT_GT(slid, 10);  // the ability is exercised, not vacuously certified
  EXPECT_EQ(boundary_vertices(mesh).size(), boundary.size());
  const auto report = imp_testing::certify(mesh, &domain_data);
  EXPECT_TRUE(report.valid) << report.finding.message;
}

TEST(imp_BoundarySliding, RejectsASlidePastANeighbourButSlidesTowardsIt) {
  const PlanarDomain domain = slanted_quadrilateral();
  const io::MeshData domain_data = generators::to_mesh_data(domain);
  const TriangleMesh2 start = start_mesh(domain, 0.1);
  const auto options = options_with(domain, prefers_left);
  const topology::InputSegment2 bottom{{0.0, 0.0}, {1.0, 0.1}};
  int checked = 0;
  for (const VertexId v : boundary_vertices(start)) {
    TriangleMesh2 mesh = start;  // each vertex from the start mesh: its neighbours where they were
    const Point2d p = mesh.point(v);
    if (is_domain_vertex(domain, p) || !(p[1] < 0.1 && p[0] > 0.0 && p[0] < 1.0)) continue;  // bottom side only
    const auto neighbours = boundary_neighbours(mesh, v);
    ASSERT_EQ(neighbours.size(), 2u);
    const Point2d left = mesh.point(neighbours[0])[0] < mesh.point(neighbours[1])[0] ? mesh.point(neighbours[0])
                                                                                      : mesh.point(neighbours[1]);
    const double f_left = left[0];  // x = f on the bottom side (its x extent is 1)
    // Past the left neighbour (and onto it): the quality would rise, the slide is refused.
    for (const double f : {f_left - 0.02, f_left - 1e-9, f_left}) {
      const Point2d target = options.input_segments.point_on(bottom, std::max(f, 0.0));
      EXPECT_FALSE(topology::try_boundary_slide(mesh, v, target, options)) << "f = " << f;
      EXPECT_EQ(mesh.point(v), p);
    }
    // Off the segment: refused.
    EXPECT_FALSE(topology::try_boundary_slide(mesh, v, {p[0] - 1e-3, p[1] + 1e-3}, options));
    // Half-way towards it: accepted, on the segment.
    const Point2d halfway = options.input_segments.point_on(bottom, 0.5 * (f_left + p[0]));
    ASSERT_TRUE(topology::try_boundary_slide(mesh, v, halfway, options));
    EXPECT_EQ(mesh.point(v), halfway);
    // The node shift's own search goes as far left as validity allows, never onto the neighbour.
    for (int k = 0; k < 4; ++k) topology::try_node_shift(mesh, v, options);
    EXPECT_LT(mesh.point(v)[0], halfway[0]);
    EXPECT_GT(mesh.point(v)[0], left[0]);
    const auto report = imp_testing::certify(mesh, &domain_data);
    EXPECT_TRUE(report.valid) << report.finding.message;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST(imp_BoundarySliding, DomainVertexAndSegmentQueriesAreExact) {
  const auto segments = generators::input_segments_of(slanted_quadrilateral());
  EXPECT_FALSE(segments.segment_containing({0.0, 0.0}));  // a domain vertex
  EXPECT_FALSE(segments.segment_containing({0.5, 0.5}));  // inside the domain
  for (const topology::InputSegment2 side : {topology::InputSegment2{{1.0, 0.1}, {1.1, 1.05}},
                                             topology::InputSegment2{{0.0, 0.0}, {1.0, 0.1}}}) {
    const Point2d on = segments.point_on(side, 1.0 / 3.0);
    const auto found = segments.segment_containing(on);
    ASSERT_TRUE(found);
    EXPECT_EQ(*found, side);
    // 1e-12 off it, far more than the rounding allows: inside no segment.
    EXPECT_FALSE(segments.segment_containing({on[0] + 1e-12, on[1] - 1e-12}));
  }
}

// A mesh edge that is a whole input segment (both ends domain vertices) is split on it too.
TEST(imp_BoundarySliding, InsertSplitsAWholeSegmentEdgeOnTheSegment) {
  const PlanarDomain domain = slanted_quadrilateral();
  const io::MeshData domain_data = generators::to_mesh_data(domain);
  // The quadrilateral as two triangles, its sides labelled as the domain's segments.
  TriangleMesh2 mesh;
  std::vector<VertexId> v;
  for (const auto& p : domain.points) v.push_back(mesh.add_vertex({p.x, p.y}));
  mesh.add_element({v[0], v[1], v[2]});
  mesh.add_element({v[0], v[2], v[3]});
  for (std::size_t i = 0; i < 4; ++i) mesh.set_facet_label({v[i], v[(i + 1) % 4]}, 1);
  ASSERT_TRUE(imp_testing::certify(mesh, &domain_data).valid);
  const auto options = options_with(domain, [](const Point2d& a, const Point2d& b, const Point2d& c) {
    return 1.0 / (std::hypot(b[0] - a[0], b[1] - a[1]) + std::hypot(c[0] - b[0], c[1] - b[1]) +
                  std::hypot(a[0] - c[0], a[1] - c[1]));  // prefers small triangles
  });
  int split = 0;
  const auto slots = static_cast<std::uint32_t>(mesh.element_slot_count());  // a bounded number of tries
  for (std::uint32_t s = 0; s < slots; ++s)
    for (int i = 0; i < 3; ++i)
      if (mesh.is_live(topology::ElementId{s}) && mesh.neighbour(topology::ElementId{s}, i) == topology::no_element)
        split += topology::try_insert_on_edge(mesh, topology::ElementId{s}, i, options).has_value();
  EXPECT_GE(split, 2);
  EXPECT_EQ(boundary_vertices(mesh).size(), 4u + static_cast<std::size_t>(split));
  const auto report = imp_testing::certify(mesh, &domain_data);
  EXPECT_TRUE(report.valid) << report.finding.message;
}

// Algorithm 35 with a size that is coarse on the left and fine on the right: boundary vertices
// go on the left (collapse along the segments) and come on the right (insert on boundary edges).
TEST(imp_BoundarySliding, Algorithm35CollapsesAndInsertsAlongSegmentsCertifiedAndDeterministic) {
  const PlanarDomain domain = slanted_quadrilateral();
  const io::MeshData domain_data = generators::to_mesh_data(domain);
  const TriangleMesh2 start = start_mesh(domain, 0.1);
  generators::ImprovementOptions2 options;
  options.size.size_function = [](const generators::Point2& p) { return 0.25 - 0.2 * std::clamp(p.x, 0.0, 1.0); };
  options.input_segments = generators::input_segments_of(domain);
  options.max_operations = imp_testing::sanitizer_divisor == 1 ? 4000 : 1500;
  const auto count_where = [](const TriangleMesh2& m, bool left) {
    std::size_t n = 0;
    for (const VertexId v : boundary_vertices(m)) n += (m.point(v)[0] < 0.3) == left && (m.point(v)[0] > 0.8) != left;
    return n;
  };
  TriangleMesh2 first = start, second = start;
  const auto stats = generators::improve_quality_2(first, options);
  generators::improve_quality_2(second, options);
  EXPECT_GT(stats.final_worst, stats.initial_worst);
  EXPECT_LT(count_where(first, true), count_where(start, true));    // coarser on the left
  EXPECT_GT(count_where(first, false), count_where(start, false));  // finer on the right
  const auto report = imp_testing::certify(first, &domain_data);
  EXPECT_TRUE(report.valid) << report.finding.message;
  const auto a = topology::to_mesh_data(first), b = topology::to_mesh_data(second);
  EXPECT_EQ(a.coordinates, b.coordinates);
  EXPECT_EQ(a.triangles, b.triangles);
}

}  // namespace
}  // namespace certimesh
