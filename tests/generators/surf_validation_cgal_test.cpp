// Surface validation (generators/domain/surface_validation_3.h) against CGAL as the oracle, over
// generated closed surfaces (RapidCheck):
//   - convex hulls of random integer points (CGAL::convex_hull_3) are accepted as one outward
//     solid (CGAL::Polygon_mesh_processing::is_outward_oriented agrees), inside out as one
//     inward solid, scaled by 2^-40, 2^40 and 1e12 (exact on these integers) alike, and so are
//     slabs (z in {0, 1}, about 1e-6 as thick as wide);
//   - each mutation is refused with its reason: a deleted triangle (open edges), a flipped one
//     (orientation), a duplicated one, one collapsed onto a line (c := 2a - b, exact);
//   - a hull with one vertex moved anywhere, and two hulls placed anywhere: the set of
//     intersecting triangle pairs equals CGAL's PMP::self_intersections with the exact kernel
//     (Epeck), touchings included; when one hull lies inside the other
//     (CGAL::Side_of_triangle_mesh) they bound an interface, or a cavity when the second is
//     turned inward (whichever is inside: winding 0 between them, or 0 inside the inner one).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

#include "certimesh/generators/domain/surface_validation_3.h"
#include "cgal_reference.h"

namespace certimesh::generators {
namespace {

using predicates::Point3;
using Pairs = std::set<std::pair<std::uint32_t, std::uint32_t>>;

constexpr int kRange = 1 << 20;

// A fixed seed, so that every run draws the same cases, unless RC_PARAMS is set (to reproduce a
// reported failure or to vary the seed); read when the first property runs.
const bool rc_seed_fixed = [] {
  setenv("RC_PARAMS", "seed=20261202 max_success=100", 0);
  return true;
}();

// The convex hull of n random integer points, as CGAL builds it, vertex order as in the mesh;
// with `slab`, z is 0 or 1 only: a slab about 1e-6 as thick as it is wide.
Surface3 random_hull(bool slab = false) {
  const auto n = *rc::gen::inRange<std::size_t>(4, 60);
  std::vector<cgal_reference::Point3> in;
  for (std::size_t i = 0; i < n; ++i) {
    auto c = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-kRange, kRange));
    if (slab) c[2] = c[2] & 1;
    in.push_back({double(c[0]), double(c[1]), double(c[2])});
  }
  const cgal_reference::HullMesh hull = cgal_reference::convex_hull_3(in);
  RC_PRE((hull.closed && hull.faces.size() >= 4));
  RC_ASSERT(hull.outward_oriented);
  Surface3 s;
  for (const auto& p : hull.vertices) s.points.push_back({p[0], p[1], p[2]});
  for (const auto& f : hull.faces) {
    RC_ASSERT(f.size() == 3u);
    s.triangles.push_back({f[0], f[1], f[2]});
    s.labels.push_back(0);
    s.facet_of.push_back(static_cast<std::uint32_t>(s.facet_of.size()));
  }
  return s;
}

SurfaceCheck check(Surface3 s, std::size_t cap = 16) { return check_surface(s, cap); }

bool has(const SurfaceCheck& c, SurfaceProblemKind kind) {
  return std::any_of(c.problems.begin(), c.problems.end(), [&](const SurfaceProblem& p) { return p.kind == kind; });
}

bool touches(const SurfaceProblem& p, std::uint32_t t) { return std::find(p.triangles.begin(), p.triangles.end(), t) != p.triangles.end(); }

// CGAL's intersecting pairs of triangles (face i = triangle i), exact kernel.
Pairs cgal_pairs(const Surface3& s) {
  std::vector<cgal_reference::Point3> points;
  for (const Point3& p : s.points) points.push_back({p.x, p.y, p.z});
  const auto out = cgal_reference::self_intersections(points, s.triangles);
  RC_ASSERT(out.has_value());  // every triangle added to CGAL's mesh
  Pairs pairs;
  for (const auto& [a, b] : *out) pairs.insert(std::minmax(a, b));
  return pairs;
}

Pairs our_pairs(const SurfaceCheck& c) {
  Pairs pairs;
  for (const SurfaceProblem& p : c.problems)
    if (p.kind == SurfaceProblemKind::self_intersection) pairs.insert({p.triangles[0], p.triangles[1]});
  return pairs;
}

Surface3 flipped(Surface3 s) {
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  return s;
}

RC_GTEST_PROP(surf_CgalProperty, HullsAreOneSolidEitherWayAndAtAnyScale, ()) {
  const Surface3 hull = random_hull();
  const SurfaceCheck c = check(hull);
  RC_ASSERT(c.problems.empty());
  RC_ASSERT((c.shells.size() == 1u && c.solids == 1u && c.cavities == 0u));
  RC_ASSERT(c.shells[0].orientation == 1);
  const SurfaceCheck inside_out = check(flipped(hull));
  RC_ASSERT((inside_out.problems.empty() && inside_out.solids == 1u && inside_out.shells[0].orientation == -1));
  for (const int k : {-40, 40}) {
    Surface3 scaled = hull;
    for (Point3& p : scaled.points) p = {std::ldexp(p.x, k), std::ldexp(p.y, k), std::ldexp(p.z, k)};
    const SurfaceCheck sc = check(scaled);
    RC_ASSERT((sc.problems.empty() && sc.solids == 1u && sc.shells[0].orientation == 1));
  }
  // Times 1e12 = 2^12 5^12: exact on these integers (21 + 28 bits), so the same surface.
  Surface3 scaled = hull;
  for (Point3& p : scaled.points) p = {p.x * 1e12, p.y * 1e12, p.z * 1e12};
  const SurfaceCheck sc = check(scaled);
  RC_ASSERT((sc.problems.empty() && sc.solids == 1u && sc.shells[0].orientation == 1));
}

RC_GTEST_PROP(surf_CgalProperty, ThinSlabHullsAreValid, ()) {
  const Surface3 slab = random_hull(true);
  const SurfaceCheck c = check(slab);
  RC_ASSERT(c.problems.empty());
  RC_ASSERT((c.shells.size() == 1u && c.solids == 1u && c.shells[0].orientation == 1));
  RC_ASSERT(our_pairs(c) == cgal_pairs(slab));
}

RC_GTEST_PROP(surf_CgalProperty, EveryMutationIsRefusedWithItsReason, ()) {
  const Surface3 hull = random_hull();
  const auto t = *rc::gen::inRange<std::uint32_t>(0, static_cast<std::uint32_t>(hull.triangles.size()));
  {
    Surface3 s = hull;
    s.triangles.erase(s.triangles.begin() + t);
    const SurfaceCheck c = check(s);
    RC_ASSERT(c.problems.size() == 3u);
    for (const auto& p : c.problems) RC_ASSERT(p.kind == SurfaceProblemKind::open_edge);
  }
  {
    Surface3 s = hull;
    std::swap(s.triangles[t][0], s.triangles[t][1]);
    const SurfaceCheck c = check(s);
    RC_ASSERT(c.problems.size() == 3u);
    for (const auto& p : c.problems) RC_ASSERT(p.kind == SurfaceProblemKind::inconsistent_orientation && touches(p, t));
  }
  {
    Surface3 s = hull;
    s.triangles.push_back(s.triangles[t]);
    const SurfaceCheck c = check(s);
    RC_ASSERT(!c.problems.empty());
    RC_ASSERT(c.problems[0].kind == SurfaceProblemKind::duplicate_triangles);
    RC_ASSERT(c.problems[0].triangles == (std::vector<std::uint32_t>{t, static_cast<std::uint32_t>(hull.triangles.size())}));
  }
  {
    Surface3 s = hull;  // corner c onto the line of a and b: c := 2a - b, exact on these integers
    const auto [a, b, cc] = s.triangles[t];
    const Point3 pa = s.points[a], pb = s.points[b];
    s.points[cc] = {2 * pa.x - pb.x, 2 * pa.y - pb.y, 2 * pa.z - pb.z};
    const SurfaceCheck c = check(s);
    RC_ASSERT((std::any_of(c.problems.begin(), c.problems.end(), [&](const SurfaceProblem& p) {
      return p.kind == SurfaceProblemKind::degenerate_triangle && touches(p, t);
    }) || has(c, SurfaceProblemKind::duplicate_vertices)));
  }
}

RC_GTEST_PROP(surf_CgalProperty, MovedVertexIntersectionsEqualCgals, ()) {
  Surface3 s = random_hull();
  const auto v = *rc::gen::inRange<std::size_t>(0, s.points.size());
  const auto c = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-2 * kRange, 2 * kRange));
  s.points[v] = {double(c[0]), double(c[1]), double(c[2])};
  const SurfaceCheck ours = check(s, 1u << 20);
  RC_PRE((!has(ours, SurfaceProblemKind::duplicate_vertices) && !has(ours, SurfaceProblemKind::degenerate_triangle)));
  RC_ASSERT((ours.problems.empty() || ours.problems[0].kind == SurfaceProblemKind::self_intersection));
  RC_ASSERT(our_pairs(ours) == cgal_pairs(s));
  RC_ASSERT(ours.intersecting_pairs == our_pairs(ours).size());
  RC_TAG(ours.problems.empty() ? "valid" : "self-intersecting");
}

RC_GTEST_PROP(surf_CgalProperty, TwoHullsIntersectAsCgalSaysOrNest, ()) {
  const Surface3 a = random_hull();
  Surface3 b = random_hull();
  // B shrunk by 2^-s and moved: often inside A, often crossing or touching it.
  const int shrink = *rc::gen::inRange(0, 8);
  const auto offset = *rc::gen::container<std::vector<int>>(3, rc::gen::inRange(-kRange / 8, kRange / 8));
  const bool inward = *rc::gen::arbitrary<bool>();
  Surface3 s = a;
  const auto base = static_cast<std::uint32_t>(s.points.size());
  for (const Point3& p : b.points)
    s.points.push_back({std::ldexp(p.x, -shrink) + offset[0], std::ldexp(p.y, -shrink) + offset[1], std::ldexp(p.z, -shrink) + offset[2]});
  for (auto t : b.triangles) {
    for (auto& i : t) i += base;
    if (inward) std::swap(t[1], t[2]);
    s.triangles.push_back(t);
  }
  const SurfaceCheck ours = check(s, 1u << 20);
  RC_PRE(!has(ours, SurfaceProblemKind::duplicate_vertices));  // a corner of B on a corner of A: two vertices, one point
  RC_ASSERT(our_pairs(ours) == cgal_pairs(s));
  if (!ours.problems.empty()) {
    RC_TAG("intersecting");
    return;
  }
  // Disjoint surfaces: one inside the other or not, by CGAL's exact point location of a vertex
  // of each in the other.
  auto inside = [](const Surface3& surface, std::uint32_t first, std::uint32_t end, const Point3& q) {
    std::vector<cgal_reference::Point3> points;
    for (std::uint32_t v = first; v < end; ++v) points.push_back({surface.points[v].x, surface.points[v].y, surface.points[v].z});
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const auto& t : surface.triangles)
      if (t[0] >= first && t[0] < end) triangles.push_back({t[0] - first, t[1] - first, t[2] - first});
    return cgal_reference::strictly_inside(points, triangles, {q.x, q.y, q.z});
  };
  const auto end = static_cast<std::uint32_t>(s.points.size());
  const bool nested = inside(s, 0, base, s.points[base]) || inside(s, base, end, s.points[0]);
  RC_ASSERT(ours.shells.size() == 2u);
  RC_ASSERT(ours.shells[1].orientation == (inward ? -1 : 1));
  if (nested) {
    RC_TAG(inward ? "cavity" : "interface");
    RC_ASSERT((ours.solids == 1u && ours.cavities == (inward ? 1u : 0u) && ours.interfaces == (inward ? 0u : 1u)));
  } else {
    RC_TAG("apart");
    RC_ASSERT((ours.solids == 2u && ours.cavities == 0u && ours.interfaces == 0u));
  }
}

}  // namespace
}  // namespace certimesh::generators
