// Incremental Bowyer-Watson insertion in a biased randomized Hilbert order (hilbert_order.h)
// over a tetrahedralization closed by ghost tetrahedra; point location by the remembering
// stochastic walk. Every sign is exact; the perturbation of the lifting makes the input
// generic, so the tetrahedralization is unique and the same for every input order.
#include "certimesh/generators/delaunay/delaunay_3.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "certimesh/generators/delaunay/perturbed_predicates_3.h"
#include "certimesh/predicates/orient2d.h"
#include "hilbert_order.h"

namespace certimesh::generators {

namespace {

using detail::insphere_perturbed;
using detail::orient3d_exact;

constexpr std::uint32_t infinite = Delaunay3::none;

// face[i]: the corners of the face opposite corner i, counterclockwise seen from corner i
// (from inside): (face[i][0], face[i][1], face[i][2], i) is an even permutation of (0, 1, 2, 3),
// so a point p is strictly beyond face i of a positive tetrahedron exactly when
// orient3d(face[i], p) > 0.
constexpr std::uint32_t face[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

std::string describe_point3(const Point3& p) {
  std::ostringstream out;
  out.precision(17);
  out << '(' << p.x << ' ' << p.y << ' ' << p.z << ')';
  return out.str();
}

bool collinear_3(const Point3& a, const Point3& b, const Point3& c) {
  using predicates::orient2d;
  using predicates::Point2;
  using predicates::Sign;
  return orient2d(Point2{a.x, a.y}, Point2{b.x, b.y}, Point2{c.x, c.y}) == Sign::zero &&
         orient2d(Point2{a.y, a.z}, Point2{b.y, b.z}, Point2{c.y, c.z}) == Sign::zero &&
         orient2d(Point2{a.z, a.x}, Point2{b.z, b.x}, Point2{c.z, c.x}) == Sign::zero;
}

constexpr std::uint64_t delaunay3_edge_key(std::uint32_t u, std::uint32_t w) { return (std::uint64_t{u} << 32) | w; }
constexpr std::uint64_t empty_key = ~std::uint64_t{0};

}  // namespace

Delaunay3::Delaunay3(std::span<const Point3> points, const ProgressCallback& progress) { build(points, progress); }

void Delaunay3::throw_duplicate(VertexId a, VertexId b) const {
  const VertexId ea = external_[a], eb = external_[b];
  throw DelaunayError("delaunay: points " + std::to_string(std::min(ea, eb)) + " and " +
                      std::to_string(std::max(ea, eb)) + " are the same point " + describe_point3(points_[a]));
}

void Delaunay3::check_distinct() const {
  std::vector<VertexId> sorted(points_.size());
  for (std::size_t k = 0; k < sorted.size(); ++k) sorted[k] = static_cast<VertexId>(k);
  auto key = [&](VertexId i) { return std::array<double, 3>{pt(i).x, pt(i).y, pt(i).z}; };
  std::sort(sorted.begin(), sorted.end(), [&](VertexId i, VertexId j) {
    return key(i) != key(j) ? key(i) < key(j) : external_[i] < external_[j];
  });
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (pt(sorted[k - 1]) == pt(sorted[k])) throw_duplicate(sorted[k - 1], sorted[k]);
}

void Delaunay3::build(std::span<const Point3> input, const ProgressCallback& progress) {
  for (std::size_t i = 0; i < input.size(); ++i)
    if (!std::isfinite(input[i].x) || !std::isfinite(input[i].y) || !std::isfinite(input[i].z))
      throw DelaunayError("delaunay: point " + std::to_string(i) + " " + describe_point3(input[i]) + " is not finite");
  // Half-face ids (4 * slot + local) are 32-bit: about 6.8 slots per point leaves room for 2^27.
  if (input.size() > (std::size_t{1} << 27))
    throw DelaunayError("delaunay: " + std::to_string(input.size()) + " points: at most 2^27 are supported");
  external_ = detail::hilbert_order_3(input);
  internal_.assign(input.size(), none);
  points_.resize(input.size());
  for (std::size_t k = 0; k < input.size(); ++k) {
    internal_[external_[k]] = static_cast<VertexId>(k);
    points_[k] = input[external_[k]];
  }
  const std::size_t n = points_.size();
  if (n < 4) {
    check_distinct();
    throw DelaunayError("delaunay: " + std::to_string(n) + " points: a tetrahedralization needs at least four");
  }
  // The first tetrahedron: the first two points (in insertion order), the first point off
  // their line and the first point off the plane of the three.
  if (pt(0) == pt(1)) throw_duplicate(0, 1);
  std::size_t third = n, fourth = n;
  for (std::size_t k = 2; k < n && third == n; ++k)
    if (!collinear_3(pt(0), pt(1), pt(static_cast<VertexId>(k)))) third = k;
  for (std::size_t k = third + 1; k < n && fourth == n; ++k)
    if (orient3d_exact(pt(0), pt(1), pt(static_cast<VertexId>(third)), pt(static_cast<VertexId>(k))) != 0) fourth = k;
  if (fourth >= n) {
    check_distinct();
    throw DelaunayError("delaunay: all " + std::to_string(n) + " points lie " +
                        (third == n ? "on one line" : "in one plane") + ": their convex hull has no volume");
  }
  // About 6.75 tetrahedra per uniform random point (6.77 asymptotically, Dwyer 1991), fewer
  // on grids; reserving avoids copies while growing.
  flags_.reserve(7 * n + 64);
  corner_.reserve(4 * flags_.capacity());
  adjacent_.reserve(4 * flags_.capacity());
  make_first_tetrahedron(0, 1, static_cast<VertexId>(third), static_cast<VertexId>(fourth));
  for (std::size_t k = 2; k < n; ++k) {
    if (k == third || k == fourth) continue;
    insert_vertex(static_cast<VertexId>(k));
    if ((k & 0xffff) == 0) report(progress, "delaunay", k, n);
  }
  report(progress, "delaunay", n, n);
  for (TetrahedronId t = 0; t < flags_.size(); ++t) live_count_ += is_live(t) ? 1 : 0;
}

Delaunay3::TetrahedronId Delaunay3::new_slot() {
  if (!free_slots_.empty()) {
    const TetrahedronId t = free_slots_.back();
    free_slots_.pop_back();
    flags_[t] = 0;
    return t;
  }
  if (flags_.size() >= (std::size_t{1} << 30)) throw DelaunayError("delaunay: more than 2^30 tetrahedron slots");
  const auto t = static_cast<TetrahedronId>(flags_.size());
  flags_.push_back(0);
  // push_back, not resize (which fills the whole growth); the entries are written next.
  for (int i = 0; i < 4; ++i) corner_.push_back(none), adjacent_.push_back(none);
  return t;
}

void Delaunay3::make_first_tetrahedron(VertexId a, VertexId b, VertexId c, VertexId d) {
  if (orient3d_exact(pt(a), pt(b), pt(c), pt(d)) > 0) std::swap(a, b);  // positive: orient3d < 0
  const TetrahedronId t = new_slot();
  const std::array<VertexId, 4> q{a, b, c, d};
  for (std::uint32_t i = 0; i < 4; ++i) corner_[4 * t + i] = q[i];
  // Ghost i lies across face i: that face seen from outside (reversed), then the infinite
  // vertex.
  std::array<TetrahedronId, 4> ghosts{};
  for (std::uint32_t i = 0; i < 4; ++i) {
    const TetrahedronId g = ghosts[i] = new_slot();
    corner_[4 * g] = q[face[i][0]];
    corner_[4 * g + 1] = q[face[i][2]];
    corner_[4 * g + 2] = q[face[i][1]];
    corner_[4 * g + 3] = infinite;
    link(4 * t + i, 4 * g + 3);
  }
  link_around(infinite, ghosts);
  last_ = t;
}

// Links the faces through `apex` of the given tetrahedra to one another: each such face, its
// corners rotated to start at the apex, is (apex, u, w); its neighbour's is (apex, w, u).
// An open-addressing table keyed by the directed edge finds the pairs in linear time: every
// face is entered first, then every face looks its twin up, which is there (two passes, so
// no branch on "is the twin in yet", which mispredicted half the time). The table is empty
// between calls: only the entries used are cleared.
void Delaunay3::link_around(VertexId apex, std::span<const TetrahedronId> tetrahedra) {
  // The table's first `size` entries, load below 1/5; a small star keeps to a small prefix
  // (in L1) even after a large one grew the table.
  const std::size_t size = std::bit_ceil(16 * tetrahedra.size() + 64);
  if (edges_.size() < size) edges_.resize(size, EdgeSlot{empty_key, 0});
  const std::size_t mask = size - 1;
  const int shift = 64 - std::countr_zero(size);
  auto slot_of = [&](std::uint64_t key) { return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15u) >> shift); };
  // With the apex as corner 3 (every finite tetrahedron of a star), face j < 3 rotated to
  // start at the apex is (corner 3, corner apex_last[j][0], corner apex_last[j][1]).
  static constexpr std::uint32_t apex_last[3][2] = {{2, 1}, {0, 2}, {1, 0}};
  pending_.clear();
  for (const TetrahedronId t : tetrahedra) {
    const VertexId* c = &corner_[4 * std::size_t{t}];
    const bool last = c[3] == apex;
    for (std::uint32_t j = 0; j < 4; ++j) {
      if (c[j] == apex) continue;
      VertexId u, w;
      if (last) {
        u = c[apex_last[j][0]], w = c[apex_last[j][1]];
      } else {
        const VertexId f0 = c[face[j][0]], f1 = c[face[j][1]], f2 = c[face[j][2]];
        u = f0 == apex ? f1 : (f1 == apex ? f2 : f0);
        w = f0 == apex ? f2 : (f1 == apex ? f0 : f1);
      }
      std::size_t s = slot_of(delaunay3_edge_key(u, w));
      while (edges_[s].key != empty_key) s = (s + 1) & mask;
      edges_[s] = {delaunay3_edge_key(u, w), 4 * t + j};
      pending_.push_back({delaunay3_edge_key(w, u), 4 * t + j, static_cast<std::uint32_t>(s)});
    }
  }
  for (const PendingFace& f : pending_) {
    std::size_t s = slot_of(f.twin);
    while (edges_[s].key != f.twin) s = (s + 1) & mask;
    adjacent_[f.half_face] = edges_[s].half_face;
  }
  for (const PendingFace& f : pending_) edges_[f.slot].key = empty_key;
}

[[gnu::always_inline]] inline bool Delaunay3::in_sphere(TetrahedronId t, const Point3& p, VertexId pid) const {
  const VertexId* c = &corner_[4 * std::size_t{t}];
  // (c1, c0, c2, c3) has orient3d > 0, where insphere > 0 means inside.
  const int s = insphere_perturbed(pt(c[1]), pt(c[0]), pt(c[2]), pt(c[3]), p);
  if (s == 0) [[unlikely]] {
    for (int i = 0; i < 4; ++i)
      if (pt(c[i]) == p) throw_duplicate(c[i], pid);
    throw std::logic_error("delaunay: the perturbed in-sphere sign is zero for distinct points");
  }
  return s > 0;
}

// Whether p is in conflict with slot t: inside its (perturbed) circumsphere, or for a ghost
// (hull face f, infinite vertex) in the limit of the spheres through f and a point going to
// infinity outside: strictly beyond f's plane, or in that plane and inside f's circumcircle.
// A point of the plane has the same power with respect to every sphere through f's circle,
// and its in-sphere sign against the finite tetrahedron behind f perturbs only the lifted
// entries of f's corners and p (the fourth corner's coefficient is orient3d(f, p) = 0): so
// that tetrahedron's answer is the circle's, perturbed consistently with every other test.
[[gnu::always_inline]] inline bool Delaunay3::conflicts(TetrahedronId t, const Point3& p, VertexId pid) const {
  const VertexId* c = &corner_[4 * std::size_t{t}];
  if (c[3] != infinite) return in_sphere(t, p, pid);
  const int s = orient3d_exact(pt(c[0]), pt(c[1]), pt(c[2]), p);
  if (s != 0) return s < 0;  // the ghost's face is counterclockwise seen from outside
  return in_sphere(adjacent_[4 * std::size_t{t} + 3] / 4, p, pid);
}

// The remembering stochastic walk (Devillers, Pion and Teillaud, "Walking in a
// triangulation"): from t, cross a face that has p strictly beyond it, looking at the faces
// in a random cyclic order and never back through the face just crossed (p is strictly on
// its inner side); stop in a tetrahedron whose closure holds p, or in the ghost beyond a hull
// face. The plain visibility walk terminates in a Delaunay (or regular) tetrahedralization,
// the in-front relation being acyclic there (Edelsbrunner 1990); the remembering variant is
// proven in 2D only, so past a generous step cap the plain stochastic walk continues.
Delaunay3::TetrahedronId Delaunay3::walk(const Point3& p, TetrahedronId start, VertexId* equal_vertex) const {
  TetrahedronId t = start;
  if (t == none || t >= flags_.size() || (flags_[t] & dead_flag)) t = last_;
  if (is_ghost(t)) t = adjacent_[4 * std::size_t{t} + 3] / 4;
  const std::size_t cap = 4 * flags_.size() + 64;
  std::uint32_t state = 0x9e3779b9u;
  std::uint32_t entry = 4;
  for (std::size_t step = 0;; ++step) {
    if (is_ghost(t)) return t;
    if (step > cap) entry = 4;
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    const std::uint32_t first = state & 3;
    const VertexId* c = &corner_[4 * std::size_t{t}];
    bool moved = false;
    for (std::uint32_t k = 0; k < 4; ++k) {
      const std::uint32_t i = (first + k) & 3;
      if (i == entry) continue;
      if (orient3d_exact(pt(c[face[i][0]]), pt(c[face[i][1]]), pt(c[face[i][2]]), p) > 0) {
        const std::uint32_t h = adjacent_[4 * t + i];
        t = h / 4;
        if (step <= cap) entry = h % 4;
        moved = true;
        break;
      }
    }
    if (!moved) {
      for (int i = 0; i < 4; ++i)
        if (pt(c[i]) == p) *equal_vertex = c[i];
      return t;
    }
  }
}

Delaunay3::TetrahedronId Delaunay3::locate(const Point3& p, TetrahedronId hint) const {
  if (flags_.empty() || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return none;
  VertexId equal = none;
  return walk(p, hint, &equal);
}

void Delaunay3::insert_vertex(VertexId v) {
  const Point3 p = pt(v);
  VertexId equal = none;
  const TetrahedronId first = walk(p, last_, &equal);
  if (equal != none) throw_duplicate(equal, v);
  // The cavity: the tetrahedra in conflict with p, reachable from the one holding p (it is
  // in conflict: p lies in its closure and is none of its corners, or strictly beyond its
  // hull face). A tetrahedron outside next to several cavity faces is tested once for each,
  // with the same exact answer (flagging it cost more than the repeated tests, which are few).
  cavity_.clear();
  boundary_.clear();
  stack_.clear();
  flags_[first] |= cavity_flag;
  cavity_.push_back(first);
  stack_.push_back(first);
  try {
    dig_cavity(p, v);
  } catch (...) {  // a duplicate point: leave no flag behind
    for (TetrahedronId t : cavity_) flags_[t] = static_cast<std::uint8_t>(flags_[t] & ~cavity_flag);
    throw;
  }
  fill_star(v);
}

void Delaunay3::dig_cavity(const Point3& p, VertexId v) {
  while (!stack_.empty()) {
    const TetrahedronId t = stack_.back();
    stack_.pop_back();
    for (std::uint32_t i = 0; i < 4; ++i) {
      const std::uint32_t across = adjacent_[4 * t + i];
      const TetrahedronId n = across / 4;
      if (flags_[n] & cavity_flag) continue;  // a face inside the cavity
      if (conflicts(n, p, v)) {
        flags_[n] |= cavity_flag;
        cavity_.push_back(n);
        stack_.push_back(n);
        continue;
      }
      const VertexId* c = &corner_[4 * std::size_t{t}];
      boundary_.push_back({{c[face[i][0]], c[face[i][1]], c[face[i][2]]}, across});
    }
  }
}

void Delaunay3::fill_star(VertexId v) {
  // The star of p: one tetrahedron (a, b, c, p) per boundary face, in the cavity's slots
  // first; one with the infinite vertex among a, b, c is a ghost, its corners evenly
  // permuted to put the infinite vertex last.
  const std::size_t m = boundary_.size();
  for (std::size_t k = m; k < cavity_.size(); ++k) {
    flags_[cavity_[k]] = dead_flag;
    free_slots_.push_back(cavity_[k]);
  }
  star_.clear();
  TetrahedronId finite = none;
  for (std::size_t k = 0; k < m; ++k) {
    const BoundaryFace& f = boundary_[k];
    TetrahedronId t;
    if (k < cavity_.size()) {
      t = cavity_[k];
      flags_[t] = 0;
    } else {
      t = new_slot();
    }
    const std::array<VertexId, 4> q{f.corner[0], f.corner[1], f.corner[2], v};
    const std::uint32_t g = q[0] == infinite ? 0 : (q[1] == infinite ? 1 : (q[2] == infinite ? 2 : 3));
    VertexId* c = &corner_[4 * std::size_t{t}];
    std::uint32_t at_v = 3;
    if (g == 3) {
      for (std::uint32_t i = 0; i < 4; ++i) c[i] = q[i];
      finite = t;
    } else {
      for (std::uint32_t i = 0; i < 3; ++i) {
        c[i] = q[face[g][i]];
        if (face[g][i] == 3) at_v = i;
      }
      c[3] = infinite;
    }
    link(4 * t + at_v, f.outer);
    star_.push_back(t);
  }
  link_around(v, star_);
  last_ = finite != none ? finite : star_.back();
}

std::vector<std::array<Delaunay3::VertexId, 4>> Delaunay3::tetrahedra() const {
  std::vector<std::array<VertexId, 4>> out;
  out.reserve(live_count_);
  for (TetrahedronId t = 0; t < flags_.size(); ++t)
    if (is_live(t)) out.push_back(vertices(t));
  return out;
}

}  // namespace certimesh::generators
