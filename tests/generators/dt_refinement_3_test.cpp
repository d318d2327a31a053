// Delaunay refinement of tetrahedral meshes (tetrahedral_refinement_3.h) and the sliver
// removal after it (quality_improvement_3.h, topology/local_modifications_3.h) against the
// independent certificate: the mesh tiles exactly the solid the input tiled (its boundary
// faces, bit for bit, are the domain), the interfaces between regions stay faces, sizes and
// radius-edge bounds are met where the rules say, scaling by a power of two scales the result
// exactly, and every local modification keeps the exact volume (a GMP sum of determinants).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/delaunay/delaunay_3.h"
#include "certimesh/generators/delaunay/tetrahedral_refinement_3.h"
#include "certimesh/generators/improvement/quality_improvement_3.h"
#include "certimesh/topology/local_modifications_3.h"

namespace certimesh {
namespace {

using generators::Point3;
using generators::Tetrahedralization3;
using Face = std::array<std::uint32_t, 3>;

constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};  // outward, positive tet

Tetrahedralization3 delaunay_of(const std::vector<Point3>& points) {
  const generators::Delaunay3 dt(points);
  Tetrahedralization3 m;
  m.points = points;
  m.tetrahedra = dt.tetrahedra();
  return m;
}

// Faces (oriented outward) held by one tetrahedron, or by two of different labels (each side).
std::vector<Face> faces_where(const Tetrahedralization3& m, bool interfaces) {
  std::map<Face, std::vector<std::pair<Face, io::Label>>> by_key;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t)
    for (const auto& f : kFace) {
      const Face o{m.tetrahedra[t][f[0]], m.tetrahedra[t][f[1]], m.tetrahedra[t][f[2]]};
      Face k = o;
      std::sort(k.begin(), k.end());
      by_key[k].push_back({o, m.labels.empty() ? 0 : m.labels[t]});
    }
  std::vector<Face> out;
  for (const auto& [k, held] : by_key) {
    if (!interfaces && held.size() == 1) out.push_back(held[0].first);
    if (interfaces && held.size() == 2 && held[0].second != held[1].second) out.push_back(k);
  }
  std::sort(out.begin(), out.end());
  return out;
}

io::MeshData as_mesh(const Tetrahedralization3& m) {
  io::MeshData d;
  d.dimension = 3;
  for (const Point3& p : m.points) d.coordinates.insert(d.coordinates.end(), {p.x, p.y, p.z});
  for (const auto& t : m.tetrahedra) d.tetrahedra.insert(d.tetrahedra.end(), t.begin(), t.end());
  return d;
}

io::MeshData surface_of(const Tetrahedralization3& m) {
  io::MeshData d;
  d.dimension = 3;
  for (const Point3& p : m.points) d.coordinates.insert(d.coordinates.end(), {p.x, p.y, p.z});
  for (const Face& f : faces_where(m, false)) d.triangles.insert(d.triangles.end(), f.begin(), f.end());
  return d;
}

void expect_certified(const Tetrahedralization3& refined, const io::MeshData& domain) {
  const io::MeshData mesh = as_mesh(refined);
  const certificate::Report r = certificate::check_mesh(mesh, &domain);
  EXPECT_TRUE(r.valid) << r.finding.message;
}

// Boundary faces as coordinate triples: the same set before and after, bit for bit.
std::set<std::array<double, 9>> boundary_geometry(const Tetrahedralization3& m) {
  std::set<std::array<double, 9>> out;
  for (const Face& f : faces_where(m, false)) {
    std::array<double, 9> g{};
    // rotate so the smallest vertex (by coordinates) comes first: orientation kept
    std::array<Point3, 3> p{m.points[f[0]], m.points[f[1]], m.points[f[2]]};
    auto less = [](const Point3& a, const Point3& b) {
      return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    const auto first = std::min_element(p.begin(), p.end(), less) - p.begin();
    std::rotate(p.begin(), p.begin() + first, p.end());
    for (int k = 0; k < 3; ++k) {
      g[3 * k] = p[static_cast<std::size_t>(k)].x;
      g[3 * k + 1] = p[static_cast<std::size_t>(k)].y;
      g[3 * k + 2] = p[static_cast<std::size_t>(k)].z;
    }
    out.insert(g);
  }
  return out;
}

double longest_edge(const Tetrahedralization3& m, std::size_t t) {
  double l = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Point3 &a = m.points[m.tetrahedra[t][i]], &b = m.points[m.tetrahedra[t][j]];
      l = std::max(l, std::hypot(a.x - b.x, a.y - b.y, a.z - b.z));
    }
  return l;
}

// Drops the points no tetrahedron uses (the certificate refuses a vertex in no element).
void compact_points(Tetrahedralization3& m) {
  std::vector<std::uint32_t> id(m.points.size(), UINT32_MAX);
  std::vector<Point3> kept;
  for (auto& t : m.tetrahedra)
    for (std::uint32_t& v : t) {
      if (id[v] == UINT32_MAX) {
        id[v] = static_cast<std::uint32_t>(kept.size());
        kept.push_back(m.points[v]);
      }
      v = id[v];
    }
  m.points = kept;
}

std::vector<Point3> grid(int n, double step) {
  std::vector<Point3> p;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) p.push_back({i * step, j * step, k * step});
  return p;
}

TEST(TetrahedralRefinement3, CubeToUniformSizeIsCertifiedAndKeepsItsBoundary) {
  Tetrahedralization3 m = delaunay_of(grid(8, 0.125));
  const io::MeshData domain = surface_of(m);
  const auto before = boundary_geometry(m);
  generators::TetrahedralRefinementOptions o;
  o.uniform_size = 0.08;
  const auto stats = generators::refine_tetrahedra_3(m, o);
  EXPECT_FALSE(stats.bound_reached);
  EXPECT_GT(m.tetrahedra.size(), 1000u);
  expect_certified(m, domain);
  EXPECT_EQ(boundary_geometry(m), before);  // no point on the boundary, faces unchanged
  std::size_t too_long = 0;
  auto depth = [](const Point3& p) {  // distance to the cube's boundary
    return std::min({p.x, p.y, p.z, 1 - p.x, 1 - p.y, 1 - p.z});
  };
  std::size_t deep = 0;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    double least = 1;
    for (std::uint32_t v : m.tetrahedra[t]) least = std::min(least, depth(m.points[v]));
    if (least < 0.25) continue;
    ++deep;
    too_long += longest_edge(m, t) > 0.08 ? 1 : 0;
  }
  // The boundary triangles are kept whole (legs 0.125 > 0.08) and no point enters their
  // diametral balls, so near them tetrahedra may stay long; two grid steps in, every one
  // meets the size but a few whose candidates came too near a vertex.
  EXPECT_GT(deep, m.tetrahedra.size() / 20);
  EXPECT_LT(too_long, deep / 200) << too_long << " of " << m.tetrahedra.size();
}

TEST(TetrahedralRefinement3, NonConvexSolidWithTwoRegionsKeepsTheInterface) {
  // A 4 x 4 x 4 grid of cells; the solid drops the cells with x > 2 and y > 2 (an L), and the
  // cells with z < 2 are region 1, the others region 2.
  const double s = 0.25;
  Tetrahedralization3 all = delaunay_of(grid(4, s));
  Tetrahedralization3 m;
  m.points = all.points;
  for (const auto& t : all.tetrahedra) {
    Point3 c{};
    for (std::uint32_t v : t) c = {c.x + all.points[v].x / 4, c.y + all.points[v].y / 4, c.z + all.points[v].z / 4};
    if (c.x > 0.5 && c.y > 0.5) continue;
    m.tetrahedra.push_back(t);
    m.labels.push_back(c.z < 0.5 ? 1 : 2);
  }
  compact_points(m);
  const io::MeshData domain = surface_of(m);
  const auto interface_before = faces_where(m, true);
  ASSERT_FALSE(interface_before.empty());
  const auto before = boundary_geometry(m);
  generators::TetrahedralRefinementOptions o;
  o.uniform_size = 0.08;
  generators::refine_tetrahedra_3(m, o);
  expect_certified(m, domain);
  EXPECT_EQ(boundary_geometry(m), before);
  EXPECT_EQ(faces_where(m, true), interface_before);  // point ids of input vertices unchanged
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    double z = 0;
    for (std::uint32_t v : m.tetrahedra[t]) z += m.points[v].z / 4;
    EXPECT_EQ(m.labels[t], z < 0.5 ? 1 : 2) << "tetrahedron " << t;
  }
}

TEST(TetrahedralRefinement3, CoarseBoundaryLimitsRefinementAndTerminates) {
  // 12 boundary triangles and --size far below them: no point may enter the diametral ball
  // of a face, so the mesh stays coarse next to them (as tetgen -pYa does) -- but valid.
  Tetrahedralization3 m = delaunay_of(grid(1, 1.0));
  const io::MeshData domain = surface_of(m);
  generators::TetrahedralRefinementOptions o;
  o.uniform_size = 0.01;
  const auto stats = generators::refine_tetrahedra_3(m, o);
  EXPECT_FALSE(stats.bound_reached);
  expect_certified(m, domain);
}

TEST(TetrahedralRefinement3, RadiusEdgeBoundHoldsWhereTheBoundaryAllowsIt) {
  Tetrahedralization3 m = delaunay_of(grid(8, 0.125));
  const io::MeshData domain = surface_of(m);
  generators::TetrahedralRefinementOptions o;
  o.uniform_size = 0.125;
  o.max_radius_edge = 2.0;
  const auto stats = generators::refine_tetrahedra_3(m, o);
  expect_certified(m, domain);
  std::size_t skinny = 0;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    const auto& q = m.tetrahedra[t];
    const Point3 &a = m.points[q[0]], &b = m.points[q[1]], &c = m.points[q[2]], &d = m.points[q[3]];
    // circumradius from the Cayley-Menger-free formula |num| / (2 * 6V), recomputed here
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z,
                 wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
    const double det = ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
    const double uu = ux * ux + uy * uy + uz * uz, vv = vx * vx + vy * vy + vz * vz, ww = wx * wx + wy * wy + wz * wz;
    const double nx = uu * (vy * wz - vz * wy) + vv * (wy * uz - wz * uy) + ww * (uy * vz - uz * vy);
    const double ny = uu * (vz * wx - vx * wz) + vv * (wz * ux - wx * uz) + ww * (uz * vx - ux * vz);
    const double nz = uu * (vx * wy - vy * wx) + vv * (wx * uy - wy * ux) + ww * (ux * vy - uy * vx);
    const double r = std::sqrt(nx * nx + ny * ny + nz * nz) / (2 * std::abs(det));
    double lmin = 1e300;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Point3 &p = m.points[q[i]], &s = m.points[q[j]];
        lmin = std::min(lmin, std::hypot(p.x - s.x, p.y - s.y, p.z - s.z));
      }
    skinny += r > 2.0 * (1 + 1e-9) * lmin ? 1 : 0;
  }
  EXPECT_EQ(skinny, stats.skinny_left);  // the count it reports is the count there is
  EXPECT_LT(skinny, m.tetrahedra.size() / 50) << skinny << " of " << m.tetrahedra.size();
}

TEST(TetrahedralRefinement3, ScalingByAPowerOfTwoScalesTheMeshExactly) {
  const Tetrahedralization3 base = delaunay_of(grid(2, 0.5));
  for (const double scale : {0x1p-30, 0x1p40}) {
    Tetrahedralization3 a = base, b = base;
    for (Point3& p : b.points) p = {p.x * scale, p.y * scale, p.z * scale};
    generators::TetrahedralRefinementOptions oa, ob;
    oa.uniform_size = 0.12;
    ob.uniform_size = 0.12 * scale;
    generators::refine_tetrahedra_3(a, oa);
    generators::refine_tetrahedra_3(b, ob);
    ASSERT_EQ(a.tetrahedra, b.tetrahedra);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t v = 0; v < a.points.size(); ++v) {
      EXPECT_EQ(a.points[v].x * scale, b.points[v].x);
      EXPECT_EQ(a.points[v].y * scale, b.points[v].y);
      EXPECT_EQ(a.points[v].z * scale, b.points[v].z);
    }
  }
}

TEST(TetrahedralRefinement3, ThinSlabTerminatesAndIsCertified) {
  std::vector<Point3> p;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j)
      for (double z : {0.0, 1e-6}) p.push_back({i * 0.25, j * 0.25, z});
  Tetrahedralization3 m = delaunay_of(p);
  const io::MeshData domain = surface_of(m);
  generators::TetrahedralRefinementOptions o;  // defaults: sizes from the boundary, R/l 2
  const auto stats = generators::refine_tetrahedra_3(m, o);
  EXPECT_FALSE(stats.bound_reached);
  expect_certified(m, domain);
}

// --- sliver removal ------------------------------------------------------------------------

// 6 x the exact volume of every tetrahedron, summed in rationals (the oracle for "the same
// solid": any double rounding in a modification would show).
mpq_class exact_volume(const Tetrahedralization3& m) {
  mpq_class sum = 0;
  for (const auto& t : m.tetrahedra) {
    const Point3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]], &d = m.points[t[3]];
    const mpq_class ux = mpq_class(b.x) - a.x, uy = mpq_class(b.y) - a.y, uz = mpq_class(b.z) - a.z;
    const mpq_class vx = mpq_class(c.x) - a.x, vy = mpq_class(c.y) - a.y, vz = mpq_class(c.z) - a.z;
    const mpq_class wx = mpq_class(d.x) - a.x, wy = mpq_class(d.y) - a.y, wz = mpq_class(d.z) - a.z;
    sum += ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  }
  return sum;
}

// 6^4 sqrt(2) |V| / P^3, recomputed here.
double quality_of(const Tetrahedralization3& m, std::size_t t) {
  const auto& q = m.tetrahedra[t];
  const Point3 &a = m.points[q[0]], &b = m.points[q[1]], &c = m.points[q[2]], &d = m.points[q[3]];
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z,
               wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  const double v = std::abs(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6;
  double perimeter = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Point3 &p = m.points[q[i]], &s = m.points[q[j]];
      perimeter += std::hypot(p.x - s.x, p.y - s.y, p.z - s.z);
    }
  return 1296 * std::sqrt(2.0) * v / (perimeter * perimeter * perimeter);
}

double worst_of(const Tetrahedralization3& m) {
  double w = 1;
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) w = std::min(w, quality_of(m, t));
  return w;
}

topology::TetrahedralMesh3 to_topology(const Tetrahedralization3& m) {
  topology::TetrahedralMesh3 mesh;
  for (const Point3& p : m.points) mesh.add_vertex({p.x, p.y, p.z});
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    const auto& c = m.tetrahedra[t];
    mesh.add_element({topology::VertexId{c[0]}, topology::VertexId{c[1]}, topology::VertexId{c[2]}, topology::VertexId{c[3]}},
                     m.labels.empty() ? 0 : m.labels[t]);
  }
  for (const auto& f : m.constrained_faces)
    mesh.set_facet_label({topology::VertexId{f[0]}, topology::VertexId{f[1]}, topology::VertexId{f[2]}}, 1);
  return mesh;
}

Tetrahedralization3 from_topology(const topology::TetrahedralMesh3& mesh, const Tetrahedralization3& like) {
  Tetrahedralization3 m;
  m.constrained_faces = like.constrained_faces;
  for (std::uint32_t v = 0; v < mesh.vertex_slot_count(); ++v) {
    const auto p = mesh.point(topology::VertexId{v});
    m.points.push_back({p[0], p[1], p[2]});
  }
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    if (!mesh.is_live(topology::ElementId{e})) continue;
    const auto c = mesh.vertices(topology::ElementId{e});
    m.tetrahedra.push_back({c[0].value, c[1].value, c[2].value, c[3].value});
    m.labels.push_back(mesh.label(topology::ElementId{e}));
  }
  return m;
}

bool holds_face(const Tetrahedralization3& m, Face f) {
  std::sort(f.begin(), f.end());
  for (const auto& t : m.tetrahedra) {
    int in = 0;
    for (std::uint32_t v : t) in += std::count(f.begin(), f.end(), v) ? 1 : 0;
    if (in == 3) return true;
  }
  return false;
}

// Two regions (z below / above 0.5) of the unit cube's grid(3) Delaunay mesh with random
// interior points, and one interior face made a constraint: slivers everywhere.
Tetrahedralization3 sliver_test_mesh(std::uint32_t seed, std::uint32_t* first_free) {
  std::vector<Point3> p = grid(3, 1.0 / 3);
  *first_free = static_cast<std::uint32_t>(p.size());
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> inside(0.05, 0.95);
  for (int i = 0; i < 25; ++i) p.push_back({inside(random), inside(random), inside(random)});
  Tetrahedralization3 m = delaunay_of(p);
  for (const auto& t : m.tetrahedra) {
    double z = 0;
    for (std::uint32_t v : t) z += m.points[v].z / 4;
    m.labels.push_back(z < 0.5 ? 1 : 2);
  }
  const auto& t = m.tetrahedra[m.tetrahedra.size() / 2];  // an interior face of some tetrahedron
  const std::vector<Face> boundary = faces_where(m, false);
  for (const auto& f : kFace) {
    const Face face{t[f[0]], t[f[1]], t[f[2]]};
    if (std::find(boundary.begin(), boundary.end(), face) == boundary.end()) {
      m.constrained_faces.push_back(face);
      break;
    }
  }
  return m;
}

TEST(SliverRemoval3, RandomOperationSequencesStayCertifiedAndKeepTheSolid) {
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    std::uint32_t first_free = 0;
    const Tetrahedralization3 start = sliver_test_mesh(seed, &first_free);
    const io::MeshData domain = surface_of(start);
    const auto boundary = boundary_geometry(start);
    const auto interfaces = faces_where(start, true);
    const mpq_class volume = exact_volume(start);
    topology::TetrahedralMesh3 mesh = to_topology(start);
    topology::LocalModificationOptions3 o;
    o.first_movable_vertex = first_free;
    std::mt19937 random(seed);
    std::size_t accepted[3] = {0, 0, 0};
    for (int step = 0; step < 400; ++step) {
      const std::uint32_t slot = static_cast<std::uint32_t>(random() % mesh.element_slot_count());
      const topology::ElementId e{slot};
      if (!mesh.is_live(e)) continue;
      const int op = static_cast<int>(random() % 3), a = static_cast<int>(random() % 4), b = (a + 1 + static_cast<int>(random() % 3)) % 4;
      std::optional<topology::LocalChange3> change;
      if (op == 0) change = topology::try_edge_removal(mesh, e, a, b, o);
      if (op == 1) change = topology::try_flip_2_3(mesh, e, a);
      if (op == 2) change = topology::try_node_shift(mesh, mesh.vertices(e)[static_cast<std::size_t>(a)], o);
      if (!change) continue;
      ++accepted[op];
      const Tetrahedralization3 now = from_topology(mesh, start);
      const certificate::Report r = certificate::check_mesh(as_mesh(now), &domain);
      ASSERT_TRUE(r.valid) << "seed " << seed << " step " << step << " op " << op << ": " << r.finding.message;
      ASSERT_EQ(exact_volume(now), volume) << "seed " << seed << " step " << step;
      ASSERT_EQ(boundary_geometry(now), boundary);
      ASSERT_EQ(faces_where(now, true), interfaces);
      for (std::uint32_t v = 0; v < first_free; ++v) ASSERT_EQ(mesh.point(topology::VertexId{v}), (std::array<double, 3>{start.points[v].x, start.points[v].y, start.points[v].z}));
      ASSERT_TRUE(holds_face(now, start.constrained_faces.at(0)));
    }
    EXPECT_GT(accepted[0], 0u) << "seed " << seed;  // the sequences did modify the meshes
    EXPECT_GT(accepted[2], 0u) << "seed " << seed;
  }
}

TEST(SliverRemoval3, TheDriverKeepsRegionsConstrainedFacesAndInputPoints) {
  std::uint32_t first_free = 0;
  Tetrahedralization3 m = sliver_test_mesh(7, &first_free);
  const Tetrahedralization3 start = m;
  const io::MeshData domain = surface_of(m);
  const auto stats = generators::improve_tetrahedra_3(m, first_free);
  EXPECT_GT(stats.edge_removals + stats.node_shifts, 0u);
  expect_certified(m, domain);
  EXPECT_EQ(exact_volume(m), exact_volume(start));
  EXPECT_EQ(boundary_geometry(m), boundary_geometry(start));
  EXPECT_EQ(faces_where(m, true), faces_where(start, true));
  EXPECT_TRUE(holds_face(m, start.constrained_faces.at(0)));
  for (std::uint32_t v = 0; v < first_free; ++v) EXPECT_EQ(m.points[v].x, start.points[v].x);
  EXPECT_GE(worst_of(m), worst_of(start));
  EXPECT_LT(worst_of(start), 0.2);  // the fixture has slivers to remove
}

TEST(SliverRemoval3, RefinedCubeLosesItsSliversAndKeepsItsBoundary) {
  Tetrahedralization3 m = delaunay_of(grid(2, 0.5));
  const io::MeshData domain = surface_of(m);
  const auto before = boundary_geometry(m);
  const std::uint32_t first_free = static_cast<std::uint32_t>(m.points.size());
  generators::TetrahedralRefinementOptions o;
  o.uniform_size = 0.2;
  generators::refine_tetrahedra_3(m, o);
  const double worst_before = worst_of(m);
  const mpq_class volume = exact_volume(m);
  const auto points_before = m.points.size();
  const auto stats = generators::improve_tetrahedra_3(m, first_free);
  expect_certified(m, domain);
  EXPECT_EQ(boundary_geometry(m), before);
  EXPECT_EQ(exact_volume(m), volume);
  EXPECT_EQ(m.points.size(), points_before);
  EXPECT_GE(worst_of(m), worst_before);
  EXPECT_LT(worst_before, 0.1);  // refinement alone leaves slivers
  EXPECT_GT(worst_of(m), 0.3) << "before " << worst_before;
  EXPECT_NEAR(stats.worst_after, worst_of(m), 1e-12);
}

}  // namespace
}  // namespace certimesh
