// The certificate against TetGen-style 3D domains (MeshData::facets: planar polygons, facet
// holes, internal facets, regions), on hand-built Kuhn grids whose verdicts are derived by hand:
// the grid tiles the cube; its faces are cut along one diagonal, so a domain of quads is covered
// whichever diagonal the certificate's own cut of the quad uses (the mirrored grid uses the
// other one); the wall x = 1 of a 2-cube grid is a union of mesh faces.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "unit_meshes.h"

namespace certimesh::certificate::test {
namespace {

using io::FacetList;

void add_facet(FacetList& f, std::initializer_list<std::vector<Index>> polygons, std::vector<double> holes = {}) {
  for (const auto& p : polygons) {
    f.corners.insert(f.corners.end(), p.begin(), p.end());
    f.polygon_end.push_back(f.corners.size());
  }
  f.facet_end.push_back(f.polygon_end.size());
  f.holes.insert(f.holes.end(), holes.begin(), holes.end());
  f.hole_end.push_back(f.holes.size() / 3);
}

// The points (x, y, z) for x in {0, 1, 2}, y, z in {0, 2}: index x + 3 y/2 + 6 z/2.
Index p(int x, int y, int z) { return static_cast<Index>(x + 3 * (y / 2) + 6 * (z / 2)); }

// The cube [0, 2]^3 with the points of the plane x = 1 on its edges: the faces y = 0, y = 2,
// z = 0 and z = 2 are hexagons through them (collinear corners), x = 0 and x = 2 are quads;
// with `wall`, the square x = 1 is an internal facet and the hexagons are two quads each.
MeshData two_cell_domain(bool wall) {
  MeshData d;
  d.dimension = 3;
  for (int z : {0, 2})
    for (int y : {0, 2})
      for (int x : {0, 1, 2}) append(d.coordinates, {double(x), double(y), double(z)});
  FacetList& f = d.facets;
  add_facet(f, {{p(0, 0, 0), p(0, 2, 0), p(0, 2, 2), p(0, 0, 2)}});
  add_facet(f, {{p(2, 0, 0), p(2, 0, 2), p(2, 2, 2), p(2, 2, 0)}});
  for (int fixed = 0; fixed < 4; ++fixed) {  // y = 0, y = 2, z = 0, z = 2
    auto at = [&](int x, int s) { return fixed < 2 ? p(x, fixed == 0 ? 0 : 2, s) : p(x, s, fixed == 2 ? 0 : 2); };
    if (wall) {
      add_facet(f, {{at(0, 0), at(1, 0), at(1, 2), at(0, 2)}, {at(1, 0), at(2, 0), at(2, 2), at(1, 2)}});
    } else {
      add_facet(f, {{at(0, 0), at(1, 0), at(2, 0), at(2, 2), at(1, 2), at(0, 2)}});
    }
  }
  if (wall) add_facet(f, {{p(1, 0, 0), p(1, 2, 0), p(1, 2, 2), p(1, 0, 2)}});
  return d;
}

Report expect_defect(const MeshData& m, const MeshData& d, Defect defect, const std::string& phrase = "") {
  const Report r = check_mesh(m, &d);
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(defect)) << r.finding.message;
  EXPECT_NE(r.finding.message.find(phrase), std::string::npos) << r.finding.message;
  return r;
}

MeshData mirrored(MeshData m) {  // x -> 2 - x, each tetrahedron turned back to positive
  for (std::size_t v = 0; v < m.coordinates.size(); v += 3) m.coordinates[v] = 2 - m.coordinates[v];
  for (std::size_t t = 0; t < m.tetrahedra.size(); t += 4) std::swap(m.tetrahedra[t + 2], m.tetrahedra[t + 3]);
  return m;
}

TEST(CertificateFacetDomain, KuhnGridTilesTheCubeOfPolygonsWhicheverDiagonalItsFacesUse) {
  const MeshData grid = kuhn_grid(2);
  expect_defect(grid, two_cell_domain(false), Defect::none);
  expect_defect(mirrored(grid), two_cell_domain(false), Defect::none);
  expect_defect(grid, two_cell_domain(true), Defect::none);  // the wall is a union of mesh faces
}

TEST(CertificateFacetDomain, RegionAttributesAgainstLabels) {
  MeshData grid = kuhn_grid(2);
  for (std::size_t t = 0; t < grid.tetrahedron_count(); ++t) {
    double x = 0;
    for (int k = 0; k < 4; ++k) x += grid.coordinates[3 * grid.tetrahedra[4 * t + std::size_t(k)]];
    grid.tetrahedron_labels.push_back(x < 4 ? 1 : 2);  // centroid left or right of x = 1
  }
  MeshData d = two_cell_domain(true);
  d.region_points = {0.5, 0.5, 0.5, 1.5, 0.5, 0.5};
  d.region_attributes = {1, 2};
  expect_defect(grid, d, Defect::none);
  MeshData swapped = grid;
  swapped.tetrahedron_labels[0] = 3 - swapped.tetrahedron_labels[0];
  expect_defect(swapped, d, Defect::region_label_mismatch, "tetrahedron 0 is labelled");
  MeshData real = d;
  real.region_attributes = {1, 2.5};  // a real attribute no integer label equals
  expect_defect(grid, real, Defect::region_label_mismatch, "whose attribute is 2.5");
  MeshData no_wall = two_cell_domain(false);  // one region: the two points disagree
  no_wall.region_points = d.region_points;
  no_wall.region_attributes = d.region_attributes;
  expect_defect(grid, no_wall, Defect::invalid_domain, "lie in one region");
  MeshData outside = d;
  outside.region_points = {0.5, 0.5, 0.5, 3, 0.5, 0.5};
  expect_defect(grid, outside, Defect::invalid_domain, "region point 1 is outside the solid");
}

TEST(CertificateFacetDomain, FacetsTheCertificateRefusesByName) {
  const MeshData grid = kuhn_grid(2);
  MeshData bent = two_cell_domain(false);
  bent.coordinates[3 * p(0, 2, 2) + 0] = 0.25;  // x = 0's quad is no longer planar
  expect_defect(grid, bent, Defect::invalid_domain, "facet 0 is not planar");
  MeshData nested = two_cell_domain(false);
  nested.coordinates.insert(nested.coordinates.end(), {0, 0.5, 0.5, 0, 1.5, 0.5, 0, 1.5, 1.5});
  nested.facets.corners.insert(nested.facets.corners.begin() + 4, {12, 13, 14});
  nested.facets.polygon_end.insert(nested.facets.polygon_end.begin() + 1, 7);
  for (std::size_t q = 2; q < nested.facets.polygon_end.size(); ++q) nested.facets.polygon_end[q] += 3;
  for (auto& e : nested.facets.facet_end) ++e;
  expect_defect(grid, nested, Defect::invalid_domain, "inside another of its polygons and no facet hole");
  MeshData segment = two_cell_domain(false);
  segment.facets.polygon_end[0] = 2;  // facet 0's first polygon keeps 2 corners, a new one the other 2
  segment.facets.polygon_end.insert(segment.facets.polygon_end.begin() + 1, 4);
  for (auto& e : segment.facets.facet_end) ++e;
  expect_defect(grid, segment, Defect::invalid_domain, "polygon of 2 corners");
}

// A hole point in the unbounded part of the domain's complement is a user error (decision 8).
TEST(CertificateFacetDomain, HolePointOutsideTheSolidIsRefused) {
  MeshData d = two_cell_domain(false);
  d.holes = {5, 1, 1};
  expect_defect(kuhn_grid(2), d, Defect::invalid_domain, "hole point 0 outside the solid");
}

}  // namespace
}  // namespace certimesh::certificate::test
