#include "refinement_mesh_3.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "certimesh/generators/delaunay/perturbed_predicates_3.h"
#include "certimesh/predicates/insphere.h"

namespace certimesh::generators::detail {

namespace {

// The walk's step bound: far beyond what a circumcentre of a mesh of any size needs (it lands
// a few tetrahedra away), small enough that a pathological walk costs microseconds.
constexpr int kMaxWalkSteps = 4096;

// The three vertices of face `face` of a tetrahedron, sorted: its key in the face matching.
std::array<std::uint32_t, 3> sorted_face(const std::uint32_t* c, int face) {
  std::array<std::uint32_t, 3> f{};
  for (int k = 0, j = 0; k < 4; ++k)
    if (k != face) f[static_cast<std::size_t>(j++)] = c[k];
  std::sort(f.begin(), f.end());
  return f;
}

std::uint64_t refinement_edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

double squared_distance_3(const Point3& a, const Point3& b) {
  const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return dx * dx + dy * dy + dz * dz;
}

}  // namespace

RefinementMesh3::RefinementMesh3(const Tetrahedralization3& mesh) : points_(mesh.points) {
  const std::size_t n = mesh.tetrahedra.size();
  corner_.resize(4 * n);
  adjacent_.assign(4 * n, none);
  label_.assign(n, 0);
  flags_.assign(n, 0);
  live_count_ = n;
  for (std::size_t t = 0; t < n; ++t) {
    const auto& c = mesh.tetrahedra[t];
    for (int k = 0; k < 4; ++k) {
      if (c[static_cast<std::size_t>(k)] >= points_.size())
        throw std::invalid_argument("tetrahedron " + std::to_string(t) + " names a vertex that does not exist");
      corner_[4 * t + static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k)];
    }
    if (-orient3d_exact(points_[c[0]], points_[c[1]], points_[c[2]], points_[c[3]]) <= 0)
      throw std::invalid_argument("tetrahedron " + std::to_string(t) + " is not positive");
    if (!mesh.labels.empty()) label_[t] = mesh.labels[t];
  }
  // Match faces by sorting their keys; a key held three times is not a mesh.
  struct Key {
    std::array<std::uint32_t, 3> face;
    std::uint32_t half_face;
  };
  std::vector<Key> keys;
  keys.reserve(4 * n);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int i = 0; i < 4; ++i) keys.push_back({sorted_face(corners(t), i), 4 * t + static_cast<std::uint32_t>(i)});
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return a.face != b.face ? a.face < b.face : a.half_face < b.half_face;
  });
  std::vector<std::array<std::uint32_t, 3>> constrained = mesh.constrained_faces;
  for (auto& f : constrained) std::sort(f.begin(), f.end());
  std::sort(constrained.begin(), constrained.end());
  for (std::size_t k = 0; k < keys.size();) {
    std::size_t e = k + 1;
    while (e < keys.size() && keys[e].face == keys[k].face) ++e;
    if (e - k > 2)
      throw std::invalid_argument("a face of tetrahedron " + std::to_string(keys[k].half_face / 4) +
                                  " is shared by more than two tetrahedra");
    if (e - k == 2) {
      const std::uint32_t a = keys[k].half_face, b = keys[k + 1].half_face;
      adjacent_[a] = b;
      adjacent_[b] = a;
      const bool interface = label_[a / 4] != label_[b / 4] ||
                             std::binary_search(constrained.begin(), constrained.end(), keys[k].face);
      if (interface) {
        flags_[a / 4] |= static_cast<std::uint8_t>(1u << (constraint_shift + static_cast<int>(a % 4)));
        flags_[b / 4] |= static_cast<std::uint8_t>(1u << (constraint_shift + static_cast<int>(b % 4)));
      }
    }
    k = e;
  }
  vertex_stamp_.assign(points_.size(), 0);
}

int RefinementMesh3::side(std::uint32_t t, int i, const Point3& p) const {
  const std::uint32_t* c = corners(t);
  const Point3* q[4] = {&points_[c[0]], &points_[c[1]], &points_[c[2]], &points_[c[3]]};
  q[i] = &p;
  return -orient3d_exact(*q[0], *q[1], *q[2], *q[3]);  // the volume sign (decision 4)
}

bool RefinementMesh3::in_sphere(std::uint32_t t, const Point3& p) const {
  const std::uint32_t* c = corners(t);
  // A positive tetrahedron has orient3d < 0, so p is inside its sphere when insphere < 0.
  return predicates::to_int(predicates::insphere(points_[c[0]], points_[c[1]], points_[c[2]], points_[c[3]], p)) < 0;
}

bool RefinementMesh3::encroaches(const CavityFace& f, const Point3& p, double ball_factor) const {
  const Point3* q[3];
  const std::uint32_t* c = corners(f.t);
  for (int k = 0, m = 0; k < 4; ++k)
    if (k != f.i) q[m++] = &points_[c[k]];
  // The circumcentre of the triangle, a + r, in double.
  const double ux = q[1]->x - q[0]->x, uy = q[1]->y - q[0]->y, uz = q[1]->z - q[0]->z;
  const double vx = q[2]->x - q[0]->x, vy = q[2]->y - q[0]->y, vz = q[2]->z - q[0]->z;
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double nn = nx * nx + ny * ny + nz * nz;
  if (!(nn > 0.0)) return false;
  const double uu = ux * ux + uy * uy + uz * uz, vv = vx * vx + vy * vy + vz * vz;
  // r = (|u|^2 (v x n) + |v|^2 (n x u)) / (2 |n|^2)
  const double rx = (uu * (vy * nz - vz * ny) + vv * (ny * uz - nz * uy)) / (2 * nn);
  const double ry = (uu * (vz * nx - vx * nz) + vv * (nz * ux - nx * uz)) / (2 * nn);
  const double rz = (uu * (vx * ny - vy * nx) + vv * (nx * uy - ny * ux)) / (2 * nn);
  const double dx = p.x - (q[0]->x + rx), dy = p.y - (q[0]->y + ry), dz = p.z - (q[0]->z + rz);
  return dx * dx + dy * dy + dz * dz < ball_factor * ball_factor * (rx * rx + ry * ry + rz * rz);
}

RefinementMesh3::Insertion RefinementMesh3::walk(const Point3& p, std::uint32_t start, std::uint32_t* found) const {
  std::uint32_t t = start;
  int came_from = -1;
  for (int step = 0; step < kMaxWalkSteps; ++step) {
    int next = -1;
    for (int k = 0; k < 4; ++k) {
      const int i = (k + step) & 3;  // rotate the first face tried, so a walk cannot cycle on ties of order
      if (i == came_from || side(t, i, p) >= 0) continue;
      next = i;
      break;
    }
    if (next < 0) {
      *found = t;
      return Insertion::inserted;
    }
    if (is_constraint(t, next)) return Insertion::behind_constraint;
    const std::uint32_t h = adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(next)];
    t = h / 4;
    came_from = static_cast<int>(h % 4);
  }
  return Insertion::walk_too_long;
}

// Grows the cavity from the seed; false as soon as a tetrahedron that joins it has a vertex
// nearer to p than `min_distance` or a constraint face whose (scaled) diametral ball holds
// p. Every vertex of a cavity tetrahedron ends on the cavity's boundary (shrink_to_star
// keeps none inside) and every constraint face of one is a boundary face, so checking them
// as they join refuses exactly what checking the final cavity would, and a little more (what
// the shrinking would drop), before the expensive part.
bool RefinementMesh3::grow_cavity(const Point3& p, std::uint32_t seed, double min_distance, double ball_factor) {
  const double clearance = min_distance * min_distance;
  cavity_.assign(1, seed);
  flags_[seed] |= cavity_flag;
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const std::uint32_t t = cavity_[k];
    const std::uint32_t* c = corners(t);
    for (int i = 0; i < 4; ++i) {
      if (squared_distance_3(points_[c[i]], p) < clearance) return false;
      if (is_constraint(t, i) && encroaches({t, i}, p, ball_factor)) return false;
    }
    for (int i = 0; i < 4; ++i) {
      if (is_constraint(t, i)) continue;
      const std::uint32_t n = adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(i)] / 4;
      if ((flags_[n] & cavity_flag) || !in_sphere(n, p)) continue;
      flags_[n] |= cavity_flag;
      cavity_.push_back(n);
    }
  }
  return true;
}

void RefinementMesh3::collect_faces() {
  faces_.clear();
  for (std::uint32_t t : cavity_)
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t h = adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(i)];
      if (h == none || !(flags_[h / 4] & cavity_flag)) faces_.push_back({t, i});
    }
}

void RefinementMesh3::keep_connected(std::uint32_t seed) {
  // The members become candidates; what the seed reaches through open faces is the cavity.
  for (std::uint32_t t : cavity_)
    flags_[t] = static_cast<std::uint8_t>((flags_[t] & ~cavity_flag) | candidate_flag);
  std::vector<std::uint32_t> candidates;
  candidates.swap(cavity_);
  cavity_.assign(1, seed);
  flags_[seed] = static_cast<std::uint8_t>((flags_[seed] & ~candidate_flag) | cavity_flag);
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const std::uint32_t t = cavity_[k];
    for (int i = 0; i < 4; ++i) {
      if (is_constraint(t, i)) continue;
      const std::uint32_t n = adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(i)] / 4;
      if (!(flags_[n] & candidate_flag)) continue;
      flags_[n] = static_cast<std::uint8_t>((flags_[n] & ~candidate_flag) | cavity_flag);
      cavity_.push_back(n);
    }
  }
  for (std::uint32_t t : candidates) flags_[t] &= static_cast<std::uint8_t>(~candidate_flag);
}

bool RefinementMesh3::shrink_to_star(const Point3& p, std::uint32_t seed) {
  for (;;) {
    collect_faces();
    std::vector<std::uint32_t> removed;
    for (const CavityFace& f : faces_)
      if (side(f.t, f.i, p) <= 0) removed.push_back(f.t);
    // A vertex of the cavity on none of its faces would vanish with it.
    ++stamp_;
    for (const CavityFace& f : faces_) {
      const std::uint32_t* c = corners(f.t);
      for (int k = 0; k < 4; ++k)
        if (k != f.i) vertex_stamp_[c[k]] = stamp_;
    }
    for (std::uint32_t t : cavity_) {
      if (t == seed) continue;
      const std::uint32_t* c = corners(t);
      for (int k = 0; k < 4; ++k)
        if (vertex_stamp_[c[k]] != stamp_) {
          removed.push_back(t);
          vertex_stamp_[c[k]] = stamp_;  // one tetrahedron out puts the vertex on the boundary
          break;
        }
    }
    if (removed.empty()) return true;
    std::sort(removed.begin(), removed.end());
    if (std::binary_search(removed.begin(), removed.end(), seed)) return false;
    for (std::uint32_t t : removed) flags_[t] &= static_cast<std::uint8_t>(~cavity_flag);
    std::erase_if(cavity_, [&](std::uint32_t t) { return !(flags_[t] & cavity_flag); });
    keep_connected(seed);
  }
}

void RefinementMesh3::clear_cavity() {
  for (std::uint32_t t : cavity_) flags_[t] &= static_cast<std::uint8_t>(~cavity_flag);
  cavity_.clear();
}

std::uint32_t RefinementMesh3::new_slot() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    flags_[t] = 0;
    return t;
  }
  const auto t = static_cast<std::uint32_t>(flags_.size());
  corner_.resize(corner_.size() + 4);
  adjacent_.resize(adjacent_.size() + 4, none);
  label_.push_back(0);
  flags_.push_back(0);
  return t;
}

void RefinementMesh3::fill(const Point3& p) {
  const auto v = static_cast<std::uint32_t>(points_.size());
  points_.push_back(p);
  vertex_stamp_.push_back(0);
  pending_.clear();
  for (const CavityFace& f : faces_) {
    NewTetrahedron n{};
    const std::uint32_t* c = corners(f.t);
    for (int k = 0; k < 4; ++k) n.corner[static_cast<std::size_t>(k)] = c[k];
    n.corner[static_cast<std::size_t>(f.i)] = v;
    n.outer = adjacent_[4 * std::size_t{f.t} + static_cast<std::size_t>(f.i)];
    n.face = f.i;
    n.constraint = (flags_[f.t] >> (constraint_shift + f.i)) & 1u;
    n.label = label_[f.t];
    pending_.push_back(n);
  }
  for (std::uint32_t t : cavity_) {
    flags_[t] = dead_flag;
    free_.push_back(t);
  }
  live_count_ -= cavity_.size();
  cavity_.clear();
  created_.clear();
  side_faces_.clear();
  for (const NewTetrahedron& n : pending_) {
    const std::uint32_t t = new_slot();
    created_.push_back(t);
    for (int k = 0; k < 4; ++k) {
      corner_[4 * std::size_t{t} + static_cast<std::size_t>(k)] = n.corner[static_cast<std::size_t>(k)];
      adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(k)] = none;
    }
    label_[t] = n.label;
    if (n.constraint) flags_[t] |= static_cast<std::uint8_t>(1u << (constraint_shift + n.face));
    const std::uint32_t h = 4 * t + static_cast<std::uint32_t>(n.face);
    adjacent_[h] = n.outer;
    if (n.outer != none) adjacent_[n.outer] = h;
    // The other three faces hold v and one edge of the cavity face: matched by that edge.
    for (int j = 0; j < 4; ++j) {
      if (j == n.face) continue;
      std::uint32_t e[2];
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != j && k != n.face) e[m++] = n.corner[static_cast<std::size_t>(k)];
      side_faces_.push_back({refinement_edge_key(e[0], e[1]), 4 * t + static_cast<std::uint32_t>(j)});
    }
  }
  live_count_ += pending_.size();
  match_side_faces();
  link_.clear();
  ++stamp_;
  for (const NewTetrahedron& n : pending_)
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t u = n.corner[static_cast<std::size_t>(k)];
      if (u != v && vertex_stamp_[u] != stamp_) {
        vertex_stamp_[u] = stamp_;
        link_.push_back(u);
      }
    }
}

// Links the new tetrahedra's side faces (each holds the new vertex and one edge of the
// cavity's boundary) in pairs by that edge, through a small open-addressing table: every key
// is held exactly twice when the cavity was star-shaped (proofs/tetrahedral_refinement_3.md).
void RefinementMesh3::match_side_faces() {
  std::size_t size = 16;
  while (size < 2 * side_faces_.size()) size *= 2;
  edge_table_.assign(size, {0, none});
  for (const auto& [key, half_face] : side_faces_) {
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & (size - 1);
    while (edge_table_[slot].second != none && edge_table_[slot].first != key) slot = (slot + 1) & (size - 1);
    auto& entry = edge_table_[slot];
    if (entry.second == none) {
      entry = {key, half_face};
    } else if (entry.second == matched) {
      throw std::logic_error("refinement: the cavity's boundary is not a closed surface (a bug)");
    } else {
      adjacent_[entry.second] = half_face;
      adjacent_[half_face] = entry.second;
      entry.second = matched;
    }
  }
  for (const auto& entry : edge_table_)
    if (entry.second != none && entry.second != matched)
      throw std::logic_error("refinement: the cavity's boundary is not a closed surface (a bug)");
}

RefinementMesh3::Insertion RefinementMesh3::insert(const Point3& p, std::uint32_t start, double min_distance,
                                                   double ball_factor) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return Insertion::walk_too_long;
  std::uint32_t t = none;
  if (const Insertion w = walk(p, start, &t); w != Insertion::inserted) return w;
  const std::uint32_t* c = corners(t);
  for (int k = 0; k < 4; ++k) {
    if (points_[c[k]] == p) return Insertion::on_vertex;
    if (is_constraint(t, k) && side(t, k, p) == 0) return Insertion::on_constraint;
  }
  if (!grow_cavity(p, t, min_distance, ball_factor)) {
    clear_cavity();
    return Insertion::too_close;
  }
  if (!shrink_to_star(p, t)) {
    clear_cavity();
    return Insertion::not_visible;
  }
  fill(p);
  return Insertion::inserted;
}

void RefinementMesh3::export_to(Tetrahedralization3& mesh) const {
  mesh.points = points_;
  mesh.tetrahedra.clear();
  mesh.labels.clear();
  mesh.tetrahedra.reserve(live_count_);
  mesh.labels.reserve(live_count_);
  for (std::uint32_t t = 0; t < flags_.size(); ++t) {
    if (!is_live(t)) continue;
    const std::uint32_t* c = corners(t);
    mesh.tetrahedra.push_back({c[0], c[1], c[2], c[3]});
    mesh.labels.push_back(label_[t]);
  }
}

}  // namespace certimesh::generators::detail
