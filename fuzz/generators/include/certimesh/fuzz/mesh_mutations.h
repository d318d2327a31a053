// One-mutation breakers for valid meshes (valid_meshes.h): each function changes a valid
// mesh in exactly one way and returns where, so that a test can assert that the certificate
// rejects it with the reason the mutation implies, at the mutated element or vertex.
// tests/certificate/README.md maps every mutation to the Defect it must produce and why.
//
// Candidates (elements, facets, vertices) are enumerated in index order and `choice` picks
// one modulo their count, so a RapidCheck-drawn choice reproduces from its seed. A function
// returns std::nullopt when the mesh has no candidate for it.
//
// Every new point is an exact dyadic combination of existing points (coordinates are
// integers plus multiples of 2^-8, so the sums and powers-of-two divisions below are exact);
// new points that must not coincide with an existing vertex are offset by a multiple of
// 2^-10 or 2^-12, off the 2^-8 lattice every grid vertex lies on.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::fuzz {

/// Where a mutation acted: the elements and vertices it created or changed (0-based indices
/// into the mutated mesh).
struct MutationSite {
  std::vector<std::int64_t> elements;
  std::vector<std::int64_t> vertices;
};

using Point3 = std::array<double, 3>;  // z = 0 in 2D
using Simplex = std::vector<io::Index>;

// ---- element access, the same for triangles (2D) and tetrahedra (3D) ----

inline std::size_t simplex_size(const io::MeshData& m) { return static_cast<std::size_t>(m.dimension) + 1; }
inline std::vector<io::Index>& element_array(io::MeshData& m) { return m.dimension == 2 ? m.triangles : m.tetrahedra; }
inline const std::vector<io::Index>& element_array(const io::MeshData& m) {
  return m.dimension == 2 ? m.triangles : m.tetrahedra;
}
inline std::size_t element_count(const io::MeshData& m) { return element_array(m).size() / simplex_size(m); }

inline Simplex element(const io::MeshData& m, std::size_t e) {
  const auto first = element_array(m).begin() + static_cast<std::ptrdiff_t>(e * simplex_size(m));
  return Simplex(first, first + static_cast<std::ptrdiff_t>(simplex_size(m)));
}

inline void set_element(io::MeshData& m, std::size_t e, const Simplex& s) {
  std::copy(s.begin(), s.end(), element_array(m).begin() + static_cast<std::ptrdiff_t>(e * simplex_size(m)));
}

inline std::int64_t add_element(io::MeshData& m, const Simplex& s) {
  element_array(m).insert(element_array(m).end(), s.begin(), s.end());
  std::vector<io::Label>& labels = m.dimension == 2 ? m.triangle_labels : m.tetrahedron_labels;
  if (!labels.empty()) labels.push_back(0);
  return static_cast<std::int64_t>(element_count(m) - 1);
}

inline void remove_element(io::MeshData& m, std::size_t e) {
  const auto first = element_array(m).begin() + static_cast<std::ptrdiff_t>(e * simplex_size(m));
  element_array(m).erase(first, first + static_cast<std::ptrdiff_t>(simplex_size(m)));
  std::vector<io::Label>& labels = m.dimension == 2 ? m.triangle_labels : m.tetrahedron_labels;
  if (!labels.empty()) labels.erase(labels.begin() + static_cast<std::ptrdiff_t>(e));
}

inline Point3 point(const io::MeshData& m, io::Index v) {
  const std::size_t d = static_cast<std::size_t>(m.dimension);
  Point3 p{0, 0, 0};
  for (std::size_t c = 0; c < d; ++c) p[c] = m.coordinates[v * d + c];
  return p;
}

inline void set_point(io::MeshData& m, io::Index v, const Point3& p) {
  const std::size_t d = static_cast<std::size_t>(m.dimension);
  for (std::size_t c = 0; c < d; ++c) m.coordinates[v * d + c] = p[c];
}

inline io::Index add_point(io::MeshData& m, const Point3& p) {
  const auto v = static_cast<io::Index>(m.point_count());
  for (int c = 0; c < m.dimension; ++c) m.coordinates.push_back(p[static_cast<std::size_t>(c)]);
  if (!m.point_labels.empty()) m.point_labels.push_back(0);
  return v;
}

/// sum_i w_i p_i / denominator, exact for the lattices described above.
inline Point3 combination(const std::vector<Point3>& points, const std::vector<double>& weights,
                          double denominator) {
  Point3 r{0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) r[c] += weights[i] * points[i][c];
  for (double& x : r) x /= denominator;
  return r;
}

// ---- facets (sorted vertex lists, in a std::map: deterministic order, test-sized meshes) ----

using FacetMap = std::map<Simplex, std::vector<std::size_t>>;

inline Simplex facet_opposite(const Simplex& s, std::size_t position) {
  Simplex f;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (i != position) f.push_back(s[i]);
  std::sort(f.begin(), f.end());
  return f;
}

/// Every facet with the elements that have it.
inline FacetMap facet_elements(const io::MeshData& m) {
  FacetMap facets;
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    for (std::size_t o = 0; o < s.size(); ++o) facets[facet_opposite(s, o)].push_back(e);
  }
  return facets;
}

/// Vertices on a facet that has exactly one element.
inline std::vector<bool> boundary_vertices(const io::MeshData& m) {
  std::vector<bool> on(m.point_count(), false);
  for (const auto& [facet, owners] : facet_elements(m))
    if (owners.size() == 1)
      for (io::Index v : facet) on[v] = true;
  return on;
}

inline std::vector<std::size_t> vertex_use_counts(const io::MeshData& m) {
  std::vector<std::size_t> uses(m.point_count(), 0);
  for (io::Index v : element_array(m)) ++uses[v];
  return uses;
}

/// A point strictly inside facet f (exact): the midpoint in 2D, (a + b + 2c)/4 in 3D.
inline Point3 point_inside_facet(const io::MeshData& m, const Simplex& f) {
  if (f.size() == 2) return combination({point(m, f[0]), point(m, f[1])}, {1, 1}, 2);
  return combination({point(m, f[0]), point(m, f[1]), point(m, f[2])}, {1, 1, 2}, 4);
}

template <typename T>
std::optional<T> pick(const std::vector<T>& candidates, std::uint64_t choice) {
  if (candidates.empty()) return std::nullopt;
  return candidates[choice % candidates.size()];
}

/// (element, position) pairs whose vertex is not on the boundary.
inline std::vector<std::pair<std::size_t, std::size_t>> interior_corners(const io::MeshData& m) {
  const std::vector<bool> on_boundary = boundary_vertices(m);
  std::vector<std::pair<std::size_t, std::size_t>> corners;
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    for (std::size_t k = 0; k < s.size(); ++k)
      if (!on_boundary[s[k]]) corners.emplace_back(e, k);
  }
  return corners;
}

// ---- the mutations ----

/// Moves an interior vertex v of element e to p + (p - v)/2, p a point of the facet of e
/// opposite v: v crosses that facet, so e turns over (its volume is multiplied by -1/2).
inline std::optional<MutationSite> invert_element(io::MeshData& m, std::uint64_t choice) {
  const auto corner = pick(interior_corners(m), choice);
  if (!corner) return std::nullopt;
  const auto [e, k] = *corner;
  const Simplex s = element(m, e);
  const Point3 p = point_inside_facet(m, facet_opposite(s, k));
  set_point(m, s[k], combination({p, point(m, s[k])}, {3, -1}, 2));
  return MutationSite{{static_cast<std::int64_t>(e)}, {static_cast<std::int64_t>(s[k])}};
}

/// Moves an interior vertex v of element e onto the facet of e opposite v (an exact point of
/// it): e becomes exactly flat.
inline std::optional<MutationSite> flatten_element(io::MeshData& m, std::uint64_t choice) {
  const auto corner = pick(interior_corners(m), choice);
  if (!corner) return std::nullopt;
  const auto [e, k] = *corner;
  const Simplex s = element(m, e);
  set_point(m, s[k], point_inside_facet(m, facet_opposite(s, k)));
  return MutationSite{{static_cast<std::int64_t>(e)}, {static_cast<std::int64_t>(s[k])}};
}

struct InteriorFacet {
  std::size_t element;   // the element that is split
  std::size_t position;  // its vertex opposite the facet
  std::size_t other;     // the element across the facet, left as it is
};

inline std::vector<InteriorFacet> interior_facets(const io::MeshData& m) {
  std::vector<InteriorFacet> found;
  const FacetMap facets = facet_elements(m);
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    for (std::size_t o = 0; o < s.size(); ++o) {
      const std::vector<std::size_t>& owners = facets.at(facet_opposite(s, o));
      if (owners.size() == 2) found.push_back({e, o, owners[0] == e ? owners[1] : owners[0]});
    }
  }
  return found;
}

/// Splits an interior facet on one side only (a T-junction): a new vertex m strictly inside
/// the facet, and the element on one side replaced by the dim elements that join m to its
/// other facets (same orientation); the element on the other side keeps the whole facet.
/// Only facets with no vertex on the boundary: otherwise the new boundary would also touch
/// the old one at that vertex (a non-manifold boundary, reported before a T-junction).
inline std::optional<MutationSite> split_facet_one_side(io::MeshData& m, std::uint64_t choice) {
  const std::vector<bool> on_boundary = boundary_vertices(m);
  std::vector<InteriorFacet> candidates;
  for (const InteriorFacet& f : interior_facets(m)) {
    const Simplex s = element(m, f.element);
    bool touches = false;
    for (std::size_t k = 0; k < s.size(); ++k) touches = touches || (k != f.position && on_boundary[s[k]]);
    if (!touches) candidates.push_back(f);
  }
  const auto facet = pick(candidates, choice);
  if (!facet) return std::nullopt;
  const Simplex s = element(m, facet->element);
  const io::Index mid = add_point(m, point_inside_facet(m, facet_opposite(s, facet->position)));
  MutationSite site{{static_cast<std::int64_t>(facet->other)}, {static_cast<std::int64_t>(mid)}};
  bool first = true;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (k == facet->position) continue;
    Simplex part = s;
    part[k] = mid;
    if (first) {
      set_element(m, facet->element, part);
      site.elements.push_back(static_cast<std::int64_t>(facet->element));
      first = false;
    } else {
      site.elements.push_back(add_element(m, part));
    }
  }
  return site;
}

/// Adds a small element strictly inside element e, oriented like it: its vertex i is
/// (w p_i + sum_{j != i} p_j) / (w + dim), w = 2 in 2D and 5 in 3D (denominators 4 and 8).
inline std::optional<MutationSite> add_element_inside(io::MeshData& m, std::uint64_t choice) {
  if (element_count(m) == 0) return std::nullopt;
  const std::size_t e = choice % element_count(m);
  const Simplex s = element(m, e);
  std::vector<Point3> corners;
  for (io::Index v : s) corners.push_back(point(m, v));
  const double heavy = m.dimension == 2 ? 2 : 5;
  MutationSite site{{static_cast<std::int64_t>(e)}, {}};
  Simplex inner;
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::vector<double> w(s.size(), 1.0);
    w[i] = heavy;
    inner.push_back(add_point(m, combination(corners, w, heavy + m.dimension)));
    site.vertices.push_back(inner.back());
  }
  site.elements.push_back(add_element(m, inner));
  return site;
}

/// Appends a copy of the whole mesh scaled by 1/2 about the centre of its bounding box and
/// moved by 2^-12 per axis (off every original coordinate): a second, nested cover.
inline MutationSite add_scaled_copy(io::MeshData& m) {
  const std::size_t n = m.point_count();
  Point3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t c = 0; c < static_cast<std::size_t>(m.dimension); ++c) {
    lo[c] = std::numeric_limits<double>::infinity();
    hi[c] = -lo[c];
    for (io::Index v = 0; v < n; ++v) {
      lo[c] = std::min(lo[c], point(m, v)[c]);
      hi[c] = std::max(hi[c], point(m, v)[c]);
    }
  }
  const Point3 centre = combination({lo, hi}, {1, 1}, 2);
  MutationSite site;
  for (io::Index v = 0; v < n; ++v) {
    Point3 p = combination({centre, point(m, v)}, {1, 1}, 2);
    for (std::size_t c = 0; c < static_cast<std::size_t>(m.dimension); ++c) p[c] += 1.0 / 4096;
    site.vertices.push_back(add_point(m, p));
  }
  const std::size_t elements = element_count(m);
  for (std::size_t e = 0; e < elements; ++e) {
    Simplex s = element(m, e);
    for (io::Index& v : s) v += static_cast<io::Index>(n);
    site.elements.push_back(add_element(m, s));
  }
  return site;
}

/// Removes an element none of whose vertices is on the boundary: a hole bounded by its facets.
inline std::optional<MutationSite> remove_interior_element(io::MeshData& m, std::uint64_t choice) {
  const std::vector<bool> on_boundary = boundary_vertices(m);
  std::vector<std::size_t> candidates;
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    if (std::none_of(s.begin(), s.end(), [&](io::Index v) { return on_boundary[v]; }))
      candidates.push_back(e);
  }
  const auto e = pick(candidates, choice);
  if (!e) return std::nullopt;
  const Simplex s = element(m, *e);
  remove_element(m, *e);
  MutationSite site;
  for (io::Index v : s) site.vertices.push_back(v);
  return site;
}

/// Removes an element that has a boundary facet and whose other vertex is interior: the
/// boundary now runs through that vertex instead of along the facet.
inline std::optional<MutationSite> remove_boundary_element(io::MeshData& m, std::uint64_t choice) {
  const std::vector<bool> on_boundary = boundary_vertices(m);
  const FacetMap facets = facet_elements(m);
  std::vector<std::size_t> candidates;
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    for (std::size_t o = 0; o < s.size(); ++o)
      if (!on_boundary[s[o]] && facets.at(facet_opposite(s, o)).size() == 1) candidates.push_back(e);
  }
  const auto e = pick(candidates, choice);
  if (!e) return std::nullopt;
  const Simplex s = element(m, *e);
  remove_element(m, *e);
  MutationSite site;
  for (io::Index v : s) site.vertices.push_back(v);
  return site;
}

/// Cuts off the corner of a box-shaped mesh at (max x, min y[, min z]): removes the elements
/// of the vertex there and the vertex itself (later vertices shift down by one). In a Kuhn
/// grid every vertex of the new boundary facets is still on the box's boundary, but those
/// facets cross the corner: they lie on no single side/face. Returns nullopt when no vertex
/// sits exactly at that corner.
inline std::optional<MutationSite> cut_box_corner(io::MeshData& m) {
  const std::size_t d = static_cast<std::size_t>(m.dimension);
  Point3 corner{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                std::numeric_limits<double>::infinity()};
  for (io::Index v = 0; v < m.point_count(); ++v) {
    const Point3 p = point(m, v);
    corner[0] = std::max(corner[0], p[0]);
    for (std::size_t c = 1; c < d; ++c) corner[c] = std::min(corner[c], p[c]);
  }
  if (d == 2) corner[2] = 0;
  io::Index cut = 0;
  while (cut < m.point_count() && point(m, cut) != corner) ++cut;
  if (cut == m.point_count()) return std::nullopt;
  for (std::size_t e = element_count(m); e-- > 0;) {
    const Simplex s = element(m, e);
    if (std::find(s.begin(), s.end(), cut) != s.end()) remove_element(m, e);
  }
  m.coordinates.erase(m.coordinates.begin() + static_cast<std::ptrdiff_t>(cut * d),
                      m.coordinates.begin() + static_cast<std::ptrdiff_t>((cut + 1) * d));
  if (!m.point_labels.empty()) m.point_labels.erase(m.point_labels.begin() + static_cast<std::ptrdiff_t>(cut));
  for (io::Index& v : element_array(m))
    if (v > cut) --v;
  return MutationSite{};
}

/// Removes an element with exactly one vertex on the boundary: the boundary then passes
/// through that vertex twice (a pinch).
inline std::optional<MutationSite> remove_element_pinching_boundary(io::MeshData& m, std::uint64_t choice) {
  const std::vector<bool> on_boundary = boundary_vertices(m);
  std::vector<std::pair<std::size_t, io::Index>> candidates;
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    const auto count = std::count_if(s.begin(), s.end(), [&](io::Index v) { return on_boundary[v]; });
    if (count != 1) continue;
    for (io::Index v : s)
      if (on_boundary[v]) candidates.emplace_back(e, v);
  }
  const auto c = pick(candidates, choice);
  if (!c) return std::nullopt;
  remove_element(m, c->first);
  return MutationSite{{}, {static_cast<std::int64_t>(c->second)}};
}

/// Appends a copy of element e with its vertices permuted (permutation number `perm`).
inline std::optional<MutationSite> duplicate_element(io::MeshData& m, std::uint64_t choice, std::uint64_t perm) {
  if (element_count(m) == 0) return std::nullopt;
  const std::size_t e = choice % element_count(m);
  Simplex copy = element(m, e);
  std::sort(copy.begin(), copy.end());
  for (std::uint64_t i = 0; i < perm % (m.dimension == 2 ? 6 : 24); ++i)
    std::next_permutation(copy.begin(), copy.end());
  return MutationSite{{static_cast<std::int64_t>(e), add_element(m, copy)}, {}};
}

/// Moves a vertex that lies inside one face (3D) or side (2D) of the bounding box -- exactly
/// one coordinate extreme -- by 1/256 across that face, outward or inward.
inline std::optional<MutationSite> move_boundary_vertex_off(io::MeshData& m, std::uint64_t choice, bool outward) {
  const std::size_t d = static_cast<std::size_t>(m.dimension);
  Point3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t c = 0; c < d; ++c) {
    lo[c] = std::numeric_limits<double>::infinity();
    hi[c] = -lo[c];
    for (io::Index v = 0; v < m.point_count(); ++v) {
      lo[c] = std::min(lo[c], point(m, v)[c]);
      hi[c] = std::max(hi[c], point(m, v)[c]);
    }
  }
  std::vector<std::pair<io::Index, double>> candidates;  // vertex, signed outward move
  for (io::Index v = 0; v < m.point_count(); ++v) {
    const Point3 p = point(m, v);
    std::size_t extreme = 0;
    double move = 0;
    for (std::size_t c = 0; c < d; ++c) {
      if (p[c] == lo[c]) ++extreme, move = -1.0 / 256;
      if (p[c] == hi[c]) ++extreme, move = 1.0 / 256;
    }
    if (extreme == 1) candidates.emplace_back(v, move);
  }
  const auto c = pick(candidates, choice);
  if (!c) return std::nullopt;
  Point3 p = point(m, c->first);
  for (std::size_t axis = 0; axis < d; ++axis)
    if (p[axis] == lo[axis] || p[axis] == hi[axis]) p[axis] += outward ? c->second : -c->second;
  set_point(m, c->first, p);
  return MutationSite{{}, {static_cast<std::int64_t>(c->first)}};
}

/// Adds a third element on an interior facet: the split element's copy with its opposite
/// vertex replaced by a new vertex 2^-10 away from it on every axis.
inline std::optional<MutationSite> add_third_element_on_facet(io::MeshData& m, std::uint64_t choice) {
  const auto facet = pick(interior_facets(m), choice);
  if (!facet) return std::nullopt;
  Simplex s = element(m, facet->element);
  Point3 p = point(m, s[facet->position]);
  for (std::size_t c = 0; c < static_cast<std::size_t>(m.dimension); ++c) p[c] += 1.0 / 1024;
  s[facet->position] = add_point(m, p);
  const std::int64_t third = add_element(m, s);
  return MutationSite{{static_cast<std::int64_t>(facet->element), static_cast<std::int64_t>(facet->other), third},
                      {static_cast<std::int64_t>(s[facet->position])}};
}

/// Swaps the first two vertices of an element that has an interior facet.
inline std::optional<MutationSite> swap_two_vertices(io::MeshData& m, std::uint64_t choice) {
  std::vector<std::size_t> candidates;
  for (const InteriorFacet& f : interior_facets(m))
    if (candidates.empty() || candidates.back() != f.element) candidates.push_back(f.element);
  const auto e = pick(candidates, choice);
  if (!e) return std::nullopt;
  Simplex s = element(m, *e);
  std::swap(s[0], s[1]);
  set_element(m, *e, s);
  MutationSite site{{static_cast<std::int64_t>(*e)}, {}};
  for (const InteriorFacet& f : interior_facets(m))
    if (f.element == *e) site.elements.push_back(static_cast<std::int64_t>(f.other));
  return site;
}

/// Appends a vertex no element uses, beyond the mesh on the first axis.
inline MutationSite add_unused_vertex(io::MeshData& m) {
  double far = 0;
  for (io::Index v = 0; v < m.point_count(); ++v) far = std::max(far, point(m, v)[0]);
  return MutationSite{{}, {add_point(m, {far + 1, 0.5, 0.5})}};
}

/// Appends a vertex with the coordinates of vertex s[k] of element e and points e at it.
inline std::optional<MutationSite> add_duplicate_vertex(io::MeshData& m, std::uint64_t choice) {
  if (element_count(m) == 0) return std::nullopt;
  const std::size_t e = choice % element_count(m);
  const std::size_t k = (choice / element_count(m)) % simplex_size(m);
  Simplex s = element(m, e);
  const io::Index original = s[k];
  s[k] = add_point(m, point(m, original));
  set_element(m, e, s);
  return MutationSite{{static_cast<std::int64_t>(e)}, {static_cast<std::int64_t>(original), s[k]}};
}

/// Replaces vertex s[k] of element e by another of its vertices, where s[k] has other
/// elements (so that it does not become unused).
inline std::optional<MutationSite> repeat_vertex_in_element(io::MeshData& m, std::uint64_t choice) {
  const std::vector<std::size_t> uses = vertex_use_counts(m);
  std::vector<std::pair<std::size_t, std::size_t>> candidates;
  for (std::size_t e = 0; e < element_count(m); ++e) {
    const Simplex s = element(m, e);
    for (std::size_t k = 0; k < s.size(); ++k)
      if (uses[s[k]] >= 2) candidates.emplace_back(e, k);
  }
  const auto c = pick(candidates, choice);
  if (!c) return std::nullopt;
  Simplex s = element(m, c->first);
  s[c->second] = s[(c->second + 1) % s.size()];
  set_element(m, c->first, s);
  return MutationSite{{static_cast<std::int64_t>(c->first)}, {}};
}

/// Points vertex k of element e past the last vertex.
inline std::optional<MutationSite> index_out_of_range(io::MeshData& m, std::uint64_t choice) {
  if (element_count(m) == 0) return std::nullopt;
  const std::size_t e = choice % element_count(m);
  Simplex s = element(m, e);
  s[(choice / element_count(m)) % s.size()] = static_cast<io::Index>(m.point_count() + choice % 3);
  set_element(m, e, s);
  return MutationSite{{static_cast<std::int64_t>(e)}, {}};
}

/// Sets one coordinate of a vertex to NaN, +Inf or -Inf.
inline MutationSite make_coordinate_non_finite(io::MeshData& m, std::uint64_t choice) {
  const std::array<double, 3> values{std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::infinity(),
                                     -std::numeric_limits<double>::infinity()};
  const std::size_t slot = choice % m.coordinates.size();
  m.coordinates[slot] = values[(choice / m.coordinates.size()) % 3];
  return MutationSite{{}, {static_cast<std::int64_t>(slot / static_cast<std::size_t>(m.dimension))}};
}

}  // namespace certimesh::fuzz
