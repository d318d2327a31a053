// tetrahedralize_solid_3 (boundary recovery, issue 13 item 4) on the shapes that break the
// peers: the cube, a cube with a cavity, Schönhardt's prism (no tetrahedralization without a
// Steiner point), Chazelle-type notched polyhedra (grooves on top and bottom crossing at right
// angles), thin slabs, dihedral angles below 1 degree, scales 1e-9 and 1e12, facets one ulp
// off coplanar, random star-shaped polyhedra. Oracles: the independent certificate (check_mesh
// against the surface), the boundary faces compared with the input triangles (same vertex
// indices, bit-identical points, same orientation) and the exact volume (GMP) against the
// surface's own by the divergence theorem.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <cstring>

#include "br_surfaces_3.h"
#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/delaunay/boundary_recovery_3.h"
#include "certimesh/generators/delaunay/delaunay_3.h"
#include "certimesh/generators/delaunay/solid_regions_3.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::testing {
namespace {

// Fixed seed, fewer cases under the sanitizers (RC_PARAMS is read when the first property
// runs; the caller may override it).
const bool rc_seed_fixed = [] {
#if defined(__SANITIZE_ADDRESS__)
  return setenv("RC_PARAMS", "seed=1313 max_success=25", 0) == 0;
#else
  return setenv("RC_PARAMS", "seed=1313 max_success=200", 0) == 0;
#endif
}();

using generators::BoundaryRecoveryOptions;
using generators::SolidMesh3;
using generators::tetrahedralize_solid_3;

mpq_class det(const P3& a, const P3& b, const P3& c, const P3& d) {  // det[b - a, c - a, d - a]
  const mpq_class ux = mpq_class(b.x) - a.x, uy = mpq_class(b.y) - a.y, uz = mpq_class(b.z) - a.z;
  const mpq_class vx = mpq_class(c.x) - a.x, vy = mpq_class(c.y) - a.y, vz = mpq_class(c.z) - a.z;
  const mpq_class wx = mpq_class(d.x) - a.x, wy = mpq_class(d.y) - a.y, wz = mpq_class(d.z) - a.z;
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

// Six times the volume the surface encloses (divergence theorem, exact).
mpq_class surface_volume6(const Surface& s) {
  mpq_class v = 0;
  const P3 o{0, 0, 0};
  for (const Tri& t : s.triangles) v += det(o, s.points[t[0]], s.points[t[1]], s.points[t[2]]);
  return v;
}

Tri canonical(Tri t) {  // the rotation with the smallest index first (keeps orientation)
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}


// Meshes the surface and checks it against the oracles; returns the mesh.
SolidMesh3 mesh_and_check(const Surface& s, const BoundaryRecoveryOptions& options = {}) {
  const SolidMesh3 r = tetrahedralize_solid_3(s.points, s.triangles, options);
  io::MeshData mesh, domain;
  mesh.dimension = domain.dimension = 3;
  for (const P3& p : r.points) mesh.coordinates.insert(mesh.coordinates.end(), {p.x, p.y, p.z});
  for (const auto& t : r.tetrahedra) mesh.tetrahedra.insert(mesh.tetrahedra.end(), t.begin(), t.end());
  for (const P3& p : s.points) domain.coordinates.insert(domain.coordinates.end(), {p.x, p.y, p.z});
  for (const Tri& t : s.triangles) domain.triangles.insert(domain.triangles.end(), t.begin(), t.end());
  const certificate::Report report = certificate::check_mesh(mesh, &domain);
  EXPECT_TRUE(report.valid) << report.finding.message;

  // Input points kept, bit for bit, at their indices.
  EXPECT_GE(r.points.size(), s.points.size());
  for (std::size_t i = 0; i < s.points.size() && i < r.points.size(); ++i)
    EXPECT_TRUE(std::memcmp(&r.points[i], &s.points[i], sizeof(P3)) == 0) << "point " << i;

  // Positive tetrahedra, and the exact volume.
  mpq_class volume6 = 0;
  for (const auto& t : r.tetrahedra) {
    const mpq_class d = det(r.points[t[0]], r.points[t[1]], r.points[t[2]], r.points[t[3]]);
    EXPECT_GT(sgn(d), 0) << "a non-positive tetrahedron";
    volume6 += d;
  }
  // Exact only when the boundary is the input (rounded boundary Steiner points are off it).
  if (!options.keep_surface_steiner_points) {
    EXPECT_TRUE(volume6 == surface_volume6(s)) << "volume " << volume6.get_d() / 6 << " vs " << surface_volume6(s).get_d() / 6;
  }

  // The boundary: in the default mode exactly the input triangles, oriented alike.
  std::map<std::array<std::uint32_t, 3>, std::pair<int, Tri>> faces;
  static constexpr int local[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};  // outward
  for (const auto& t : r.tetrahedra)
    for (const auto& l : local) {
      Tri f{t[l[0]], t[l[1]], t[l[2]]};
      Tri key = f;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      entry.first++;
      entry.second = canonical(f);
    }
  std::set<Tri> boundary;
  for (const auto& [key, entry] : faces) {
    EXPECT_LE(entry.first, 2);
    if (entry.first == 1) boundary.insert(entry.second);
  }
  if (!options.keep_surface_steiner_points) {
    std::set<Tri> input;
    for (const Tri& t : s.triangles) input.insert(canonical(t));
    EXPECT_EQ(boundary.size(), input.size());
    EXPECT_TRUE(boundary == input) << "the boundary is not the input surface";
  }
  return r;
}

std::size_t steiner_points(const SolidMesh3& r, const Surface& s) { return r.points.size() - s.points.size(); }

TEST(br_Shapes, Cube) {
  const Surface s = notched_box(1, 1, 0, 0, 0, 0);
  EXPECT_EQ(s.triangles.size(), 12u);
  mesh_and_check(s);
}

TEST(br_Shapes, CubeWithCavity) {
  Surface s = notched_box(3, 3, 0, 0, 0, 0);
  Surface inner = notched_box(1, 1, 0, 0, 0, 0);
  inner.translate({1, 1, 1});
  s.append(inner, true);
  mesh_and_check(s);
}

TEST(br_Shapes, SchonhardtPrismNeedsASteinerPoint) {
  const Surface s = schonhardt();
  // It is Schönhardt's: each side diagonal is a reflex edge (the far corner of one side
  // triangle is outside the plane of the other), so no tetrahedron of its six corners fits.
  for (int i = 0; i < 3; ++i) {
    const Tri& t1 = s.triangles[2 + 2 * i];
    const Tri& t2 = s.triangles[3 + 2 * i];
    const P3& far = s.points[t2[2]];
    EXPECT_EQ(predicates::orient3d(s.points[t1[0]], s.points[t1[1]], s.points[t1[2]], far), predicates::Sign::negative)
        << "side " << i << " is not reflex";
  }
  EXPECT_GT(surface_volume6(s), 0);
  const SolidMesh3 r = mesh_and_check(s);
  EXPECT_GE(steiner_points(r, s), 1u);
}

TEST(br_Shapes, ChazellePolyhedron) {
  const Surface s = notched_box(1, 1, 1, 1, 0.25, 0.49);  // grooves crossing, tips 0.02 apart
  EXPECT_GT(surface_volume6(s), 0);
  const SolidMesh3 r = mesh_and_check(s);
  EXPECT_GT(steiner_points(r, s), 0u);
}

// Three grooves a side: with splits only (before the flips of proofs/boundary_recovery_3.md
// section 1a) stages 1-2 made about 10^4 Steiner points and stage 4 failed.
TEST(br_Shapes, ChazellePolyhedronThreeGrooves) { mesh_and_check(notched_box(1, 1, 3, 3, 0.5 / 4, 0.49)); }

// KNOWN FAILURE (proofs/boundary_recovery_3.md section 7): with six grooves a side stage 4
// finds no double position for one Steiner point (BoundaryRecoveryError, never a wrong mesh
// or a hang).
TEST(br_Shapes, DISABLED_ChazellePolyhedronSixGrooves) { mesh_and_check(notched_box(1, 1, 6, 6, 0.5 / 7, 0.49)); }

// With the Steiner points kept on the surface (--refine-surface) the same polyhedron is meshed
// and certified (stage 4, which fails above, is not run).
TEST(br_Shapes, ChazellePolyhedronThreeGroovesKeepingSurfaceSteinerPoints) {
#if defined(__SANITIZE_ADDRESS__)
  // 15,000 Steiner points: 85 s under the sanitizers, the longest test of that stage; the
  // Release stage runs it, and the one-groove cases cover the same code here.
  GTEST_SKIP() << "runs in the Release stage of the suite (scripts/test.sh)";
#endif
  BoundaryRecoveryOptions keep;
  keep.keep_surface_steiner_points = true;
  mesh_and_check(notched_box(1, 1, 3, 3, 0.5 / 4, 0.49), keep);
}

TEST(br_Shapes, ThinSlab) {
  mesh_and_check(notched_box(1, 1e-6, 0, 0, 0, 0));
  mesh_and_check(notched_box(1, 1e-6, 2, 2, 0.1, 0.4e-6));
}

void mesh_scaled(const Surface& s) {
  for (double k : {1e-9, 1e12}) {
    Surface scaled = s;
    scaled.scale(k);
    mesh_and_check(scaled);
  }
}

TEST(br_Shapes, ScaledNotchedPolyhedra) { mesh_scaled(notched_box(1, 1, 1, 1, 0.25, 0.45)); }

// Scaling the input by 2^k scales the output exactly; the same input gives the same output.
TEST(br_Shapes, ScalingByPowersOfTwoIsExactAndOutputIsDeterministic) {
  const Surface s = notched_box(1, 1, 1, 1, 0.25, 0.45);
  const SolidMesh3 r = tetrahedralize_solid_3(s.points, s.triangles);
  const SolidMesh3 again = tetrahedralize_solid_3(s.points, s.triangles);
  EXPECT_TRUE(r.tetrahedra == again.tetrahedra);
  EXPECT_EQ(std::memcmp(r.points.data(), again.points.data(), r.points.size() * sizeof(P3)), 0);
  for (double k : {0x1p-30, 0x1p40}) {
    Surface scaled = s;
    scaled.scale(k);
    const SolidMesh3 q = tetrahedralize_solid_3(scaled.points, scaled.triangles);
    ASSERT_EQ(q.points.size(), r.points.size());
    EXPECT_TRUE(q.tetrahedra == r.tetrahedra);
    for (std::size_t i = 0; i < r.points.size(); ++i)
      EXPECT_TRUE(q.points[i].x == r.points[i].x * k && q.points[i].y == r.points[i].y * k && q.points[i].z == r.points[i].z * k) << i;
  }
}

// Three grooves a side at the scales 1e-9 and 1e12 (a known failure before the flips).
TEST(br_Shapes, ScaledNotchedPolyhedraThreeGrooves) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "2 s in Release, ~30 s under the sanitizers; ScaledNotchedPolyhedra covers the same code here";
#endif
  mesh_scaled(notched_box(1, 1, 3, 3, 0.1, 0.45));
}

TEST(br_Shapes, DihedralAnglesBelowOneDegree) {
  for (double degrees : {0.9, 0.1, 0.01}) mesh_and_check(wedge_prism(degrees * M_PI / 180));
}

// Reflex V grooves whose walls meet at 0.6 degrees (a known failure before the flips).
TEST(br_Shapes, ReflexDihedralAnglesBelowOneDegree) { mesh_and_check(notched_box(1, 1, 2, 2, 0.005, 0.45)); }

// A cube whose top face is a fan around its centre raised (or lowered) by one ulp: four
// triangles one ulp off coplanar, a dihedral angle within 1e-16 of 180 degrees.
TEST(br_Shapes, NearlyCoplanarFacetsOneUlpOff) {
  for (const double z : {std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)}) {
    Surface s = notched_box(1, 1, 0, 0, 0, 0);
    std::vector<Tri> kept;
    std::vector<std::uint32_t> top;
    for (const Tri& t : s.triangles)
      if (s.points[t[0]].z == 1 && s.points[t[1]].z == 1 && s.points[t[2]].z == 1)
        continue;
      else
        kept.push_back(t);
    s.triangles = kept;
    const std::uint32_t c = s.add({0.5, 0.5, z});
    auto at = [&](double x, double y) {
      for (std::uint32_t i = 0; i < s.points.size(); ++i)
        if (s.points[i].x == x && s.points[i].y == y && s.points[i].z == 1) return i;
      return ~0u;
    };
    const std::uint32_t ring[4] = {at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
    for (int i = 0; i < 4; ++i) s.triangles.push_back({c, ring[i], ring[(i + 1) % 4]});
    mesh_and_check(s);
  }
}

TEST(br_Shapes, KeepSurfaceSteinerPoints) {
  BoundaryRecoveryOptions keep;
  keep.keep_surface_steiner_points = true;
  mesh_and_check(notched_box(1, 1, 0, 0, 0, 0), keep);
  mesh_and_check(schonhardt(), keep);
  mesh_and_check(notched_box(1, 1, 1, 1, 0.25, 0.49), keep);
}

TEST(br_Shapes, RefusesOpenSurfaces) {
  Surface s = notched_box(1, 1, 0, 0, 0, 0);
  s.triangles.pop_back();
  try {
    tetrahedralize_solid_3(s.points, s.triangles);
    ADD_FAILURE() << "an open surface was meshed";
  } catch (const generators::BoundaryRecoveryError& e) {
    EXPECT_NE(std::string(e.what()).find("is in 1 triangles"), std::string::npos) << e.what();
  }
}

// The hull of `points` (Delaunay3's boundary faces, outward), its vertices then moved along
// their rays from the origin by `radius`: a star-shaped polyhedron (each triangle stays in
// the cone it spans from the origin, and those cones tile space).
Surface star_shaped(const std::vector<P3>& sphere, const std::vector<double>& radius) {
  const generators::Delaunay3 dt(sphere);
  Surface s;
  std::map<std::uint32_t, std::uint32_t> index;
  static constexpr int local[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (std::uint32_t t = 0; t < dt.tetrahedron_slot_count(); ++t) {
    if (!dt.is_live(t)) continue;
    const auto c = dt.vertices(t);
    for (int i = 0; i < 4; ++i) {
      if (dt.neighbour(t, i) != generators::Delaunay3::none) continue;
      Tri f;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = c[static_cast<std::size_t>(local[i][k])];
        auto [it, added] = index.emplace(v, static_cast<std::uint32_t>(s.points.size()));
        if (added) {
          const P3& p = sphere[v];
          s.points.push_back({p.x * radius[v], p.y * radius[v], p.z * radius[v]});
        }
        f[static_cast<std::size_t>(k)] = it->second;
      }
      s.triangles.push_back(f);
    }
  }
  return s;
}

// Boxes with gridded faces and random diagonals (the shape where the Delaunay
// tetrahedralization's hull triangulation differs from the input's almost everywhere: the
// flips of proofs/boundary_recovery_3.md section 1a), grid lines at random decimal or dyadic
// coordinates, some boxes thin.
RC_GTEST_PROP(br_Random, GriddedBoxesWithRandomDiagonalsAreMeshedExactly, ()) {
  const auto seed = *rc::gen::arbitrary<std::uint32_t>();
  const bool dyadic = *rc::gen::arbitrary<bool>();
  std::mt19937 random(seed);
  std::array<std::vector<double>, 3> lines;
  for (auto& axis : lines) {
    const int n = *rc::gen::inRange(1, 6);
    std::set<double> values{0.0};
    while (values.size() < static_cast<std::size_t>(n) + 1)
      values.insert(dyadic ? std::ldexp(static_cast<double>(random() % 64 + 1), -4) : static_cast<double>(random() % 97 + 1) / 10);
    axis.assign(values.begin(), values.end());
  }
  const Surface s = gridded_box(lines, [&](int, std::size_t, std::size_t) { return random() % 2 == 1; });
  mesh_and_check(s);
}

RC_GTEST_PROP(br_Random, StarShapedAndConvexPolyhedraAreMeshedExactly, ()) {
  const int n = *rc::gen::inRange(4, 60);
  const auto seed = *rc::gen::arbitrary<std::uint32_t>();
  const bool convex = *rc::gen::arbitrary<bool>();
  const bool integer = *rc::gen::arbitrary<bool>();  // small integer coordinates: coplanarities
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.3, 1.0);
  std::vector<P3> sphere;
  std::set<std::array<double, 3>> seen;
  while (sphere.size() < static_cast<std::size_t>(n)) {
    P3 p{normal(random), normal(random), normal(random)};
    const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (l == 0) continue;
    p = {p.x / l, p.y / l, p.z / l};
    if (integer) p = {std::round(p.x * 4), std::round(p.y * 4), std::round(p.z * 4)};
    if (p.x == 0 && p.y == 0 && p.z == 0) continue;
    if (!seen.insert({p.x, p.y, p.z}).second) continue;
    sphere.push_back(p);
  }
  // All on one plane: no solid; skip.
  bool flat = true;
  for (std::size_t i = 3; i < sphere.size() && flat; ++i)
    for (std::size_t a = 0; a < 3 && flat; ++a)
      flat = predicates::orient3d(sphere[0], sphere[1], sphere[2], sphere[i]) == predicates::Sign::zero;
  RC_PRE(!flat);
  std::vector<double> radius(sphere.size(), 1.0);
  if (!convex)
    for (double& r : radius) r = integer ? std::round(uniform(random) * 4) / 2 + 1 : uniform(random);
  // The origin must be strictly inside for the radial move to keep a valid surface.
  const generators::Delaunay3 dt(sphere);
  const auto at = dt.locate({0, 0, 0});
  RC_PRE(at != generators::Delaunay3::none && !dt.is_ghost(at));
  bool origin_on_face = false;
  {
    const auto c = dt.vertices(at);
    for (int i = 0; i < 4; ++i) {
      const P3 q[3] = {sphere[c[(i + 1) % 4]], sphere[c[(i + 2) % 4]], sphere[c[(i + 3) % 4]]};
      origin_on_face |= predicates::orient3d(q[0], q[1], q[2], {0, 0, 0}) == predicates::Sign::zero;
    }
  }
  RC_PRE(!origin_on_face);
  const Surface s = star_shaped(sphere, radius);
  mesh_and_check(s);
  RC_ASSERT(!::testing::Test::HasFailure());
}

}  // namespace
}  // namespace certimesh::testing

namespace certimesh::testing {
namespace {

// TetGen's hole and region points (solid_regions_3.h) on a box [0, 4]^3 holding a box [1, 3]^3
// (both shells outward: an interface, as every nested shell of a .poly/.smesh is). Oracles:
// the exact volume of the kept tetrahedra and, per tetrahedron, which box its centroid is in
// (integer corners: the centroid is exact in doubles).
struct NestedBoxes {
  Surface surface;
  generators::Tetrahedralization3 solid;
  NestedBoxes() {
    surface = gridded_box({std::vector<double>{0, 4}, {0, 4}, {0, 4}}, [](int, std::size_t, std::size_t) { return true; });
    surface.append(gridded_box({std::vector<double>{1, 3}, {1, 3}, {1, 3}}, [](int, std::size_t, std::size_t) { return false; }), false);
    const SolidMesh3 r = tetrahedralize_solid_3(surface.points, surface.triangles);
    solid.points = r.points;
    solid.tetrahedra = r.tetrahedra;
  }
  bool in_inner_box(const std::array<std::uint32_t, 4>& t) const {
    double c[3] = {0, 0, 0};
    for (std::uint32_t v : t) c[0] += solid.points[v].x / 4, c[1] += solid.points[v].y / 4, c[2] += solid.points[v].z / 4;
    return c[0] > 1 && c[0] < 3 && c[1] > 1 && c[1] < 3 && c[2] > 1 && c[2] < 3;
  }
  mpq_class volume6() const {
    mpq_class v = 0;
    for (const auto& t : solid.tetrahedra) v += det(solid.points[t[0]], solid.points[t[1]], solid.points[t[2]], solid.points[t[3]]);
    return v;
  }
};

TEST(br_Regions, AHolePointRemovesItsRegionAndARegionPointLabelsIts) {
  NestedBoxes boxes;
  ASSERT_TRUE(boxes.volume6() == 6 * 64);
  const P3 hole{2, 2, 2}, region{0.5, 0.5, 0.5};
  const double attribute = 7;
  const auto counts = generators::apply_holes_and_regions_3(boxes.solid, boxes.surface.triangles, {&hole, 1}, {&region, 1}, {&attribute, 1});
  EXPECT_TRUE(boxes.volume6() == 6 * (64 - 8));
  EXPECT_GT(counts.hole_tetrahedra, 0u);
  ASSERT_EQ(boxes.solid.labels.size(), boxes.solid.tetrahedra.size());
  for (std::size_t t = 0; t < boxes.solid.tetrahedra.size(); ++t) {
    EXPECT_FALSE(boxes.in_inner_box(boxes.solid.tetrahedra[t])) << t;
    EXPECT_EQ(boxes.solid.labels[t], 7) << t;
  }
}

TEST(br_Regions, TwoRegionPointsLabelTheTwoSidesOfAnInterface) {
  NestedBoxes boxes;
  const P3 regions[2] = {{0.5, 0.5, 0.5}, {2, 2, 2}};
  const double attributes[2] = {7, -9};
  generators::apply_holes_and_regions_3(boxes.solid, boxes.surface.triangles, {}, regions, attributes);
  EXPECT_TRUE(boxes.volume6() == 6 * 64);
  for (std::size_t t = 0; t < boxes.solid.tetrahedra.size(); ++t)
    EXPECT_EQ(boxes.solid.labels[t], boxes.in_inner_box(boxes.solid.tetrahedra[t]) ? -9 : 7) << t;
}

TEST(br_Regions, PointsTheRegionsCannotTakeAreRefused) {
  const P3 outside{9, 9, 9}, on_face{1, 2, 2}, on_vertex{1, 1, 1}, in_hole{2, 2, 2}, inside{0.5, 0.5, 0.5};
  const double half = 0.5, one = 1;
  EXPECT_THROW({ NestedBoxes b; generators::apply_holes_and_regions_3(b.solid, b.surface.triangles, {&outside, 1}, {}, {}); },
               generators::SolidRegionsError);
  EXPECT_THROW({ NestedBoxes b; generators::apply_holes_and_regions_3(b.solid, b.surface.triangles, {&on_face, 1}, {}, {}); },
               generators::SolidRegionsError);
  // On a surface vertex: refused whichever tetrahedron round it is met first.
  EXPECT_THROW({ NestedBoxes b; generators::apply_holes_and_regions_3(b.solid, b.surface.triangles, {&on_vertex, 1}, {}, {}); },
               generators::SolidRegionsError);
  EXPECT_THROW({ NestedBoxes b; generators::apply_holes_and_regions_3(b.solid, b.surface.triangles, {&in_hole, 1}, {&in_hole, 1}, {&one, 1}); },
               generators::SolidRegionsError);
  EXPECT_THROW({ NestedBoxes b; generators::apply_holes_and_regions_3(b.solid, b.surface.triangles, {}, {&inside, 1}, {&half, 1}); },
               generators::SolidRegionsError);
}

}  // namespace
}  // namespace certimesh::testing
