// Invalid meshes, each made by ONE mutation of a valid jittered Kuhn grid, are rejected with
// the reason the mutation implies (README.md has the mapping and the argument for each) and
// at the mutated place. The oracle first confirms what the mutation did geometrically
// (which elements turned over or flat, that no two vertices coincide), so that a failure is
// the certificate's and not the mutation's.
#include "rc_support.h"

namespace certimesh::testing {
namespace {

using certificate::Defect;

// A boundary vertex off the domain boundary is vertex_off_domain_boundary; facet_off is only
// for facets whose vertices are all on the domain boundary (defect.h).
const Defect kOffDomain = Defect::vertex_off_domain_boundary;

std::uint64_t draw_choice() { return *rc::gen::inRange<std::uint64_t>(0, 1u << 20); }

template <typename Mutation>
fuzz::MutationSite mutate(io::MeshData& mesh, Mutation&& mutation) {
  const std::optional<fuzz::MutationSite> site = mutation(mesh);
  RC_PRE(site.has_value());
  return *site;
}

void inverted_element(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  mutate(g.mesh, [&](io::MeshData& m) { return fuzz::invert_element(m, c); });
  RC_PRE(!has_coincident_vertices(g.mesh));
  RC_PRE(elements_with_sign(g.mesh, 0).empty());  // flat would be reported first
  const std::vector<std::int64_t> negative = elements_with_sign(g.mesh, -1);
  RC_ASSERT(!negative.empty());
  const fuzz::MutationSite any_negative{negative, {}};
  expect_rejected(g.mesh, nullptr, Defect::inverted_element, &any_negative);
}

void flat_element(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::flatten_element(m, c); });
  RC_PRE(!has_coincident_vertices(g.mesh));
  const std::vector<std::int64_t> flat = elements_with_sign(g.mesh, 0);
  RC_ASSERT(std::find(flat.begin(), flat.end(), site.elements[0]) != flat.end());
  const fuzz::MutationSite any_flat{flat, {}};
  expect_rejected(g.mesh, nullptr, Defect::flat_element, &any_flat);
}

void t_junction(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::split_facet_one_side(m, c); });
  RC_ASSERT(all_elements_positive(g.mesh));
  expect_rejected(g.mesh, nullptr, Defect::t_junction, &site);
}

void overlapping_element(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  mutate(g.mesh, [&](io::MeshData& m) { return fuzz::add_element_inside(m, c); });
  RC_ASSERT(all_elements_positive(g.mesh));
  RC_PRE(!has_coincident_vertices(g.mesh));
  // A global defect: the interface does not say which element names it.
  expect_rejected(g.mesh, nullptr, Defect::multiple_cover, nullptr);
}

void double_cover(int dim) {
  // No hole: the half-size copy would cross the hole's boundary (a boundary intersection).
  DrawnGrid g = draw_grid(dim);
  fuzz::add_scaled_copy(g.mesh);
  RC_ASSERT(all_elements_positive(g.mesh));
  RC_ASSERT(!has_coincident_vertices(g.mesh));
  expect_rejected(g.mesh, nullptr, Defect::multiple_cover, nullptr);
  expect_rejected(g.mesh, &g.domain, Defect::multiple_cover, nullptr);
}

void missing_element(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::remove_interior_element(m, c); });
  // Alone, a mesh with a cavity is a valid mesh of the region its boundary encloses.
  expect_accepted(g.mesh, nullptr);
  // The cavity's vertices are boundary vertices off the domain, at a vertex of the removed element.
  expect_rejected(g.mesh, &g.domain, kOffDomain, &site);
}

void corner_cut(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  RC_ASSERT(fuzz::cut_box_corner(g.mesh).has_value());
  expect_accepted(g.mesh, nullptr);
  // Every boundary vertex is still on the domain boundary; the new facets are not.
  expect_rejected(g.mesh, &g.domain, Defect::facet_off_domain_boundary, nullptr);
}

void duplicated_element(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const std::uint64_t perm = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::duplicate_element(m, c, perm); });
  expect_rejected(g.mesh, nullptr, Defect::duplicate_element, &site);
}

void boundary_vertex_off_domain(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const bool outward = *rc::gen::arbitrary<bool>();
  const fuzz::MutationSite site =
      mutate(g.mesh, [&](io::MeshData& m) { return fuzz::move_boundary_vertex_off(m, c, outward); });
  RC_ASSERT(all_elements_positive(g.mesh));
  expect_accepted(g.mesh, nullptr);  // alone, still a valid mesh of a slightly different region
  // That vertex is a boundary vertex on no domain segment/face.
  expect_rejected(g.mesh, &g.domain, kOffDomain, nullptr);
  const certificate::Report r = certificate::check_mesh(g.mesh, &g.domain);
  RC_ASSERT(r.finding.vertex == -1 || r.finding.vertex == site.vertices[0]);
}

void boundary_element_removed(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::remove_boundary_element(m, c); });
  expect_accepted(g.mesh, nullptr);
  // The exposed interior vertex is a boundary vertex off the domain.
  expect_rejected(g.mesh, &g.domain, kOffDomain, &site);
}

void pinched_boundary(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  mutate(g.mesh, [&](io::MeshData& m) { return fuzz::remove_element_pinching_boundary(m, c); });
  // A cavity touching the boundary at one vertex: a valid pinch (design decision 8) of a
  // region the domain does not have; the cavity's other vertices are off the domain.
  expect_accepted(g.mesh, nullptr);
  expect_rejected(g.mesh, &g.domain, kOffDomain, nullptr);
}

void non_manifold_facet(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::add_third_element_on_facet(m, c); });
  RC_PRE(!has_coincident_vertices(g.mesh));
  expect_rejected(g.mesh, nullptr, Defect::non_manifold_facet, &site);
}

void mixed_orientation(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::swap_two_vertices(m, c); });
  expect_rejected(g.mesh, nullptr, Defect::inconsistent_orientation, &site);
}

void unused_vertex(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const fuzz::MutationSite site = fuzz::add_unused_vertex(g.mesh);
  expect_rejected(g.mesh, nullptr, Defect::unused_vertex, &site);
}

void duplicate_vertex(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::add_duplicate_vertex(m, c); });
  const fuzz::MutationSite vertices_only{{}, site.vertices};
  expect_rejected(g.mesh, nullptr, Defect::duplicate_vertex, &vertices_only);
}

void repeated_vertex(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::repeat_vertex_in_element(m, c); });
  expect_rejected(g.mesh, nullptr, Defect::repeated_vertex, &site);
}

void index_out_of_range(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const std::uint64_t c = draw_choice();
  const fuzz::MutationSite site = mutate(g.mesh, [&](io::MeshData& m) { return fuzz::index_out_of_range(m, c); });
  expect_rejected(g.mesh, nullptr, Defect::index_out_of_range, &site);
}

void non_finite_coordinate(int dim) {
  DrawnGrid g = draw_grid(dim, true, true);
  const fuzz::MutationSite site = fuzz::make_coordinate_non_finite(g.mesh, draw_choice());
  expect_rejected(g.mesh, nullptr, Defect::non_finite_coordinate, &site);
}

#define CERTIMESH_MUTATION_PROPS(name)                            \
  RC_GTEST_PROP(Mutations, name##2d, ()) { name(2); }             \
  RC_GTEST_PROP(Mutations, name##3d, ()) { name(3); }

CERTIMESH_MUTATION_PROPS(inverted_element)
CERTIMESH_MUTATION_PROPS(flat_element)
CERTIMESH_MUTATION_PROPS(t_junction)
CERTIMESH_MUTATION_PROPS(overlapping_element)
CERTIMESH_MUTATION_PROPS(double_cover)
CERTIMESH_MUTATION_PROPS(missing_element)
CERTIMESH_MUTATION_PROPS(corner_cut)
CERTIMESH_MUTATION_PROPS(duplicated_element)
CERTIMESH_MUTATION_PROPS(boundary_vertex_off_domain)
CERTIMESH_MUTATION_PROPS(boundary_element_removed)
CERTIMESH_MUTATION_PROPS(pinched_boundary)
CERTIMESH_MUTATION_PROPS(non_manifold_facet)
CERTIMESH_MUTATION_PROPS(mixed_orientation)
CERTIMESH_MUTATION_PROPS(unused_vertex)
CERTIMESH_MUTATION_PROPS(duplicate_vertex)
CERTIMESH_MUTATION_PROPS(repeated_vertex)
CERTIMESH_MUTATION_PROPS(index_out_of_range)
CERTIMESH_MUTATION_PROPS(non_finite_coordinate)

}  // namespace
}  // namespace certimesh::testing
