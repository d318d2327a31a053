// Valid simplicial meshes built independently of certimesh's generators, as seeds for the
// certificate's tests and benchmark: Kuhn-subdivided structured grids (2D: each square into 2
// triangles; 3D: each cube into 6 tetrahedra around its main diagonal), optionally with a
// block of cells removed (a hole) and interior vertices jittered, plus the matching domains
// (a square .poly with 4 coarse segments; a cube surface of 12 triangles).
//
// Why these are valid: an unjittered Kuhn grid is the standard Freudenthal triangulation
// (conforming because every cell splits along the same diagonal direction). Jitter moves
// a vertex by at most 1/8 of a cell per coordinate, and every Kuhn element has all heights
// >= 1/sqrt(2), which no two such moves can overcome. The tests still verify every element's
// orientation with the rational oracle before using a mesh.
//
// Exactness: coordinates are integers plus multiples of 2^-8, so the sums and halvings the
// mutations (mesh_mutations.h) apply to them are exact in double.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::fuzz {

/// A block of cells [lo, hi) per axis removed from a grid; empty when lo == hi on an axis.
struct CellBlock {
  std::array<int, 3> lo{0, 0, 0};
  std::array<int, 3> hi{0, 0, 0};
  bool empty() const { return lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]; }
  bool contains_cell(int i, int j, int k) const {
    return i >= lo[0] && i < hi[0] && j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2];
  }
};

/// A grid of n[0] x n[1] (x n[2]) unit cells over [0, n]. `jitter_seed` == 0 means no jitter;
/// otherwise interior vertices off the hole's boundary move by k/256, |k| <= 31, per coordinate,
/// drawn from std::mt19937_64(jitter_seed) in vertex order (deterministic).
struct GridSpec {
  int dimension = 2;
  std::array<int, 3> cells{4, 4, 1};
  CellBlock hole;  // for 2D, keep lo[2] = 0, hi[2] = 1 to mean "the whole (single) layer"
  std::uint64_t jitter_seed = 0;
};

/// A block of cells of a 2D grid: [x0, x1) x [y0, y1) in the single layer k = 0.
inline CellBlock cell_block_2d(int x0, int y0, int x1, int y1) { return {{x0, y0, 0}, {x1, y1, 1}}; }

namespace detail {

inline std::size_t grid_vertex_id(const GridSpec& g, int i, int j, int k) {
  const auto nx = static_cast<std::size_t>(g.cells[0] + 1);
  const auto ny = static_cast<std::size_t>(g.cells[1] + 1);
  return (static_cast<std::size_t>(k) * ny + static_cast<std::size_t>(j)) * nx +
         static_cast<std::size_t>(i);
}

inline bool cell_removed(const GridSpec& g, int i, int j, int k) {
  return !g.hole.empty() && g.hole.contains_cell(i, j, k);
}

// True when grid vertex (i, j, k) is a corner of some removed cell (on the hole's boundary or
// inside it): such vertices stay unjittered so that they lie exactly on the hole's segments.
inline bool touches_hole(const GridSpec& g, int i, int j, int k) {
  if (g.hole.empty()) return false;
  const int layers = g.dimension == 3 ? 1 : 0;
  for (int dk = -layers; dk <= 0; ++dk)
    for (int dj = -1; dj <= 0; ++dj)
      for (int di = -1; di <= 0; ++di)
        if (cell_removed(g, i + di, j + dj, k + dk)) return true;
  return false;
}

inline bool on_outer_boundary(const GridSpec& g, int i, int j, int k) {
  bool on = i == 0 || i == g.cells[0] || j == 0 || j == g.cells[1];
  if (g.dimension == 3) on = on || k == 0 || k == g.cells[2];
  return on;
}

// The 6 Kuhn tetrahedra of a cube: the paths 000 -> 111 along the axes in every order. The
// path in axis order sigma has volume sign sign(sigma); odd ones swap their last two vertices.
inline const std::array<std::array<int, 3>, 6>& kuhn_axis_orders() {
  static const std::array<std::array<int, 3>, 6> orders{
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  return orders;
}

// Drops vertices no element uses (those strictly inside a hole) and renumbers the rest in
// their original order.
inline void compact_vertices(io::MeshData& mesh) {
  const std::size_t d = static_cast<std::size_t>(mesh.dimension);
  std::vector<io::Index>& elements = mesh.dimension == 2 ? mesh.triangles : mesh.tetrahedra;
  std::vector<std::int64_t> new_id(mesh.point_count(), -1);
  for (io::Index v : elements) new_id[v] = 0;
  std::vector<double> kept;
  std::int64_t next = 0;
  for (std::size_t v = 0; v < new_id.size(); ++v) {
    if (new_id[v] < 0) continue;
    new_id[v] = next++;
    for (std::size_t c = 0; c < d; ++c) kept.push_back(mesh.coordinates[v * d + c]);
  }
  for (io::Index& v : elements) v = static_cast<io::Index>(new_id[v]);
  mesh.coordinates = std::move(kept);
}

}  // namespace detail

/// The Kuhn-subdivided grid of `g`: positively oriented elements (counterclockwise triangles;
/// tetrahedra with det[b-a, c-a, d-a] > 0), labels 0, no unused vertex.
inline io::MeshData kuhn_grid(const GridSpec& g) {
  io::MeshData mesh;
  mesh.dimension = g.dimension;
  const int nz = g.dimension == 3 ? g.cells[2] : 0;
  std::mt19937_64 rng(g.jitter_seed);
  std::uniform_int_distribution<int> jitter(-31, 31);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= g.cells[1]; ++j)
      for (int i = 0; i <= g.cells[0]; ++i) {
        const bool movable = g.jitter_seed != 0 && !detail::on_outer_boundary(g, i, j, k) &&
                             !detail::touches_hole(g, i, j, k);
        const std::array<int, 3> ijk{i, j, k};
        for (int c = 0; c < g.dimension; ++c) {
          const double offset = movable ? jitter(rng) / 256.0 : 0.0;
          mesh.coordinates.push_back(ijk[static_cast<std::size_t>(c)] + offset);
        }
      }
  if (g.dimension == 2) {
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        if (detail::cell_removed(g, i, j, 0)) continue;
        const auto v00 = static_cast<io::Index>(detail::grid_vertex_id(g, i, j, 0));
        const auto v10 = static_cast<io::Index>(detail::grid_vertex_id(g, i + 1, j, 0));
        const auto v11 = static_cast<io::Index>(detail::grid_vertex_id(g, i + 1, j + 1, 0));
        const auto v01 = static_cast<io::Index>(detail::grid_vertex_id(g, i, j + 1, 0));
        mesh.triangles.insert(mesh.triangles.end(), {v00, v10, v11, v00, v11, v01});
      }
    mesh.triangle_labels.assign(mesh.triangle_count(), 0);
  } else {
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < g.cells[1]; ++j)
        for (int i = 0; i < g.cells[0]; ++i) {
          if (detail::cell_removed(g, i, j, k)) continue;
          for (std::size_t o = 0; o < 6; ++o) {
            std::array<int, 3> at{i, j, k};
            std::array<io::Index, 4> tet{};
            tet[0] = static_cast<io::Index>(detail::grid_vertex_id(g, at[0], at[1], at[2]));
            for (std::size_t step = 0; step < 3; ++step) {
              ++at[static_cast<std::size_t>(detail::kuhn_axis_orders()[o][step])];
              tet[step + 1] =
                  static_cast<io::Index>(detail::grid_vertex_id(g, at[0], at[1], at[2]));
            }
            if (o >= 3) std::swap(tet[2], tet[3]);  // odd axis order: restore a positive volume
            mesh.tetrahedra.insert(mesh.tetrahedra.end(), tet.begin(), tet.end());
          }
        }
    mesh.tetrahedron_labels.assign(mesh.tetrahedron_count(), 0);
  }
  detail::compact_vertices(mesh);
  return mesh;
}

/// The 2D domain of a grid as a .poly holds it: the outer square [0,nx]x[0,ny] as 4 segments
/// (corners only, so the mesh splits them at the grid vertices exactly on them) and, when
/// `g.hole` is set, the hole's 4 segments and one hole point at its centre.
inline io::MeshData square_domain(const GridSpec& g) {
  io::MeshData d;
  d.dimension = 2;
  const auto add_square = [&d](double x0, double y0, double x1, double y1) {
    const auto base = static_cast<io::Index>(d.point_count());
    // push_back, not insert({...}): GCC 12 reports a false stringop-overflow on the latter.
    for (double c : {x0, y0, x1, y0, x1, y1, x0, y1}) d.coordinates.push_back(c);
    for (io::Index s = 0; s < 4; ++s) d.segments.insert(d.segments.end(), {base + s, base + (s + 1) % 4});
  };
  add_square(0, 0, g.cells[0], g.cells[1]);
  if (!g.hole.empty()) {
    add_square(g.hole.lo[0], g.hole.lo[1], g.hole.hi[0], g.hole.hi[1]);
    d.holes = {(g.hole.lo[0] + g.hole.hi[0]) / 2.0, (g.hole.lo[1] + g.hole.hi[1]) / 2.0};
  }
  d.segment_labels.assign(d.segment_count(), 0);
  return d;
}

/// Appends the surface of the box [lo, hi]^3 to `d` as 12 triangles, each face split along the
/// diagonal from its lowest to its highest corner -- the direction in which the Kuhn grid
/// splits every face square, so that the mesh's boundary facets tile each triangle when lo
/// and hi are grid coordinates. Oriented outward, or inward (`inward`, for a hole's surface).
inline void append_box_surface(io::MeshData& d, double lo, double hi, bool inward) {
  const auto base = static_cast<io::Index>(d.point_count());
  for (int c = 0; c < 8; ++c)
    for (int axis = 0; axis < 3; ++axis) d.coordinates.push_back(((c >> axis) & 1) ? hi : lo);
  // Each face: its 4 corners (bit 0 = x, 1 = y, 2 = z) counterclockwise seen from outside,
  // starting at the lowest, so (q0, q1, q2) and (q0, q2, q3) split it along the low-high diagonal.
  const std::array<std::array<io::Index, 4>, 6> faces{{{0, 2, 3, 1},   // z = lo
                                                        {4, 5, 7, 6},   // z = hi
                                                        {0, 1, 5, 4},   // y = lo
                                                        {2, 6, 7, 3},   // y = hi
                                                        {0, 4, 6, 2},   // x = lo
                                                        {1, 3, 7, 5}}};  // x = hi
  for (const auto& q : faces) {
    std::array<io::Index, 6> t{q[0], q[1], q[2], q[0], q[2], q[3]};
    if (inward) std::swap(t[1], t[2]), std::swap(t[4], t[5]);
    for (io::Index v : t) d.triangles.push_back(base + v);
  }
  d.triangle_labels.assign(d.triangle_count(), 0);
}

/// The 3D domain of an n x n x n grid: the cube [0,n]^3 as 12 outward triangles.
inline io::MeshData cube_surface_domain(int n) {
  io::MeshData d;
  d.dimension = 3;
  append_box_surface(d, 0, n, false);
  return d;
}

}  // namespace certimesh::fuzz
