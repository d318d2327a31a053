#include "recovery_mesh_3.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "certimesh/predicates/orient3d.h"
#include "certimesh/topology/star_walk.h"

namespace certimesh::generators::detail {

void recovery_invariant_broken(const std::string& what) {
  throw BoundaryRecoveryError("internal error in boundary recovery (please report): " + what);
}

QPoint to_q(const Point3& p) { return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)}; }

mpq_class orient_q(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  const mpq_class ax = a[0] - d[0], ay = a[1] - d[1], az = a[2] - d[2];
  const mpq_class bx = b[0] - d[0], by = b[1] - d[1], bz = b[2] - d[2];
  const mpq_class cx = c[0] - d[0], cy = c[1] - d[1], cz = c[2] - d[2];
  return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

QPoint along(const QPoint& a, const QPoint& b, const mpq_class& t) {
  QPoint p;
  for (int i = 0; i < 3; ++i) p[i] = a[i] + t * (b[i] - a[i]);
  return p;
}

namespace {

// Bounds of an exact rational coordinate: mpq_get_d truncates towards zero, so the double
// one step further out on each side bounds it.
void bound(const mpq_class& q, double* low, double* high, double* approx) {
  const double d = q.get_d();
  *approx = d;
  if (mpq_class(d) == q) {
    *low = *high = d;
  } else {
    *low = std::nextafter(d, -std::numeric_limits<double>::infinity());
    *high = std::nextafter(d, std::numeric_limits<double>::infinity());
  }
}

}  // namespace

RecoveryVertex make_vertex(QPoint p, RecoveryVertex::Origin origin, std::uint32_t on) {
  RecoveryVertex v;
  bound(p[0], &v.low.x, &v.high.x, &v.approx.x);
  bound(p[1], &v.low.y, &v.high.y, &v.approx.y);
  bound(p[2], &v.low.z, &v.high.z, &v.approx.z);
  v.is_double = v.low.x == v.high.x && v.low.y == v.high.y && v.low.z == v.high.z;
  v.exact = std::move(p);
  v.origin = origin;
  v.on = on;
  return v;
}

RecoveryVertex make_input_vertex(const Point3& p) {
  RecoveryVertex v;
  v.exact = to_q(p);
  v.approx = v.low = v.high = p;
  return v;
}

VertexId RecoveryMesh::add_vertex(RecoveryVertex v) {
  const VertexId id = mesh.add_vertex({v.approx.x, v.approx.y, v.approx.z});
  if (id.value != vertices.size()) recovery_invariant_broken("vertex slots are not consecutive");
  vertices.push_back(std::move(v));
  return id;
}

void RecoveryMesh::set_double_point(VertexId v, const Point3& p, RecoveryVertex::Origin origin) {
  RecoveryVertex moved = make_input_vertex(p);
  moved.origin = origin;
  vertices[v.value] = std::move(moved);
  mesh.move_vertex(v, {p.x, p.y, p.z});
}

namespace {

struct Fuzzy {  // a point's approximation and, per coordinate, a bound on its distance to the exact one
  const Point3* p;
  double w[3];
};

Fuzzy fuzzy(const RecoveryVertex& v) {
  return {&v.approx,
          {std::max(v.high.x - v.approx.x, v.approx.x - v.low.x), std::max(v.high.y - v.approx.y, v.approx.y - v.low.y),
           std::max(v.high.z - v.approx.z, v.approx.z - v.low.z)}};
}

// The sign of det[a - d, b - d, c - d] for inexactly known points when the double evaluation
// decides it, else 2. Bound: each computed difference C is within
// delta = w_p + w_d + 2^-52 |C| of the exact one (the points' distances plus the rounding of
// the subtraction); a product xyz of entries moves by at most
// dx(|y|+dy)(|z|+dz) + |x| dy(|z|+dz) + |x||y| dz; the evaluation of the six products and
// their sum errs by at most 2e-15 times the sum of their magnitudes (gamma_7 < 8e-16). Every
// bound is a sum of non-negative terms, so its own rounding is covered by the 1.01 factor.
// Below 1e-280 (where products could underflow) the filter abstains.
int orient_filter(const Fuzzy& a, const Fuzzy& b, const Fuzzy& c, const Fuzzy& d) {
  const Fuzzy* rows[3] = {&a, &b, &c};
  double m[3][3], e[3][3];
  const double dp[3] = {d.p->x, d.p->y, d.p->z};
  for (int i = 0; i < 3; ++i) {
    const double rp[3] = {rows[i]->p->x, rows[i]->p->y, rows[i]->p->z};
    for (int j = 0; j < 3; ++j) {
      m[i][j] = rp[j] - dp[j];
      e[i][j] = 1.01 * (rows[i]->w[j] + d.w[j] + 0x1p-52 * std::fabs(m[i][j]));
    }
  }
  static constexpr int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  double det = 0, magnitude = 0, moved = 0;
  for (int k = 0; k < 6; ++k) {
    const double x = m[0][perm[k][0]], y = m[1][perm[k][1]], z = m[2][perm[k][2]];
    const double dx = e[0][perm[k][0]], dy = e[1][perm[k][1]], dz = e[2][perm[k][2]];
    const double product = x * y * z;
    det += k < 3 ? product : -product;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    magnitude += ax * ay * az;
    moved += dx * (ay + dy) * (az + dz) + ax * dy * (az + dz) + ax * ay * dz;
  }
  const double bound = 1.01 * (moved + 2e-15 * magnitude);
  if (!(bound < 1e300) || magnitude < 1e-280) return 2;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return 2;
}

}  // namespace

int RecoveryMesh::orient(VertexId a, VertexId b, VertexId c, VertexId d) const {
  const RecoveryVertex &va = vertices[a.value], &vb = vertices[b.value], &vc = vertices[c.value],
                       &vd = vertices[d.value];
  if (va.is_double && vb.is_double && vc.is_double && vd.is_double)
    return predicates::to_int(predicates::orient3d(va.approx, vb.approx, vc.approx, vd.approx));
  const int f = orient_filter(fuzzy(va), fuzzy(vb), fuzzy(vc), fuzzy(vd));
  if (f != 2) return f;
  return sgn(orient_q(va.exact, vb.exact, vc.exact, vd.exact));
}

int RecoveryMesh::orient(VertexId a, VertexId b, VertexId c, const Point3& d) const {
  const RecoveryVertex &va = vertices[a.value], &vb = vertices[b.value], &vc = vertices[c.value];
  if (va.is_double && vb.is_double && vc.is_double)
    return predicates::to_int(predicates::orient3d(va.approx, vb.approx, vc.approx, d));
  const int f = orient_filter(fuzzy(va), fuzzy(vb), fuzzy(vc), Fuzzy{&d, {0, 0, 0}});
  if (f != 2) return f;
  return sgn(orient_q(va.exact, vb.exact, vc.exact, to_q(d)));
}

std::vector<ElementId> RecoveryMesh::star(VertexId v) const { return topology::walk_star(mesh, v); }

std::vector<ElementId> RecoveryMesh::around_edge(VertexId a, VertexId b) const {
  std::vector<ElementId> out;
  for (const ElementId t : star(a)) {
    const auto c = mesh.vertices(t);
    if (std::find(c.begin(), c.end(), b) != c.end()) out.push_back(t);
  }
  return out;
}

std::vector<ElementId> RecoveryMesh::around_face(VertexId a, VertexId b, VertexId c) const {
  std::vector<ElementId> out;
  for (const ElementId t : around_edge(a, b)) {
    const auto v = mesh.vertices(t);
    if (std::find(v.begin(), v.end(), c) != v.end()) out.push_back(t);
  }
  return out;
}

VertexId RecoveryMesh::split(std::span<const VertexId> corners, RecoveryVertex p) {
  const std::vector<ElementId> holders =
      corners.size() == 2 ? around_edge(corners[0], corners[1]) : around_face(corners[0], corners[1], corners[2]);
  if (holders.empty()) recovery_invariant_broken("a split simplex is in no tetrahedron");
  std::vector<topology::TetrahedralMesh3::Element> old;
  old.reserve(holders.size());
  for (const ElementId t : holders) {
    old.push_back(mesh.vertices(t));
    mesh.remove_element(t);
  }
  const VertexId id = add_vertex(std::move(p));
  for (const auto& t : old)
    for (const VertexId c : corners) {
      auto n = t;
      *std::find(n.begin(), n.end(), c) = id;
      mesh.add_element(n);
    }
  return id;
}

}  // namespace certimesh::generators::detail
