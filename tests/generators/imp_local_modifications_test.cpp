// The five 2D local modifications on random valid meshes (jittered Kuhn grids, with or
// without a hole, with material interfaces and labelled cuts): after every committed
// operation the independent certificate accepts the mesh against its domain, the boundary
// edges and the constrained interior edges are the same (same coordinates), the total area is
// unchanged exactly (GMP rationals), and the worst quality of what changed rose strictly.
// With straight-boundary coarsening on, boundary edges may merge; the rest still holds.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>

#include "certimesh/topology/local_modifications_2.h"
#include "certimesh/topology/quality.h"
#include "imp_fixtures.h"

namespace certimesh {
namespace {

using imp_testing::ElementId;
using imp_testing::TriangleMesh2;
using topology::LocalChange2;
using topology::LocalModificationOptions2;
using topology::Point2d;

constexpr const char* operation_names[] = {"insert", "flip", "shift", "collapse", "delete"};

std::optional<LocalChange2> apply(TriangleMesh2& mesh, int operation, ElementId e, int local,
                                  const LocalModificationOptions2& options) {
  const auto vertex = mesh.vertices(e)[static_cast<std::size_t>(local)];
  switch (operation) {
    case 0: return topology::try_insert_on_edge(mesh, e, local, options);
    case 1: return topology::try_flip(mesh, e, local, options);
    case 2: return topology::try_node_shift(mesh, vertex, options);
    case 3: return topology::try_edge_collapse(mesh, e, local, options);
    default: return topology::try_node_deletion(mesh, vertex, options);
  }
}

std::vector<ElementId> live_elements(const TriangleMesh2& mesh) {
  std::vector<ElementId> live;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s)
    if (mesh.is_live(ElementId{s})) live.push_back(ElementId{s});
  return live;
}

double quality_of(const TriangleMesh2& mesh, ElementId e, const LocalModificationOptions2& options) {
  const auto v = mesh.vertices(e);
  return options.quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]));
}

LocalModificationOptions2 options_with_size(double h, topology::CollapseReference reference) {
  LocalModificationOptions2 options;
  options.collapse_reference = reference;
  if (h == 0.0)
    options.quality = [](const Point2d& a, const Point2d& b, const Point2d& c) {
      return topology::triangle_quality(a, b, c);
    };
  else
    options.quality = [h](const Point2d& a, const Point2d& b, const Point2d& c) {
      return topology::size_aware_triangle_quality(a, b, c, h);
    };
  return options;
}

// Materials 1 and 2 left and right of x = nx/2 (an interface), and a few interior edges
// labelled 9 (cuts).
void add_constraints(TriangleMesh2& mesh, int nx) {
  for (const ElementId e : live_elements(mesh)) {
    const auto v = mesh.vertices(e);
    const double x = (mesh.point(v[0])[0] + mesh.point(v[1])[0] + mesh.point(v[2])[0]) / 3.0;
    mesh.set_label(e, x < nx / 2 ? 1 : 2);
  }
  const auto live = live_elements(mesh);
  const auto cut = *rc::gen::container<std::vector<std::size_t>>(3, rc::gen::inRange<std::size_t>(0, live.size()));
  for (const std::size_t k : cut)
    if (mesh.neighbour(live[k], 0) != topology::no_element) mesh.set_facet_label(mesh.facet(live[k], 0), 9);
}

RC_GTEST_PROP(imp_LocalModifications, CommittedOperationsKeepMeshValidBoundaryAreaAndImprove, ()) {
  fuzz::GridSpec grid;
  grid.cells = {*rc::gen::inRange(2, 9), *rc::gen::inRange(2, 9), 1};
  grid.jitter_seed = *rc::gen::inRange<std::uint64_t>(1, 1u << 30);
  if (grid.cells[0] >= 4 && grid.cells[1] >= 4 && *rc::gen::arbitrary<bool>())
    grid.hole = fuzz::cell_block_2d(1, 1, 2, 3);
  const io::MeshData domain = fuzz::square_domain(grid);
  TriangleMesh2 mesh = imp_testing::to_mesh(fuzz::kuhn_grid(grid));
  if (*rc::gen::arbitrary<bool>()) add_constraints(mesh, grid.cells[0]);
  const double h = *rc::gen::element(0.0, 0.4, 1.0, 2.5);
  auto options = options_with_size(
      h, *rc::gen::element(topology::CollapseReference::survivors_only,
                           topology::CollapseReference::survivors_and_removed));
  // With coarsening the boundary edges may merge along straight sides: the certificate with the
  // domain and the exact area then decide that the boundary is still the same point set.
  options.coarsen_straight_boundary = *rc::gen::arbitrary<bool>();

  const auto boundary = imp_testing::boundary_edges(mesh);
  const auto constrained = imp_testing::labelled_edges(mesh);
  const mpq_class area = imp_testing::twice_signed_area(mesh);
  std::map<std::string, int> commits;
  for (int step = 0; step < 150 / imp_testing::sanitizer_divisor; ++step) {
    const auto live = live_elements(mesh);
    const ElementId e = live[*rc::gen::inRange<std::size_t>(0, live.size())];
    const int operation = *rc::gen::inRange(0, 5);
    const int local = *rc::gen::inRange(0, 3);
    std::map<std::uint32_t, double> before;
    for (const ElementId x : live) before[x.value] = quality_of(mesh, x, options);
    const auto change = apply(mesh, operation, e, local, options);
    if (!change) continue;
    ++commits[operation_names[operation]];
    double q0 = 2.0, q1 = 2.0;
    for (const ElementId x : change->removed) q0 = std::min(q0, before.at(x.value));
    for (const ElementId x : change->added) q1 = std::min(q1, quality_of(mesh, x, options));
    RC_ASSERT(q1 > q0);
    const auto report = imp_testing::certify(mesh, &domain);
    if (!report.valid) RC_FAIL(std::string(operation_names[operation]) + ": " + report.finding.message);
    if (!options.coarsen_straight_boundary) RC_ASSERT(imp_testing::boundary_edges(mesh) == boundary);
    RC_ASSERT(imp_testing::labelled_edges(mesh) == constrained);
    RC_ASSERT(imp_testing::twice_signed_area(mesh) == area);
  }
  for (const auto& [name, count] : commits) RC_CLASSIFY(count > 0, name);
}

}  // namespace
}  // namespace certimesh
