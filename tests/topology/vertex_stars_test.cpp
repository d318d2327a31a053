// Vertex stars (CSR inverse incidence, Algorithm 3) and edge/facet extraction, against brute
// force: the identities of digest A §6.2 "Incidence and CSR" on random incidences, and stars,
// neighbours and interior/boundary classes on meshes recomputed by scanning every element.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "certimesh/topology/csr.h"
#include "certimesh/topology/mesh_entities.h"
#include "certimesh/topology/star_walk.h"
#include "certimesh/topology/vertex_stars.h"
#include "fixtures.h"

namespace certimesh::topology {
namespace {

const bool rc_seed_fixed = [] {
  setenv("RC_PARAMS", "seed=20261129 max_success=200", 0);
  return true;
}();

RC_GTEST_PROP(Csr, InvertThenInvertBackIsTheIdentity, ()) {
  const std::size_t arity = *rc::gen::inRange<std::size_t>(2, 5);
  const std::size_t columns = *rc::gen::inRange<std::size_t>(arity, 30);
  const std::size_t items = *rc::gen::inRange<std::size_t>(0, 60);
  std::vector<std::uint32_t> incidence;
  for (std::size_t s = 0; s < items * arity; ++s)
    incidence.push_back(*rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(columns)));
  const Csr inverse = invert_incidence(incidence, arity, columns);
  // Row lengths sum to arity * items; every (item, column) pair sits in exactly one row,
  // as often as the item names the column; rows are in increasing item order.
  RC_ASSERT(inverse.row_count() == columns);
  RC_ASSERT(inverse.entries.size() == arity * items);
  std::multiset<std::pair<std::uint32_t, std::uint32_t>> expected, found;
  for (std::size_t s = 0; s < items; ++s)
    for (std::size_t k = 0; k < arity; ++k) expected.emplace(incidence[s * arity + k], std::uint32_t(s));
  for (std::size_t c = 0; c < columns; ++c) {
    const auto row = inverse.row(c);
    RC_ASSERT(std::is_sorted(row.begin(), row.end()));
    for (const std::uint32_t s : row) found.emplace(std::uint32_t(c), s);
  }
  RC_ASSERT(found == expected);
  // Inverting back gives every item its columns again (as a multiset, in column order).
  const Csr back = invert_csr(inverse, items);
  RC_ASSERT(back.row_count() == items);
  for (std::size_t s = 0; s < items; ++s) {
    std::vector<std::uint32_t> original(incidence.begin() + static_cast<std::ptrdiff_t>(s * arity),
                                        incidence.begin() + static_cast<std::ptrdiff_t>((s + 1) * arity));
    std::sort(original.begin(), original.end());
    const auto row = back.row(s);
    RC_ASSERT(std::vector<std::uint32_t>(row.begin(), row.end()) == original);
  }
}

TEST(Csr, SkipsDeadItemsAndRefusesOutOfRangeColumns) {
  const std::vector<std::uint32_t> incidence{0, 1, 2, 1, 2, 3, 2, 3, 0};
  const std::vector<std::uint8_t> live{1, 0, 1};
  const Csr inverse = invert_incidence(incidence, 3, 4, live);
  EXPECT_EQ(inverse.offsets, (std::vector<std::uint32_t>{0, 2, 3, 5, 6}));
  EXPECT_EQ(inverse.entries, (std::vector<std::uint32_t>{0, 2, 0, 0, 2, 2}));
  EXPECT_THROW(invert_incidence(incidence, 3, 3), std::invalid_argument);
}

// Brute force: scan every live element for every question.
template <class Mesh>
void expect_stars_and_entities_match_brute_force(const Mesh& mesh) {
  const VertexStars<Mesh> stars(mesh);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_elements;
  std::map<std::uint32_t, std::vector<std::uint32_t>> star;
  std::map<std::vector<std::uint32_t>, int> facet_elements;
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    if (!mesh.is_live(ElementId{e})) continue;
    const auto v = mesh.vertices(ElementId{e});
    for (std::size_t a = 0; a < v.size(); ++a) {
      star[v[a].value].push_back(e);
      for (std::size_t b = a + 1; b < v.size(); ++b)
        ++edge_elements[std::minmax(v[a].value, v[b].value)];
      std::vector<std::uint32_t> facet;
      for (std::size_t k = 0; k < v.size(); ++k)
        if (k != a) facet.push_back(v[k].value);
      std::sort(facet.begin(), facet.end());
      ++facet_elements[facet];
    }
  }
  // Boundary edges: those lying on a facet held once.
  std::set<std::pair<std::uint32_t, std::uint32_t>> boundary_edges;
  for (const auto& [facet, count] : facet_elements)
    if (count == 1)
      for (std::size_t a = 0; a < facet.size(); ++a)
        for (std::size_t b = a + 1; b < facet.size(); ++b) boundary_edges.emplace(facet[a], facet[b]);

  for (std::uint32_t v = 0; v < mesh.vertex_slot_count(); ++v) {
    const auto row = stars.elements_around(VertexId{v});
    EXPECT_EQ(std::vector<std::uint32_t>(row.begin(), row.end()), star[v]) << "star of " << v;
    std::vector<VertexId> neighbours;
    for (const auto& [edge, count] : edge_elements) {
      if (edge.first == v) neighbours.push_back(VertexId{edge.second});
      if (edge.second == v) neighbours.push_back(VertexId{edge.first});
    }
    std::sort(neighbours.begin(), neighbours.end());
    EXPECT_EQ(stars.vertex_neighbours(VertexId{v}), neighbours) << "neighbours of " << v;
  }
  const std::vector<EdgeRecord> edges = extract_edges(mesh, stars);
  ASSERT_EQ(edges.size(), edge_elements.size());
  auto expected = edge_elements.begin();
  for (const EdgeRecord& e : edges) {
    EXPECT_EQ(std::pair(e.a.value, e.b.value), expected->first);
    EXPECT_EQ(e.element_count, expected->second);
    EXPECT_EQ(e.boundary, boundary_edges.count(expected->first) == 1) << e.a.value << "-" << e.b.value;
    ++expected;
  }
  std::size_t boundary_facets = 0, interior_facets = 0;
  for (const auto& [facet, count] : facet_elements) ++(count == 1 ? boundary_facets : interior_facets);
  std::size_t found_boundary = 0, found_interior = 0;
  for (const FacetRecord& f : extract_facets(mesh)) ++(f.boundary() ? found_boundary : found_interior);
  EXPECT_EQ(found_boundary, boundary_facets);
  EXPECT_EQ(found_interior, interior_facets);
}

TEST(VertexStars, MatchBruteForceOnGridsWithHolesAndFreedSlots) {
  TriangleMesh2 grid = testing::grid2(6, 5, {testing::Cell2{2, 2}});
  expect_stars_and_entities_match_brute_force(grid);
  for (std::uint32_t e = 3; e < grid.element_slot_count(); e += 11) grid.remove_element(ElementId{e});
  expect_stars_and_entities_match_brute_force(grid);

  TetrahedralMesh3 cube = testing::kuhn_grid3(3, 2, 2, {testing::Cell3{1, 1, 1}});
  expect_stars_and_entities_match_brute_force(cube);
  for (std::uint32_t e = 0; e < cube.element_slot_count(); e += 5) cube.remove_element(ElementId{e});
  expect_stars_and_entities_match_brute_force(cube);

  expect_stars_and_entities_match_brute_force(testing::boundary_surface(testing::kuhn_grid3(2, 2, 1)));
}

TEST(VertexStars, IncidentElementHintIsInTheStar) {
  TetrahedralMesh3 mesh = testing::kuhn_grid3(3, 3, 3);
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); e += 3) mesh.remove_element(ElementId{e});
  const VertexStars<TetrahedralMesh3> stars(mesh);
  for (std::uint32_t v = 0; v < mesh.vertex_slot_count(); ++v) {
    const auto row = stars.elements_around(VertexId{v});
    const ElementId hint = mesh.incident_element(VertexId{v});
    EXPECT_EQ(mesh.incident_element_count(VertexId{v}), row.size());
    if (hint != no_element) {
      EXPECT_TRUE(std::find(row.begin(), row.end(), hint.value) != row.end());
    }
  }
}

// Whether the elements of v's star (brute force) are connected through facets through v:
// two elements of the star are adjacent when they share S vertices (v is always one of them).
template <class Mesh>
bool star_is_facet_connected(const Mesh& mesh, const std::vector<std::uint32_t>& star) {
  if (star.empty()) return true;
  std::vector<std::uint32_t> reached{star[0]};
  for (std::size_t next = 0; next < reached.size(); ++next) {
    const auto a = mesh.vertices(ElementId{reached[next]});
    for (const std::uint32_t other : star) {
      if (std::find(reached.begin(), reached.end(), other) != reached.end()) continue;
      const auto b = mesh.vertices(ElementId{other});
      int shared = 0;
      for (const VertexId x : a) shared += std::find(b.begin(), b.end(), x) != b.end() ? 1 : 0;
      if (shared == Mesh::simplex_dimension) reached.push_back(other);
    }
  }
  return reached.size() == star.size();
}

// walk_star (local, from the hint) against the CSR star: equal when the star is connected
// through facets, a non-empty part of it otherwise.
template <class Mesh>
void expect_walks_match_stars(const Mesh& mesh, std::size_t& compared) {
  const VertexStars<Mesh> stars(mesh);
  for (std::uint32_t v = 0; v < mesh.vertex_slot_count(); ++v) {
    const auto row = stars.elements_around(VertexId{v});
    const std::vector<std::uint32_t> star(row.begin(), row.end());
    std::vector<std::uint32_t> walked;
    for (const ElementId e : walk_star(mesh, VertexId{v})) walked.push_back(e.value);
    EXPECT_TRUE(std::includes(star.begin(), star.end(), walked.begin(), walked.end())) << "vertex " << v;
    if (star_is_facet_connected(mesh, star)) {
      EXPECT_EQ(walked, star) << "vertex " << v;
      ++compared;
    }
  }
}

TEST(StarWalk, FindsTheWholeStarWhenItIsConnected) {
  std::size_t compared = 0;
  expect_walks_match_stars(testing::grid2(5, 4, {testing::Cell2{2, 2}}), compared);
  expect_walks_match_stars(testing::kuhn_grid3(3, 3, 3, {testing::Cell3{1, 1, 1}}), compared);
  expect_walks_match_stars(testing::torus(4, 5), compared);
  TetrahedralMesh3 holed = testing::kuhn_grid3(3, 3, 2);
  for (std::uint32_t e = 0; e < holed.element_slot_count(); e += 4) holed.remove_element(ElementId{e});
  expect_walks_match_stars(holed, compared);
  EXPECT_GT(compared, 100u);
}

}  // namespace
}  // namespace certimesh::topology
