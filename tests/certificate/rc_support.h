// RapidCheck plumbing shared by the certificate's property tests: a fixed seed, grid draws,
// and the assertion that a mesh is rejected for the expected reason at the mutated place.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "defect_printer.h"
#include "certimesh/fuzz/mesh_mutations.h"
#include "certimesh/fuzz/valid_meshes.h"
#include "mesh_oracle.h"

namespace certimesh::testing {

// RC_GTEST_PROP reads RC_PARAMS when the first property runs, after static initialisation:
// fix the seed here so that every run draws the same cases, unless the caller set RC_PARAMS
// (to reproduce a reported failure, or to vary the seed on purpose).
// Under the sanitizers (5-10x slower, there for memory errors and undefined behaviour) a
// quarter of the cases.
inline const bool rc_seed_fixed = [] {
#if defined(__SANITIZE_ADDRESS__)
  setenv("RC_PARAMS", "seed=4242424242 max_success=15", 0);
#else
  setenv("RC_PARAMS", "seed=4242424242 max_success=60", 0);
#endif
  return true;
}();

struct DrawnGrid {
  fuzz::GridSpec spec;
  io::MeshData mesh;
  io::MeshData domain;  // the square (2D) or cube (3D) the grid fills
};

/// A Kuhn grid: 2D 3..8 x 3..8 cells, 3D n^3 cells with n in 3..4 (cubes, so that the cube
/// domain's face diagonals follow the grid's), jittered unless `jitter` is false, and, when
/// `allow_hole` and a coin says so, without the block [2, n-2) per axis (its domain then
/// has that block's boundary, inward, and a hole point at its centre). Its orientation is
/// confirmed with the oracle before use.
inline DrawnGrid draw_grid(int dimension, bool jitter = true, bool allow_hole = false) {
  DrawnGrid g;
  g.spec.dimension = dimension;
  // With a hole, at least 5 cells per axis and the block [2, n-2): a ring two cells wide,
  // so that some vertices touch neither boundary (most mutations need one).
  const bool hole = allow_hole && *rc::gen::arbitrary<bool>();
  const int least = hole ? 5 : 3;
  if (dimension == 2) {
    g.spec.cells = {*rc::gen::inRange(least, 9), *rc::gen::inRange(least, 9), 1};
  } else {
    const int n = hole ? 5 : *rc::gen::inRange(3, 5);
    g.spec.cells = {n, n, n};
  }
  g.spec.jitter_seed = jitter ? *rc::gen::inRange<std::uint64_t>(1, 1u << 30) : 0;
  const int n = g.spec.cells[0];
  if (hole && dimension == 2) g.spec.hole = fuzz::cell_block_2d(2, 2, n - 2, g.spec.cells[1] - 2);
  if (hole && dimension == 3) g.spec.hole = {{2, 2, 2}, {n - 2, n - 2, n - 2}};
  g.mesh = fuzz::kuhn_grid(g.spec);
  g.domain = dimension == 2 ? fuzz::square_domain(g.spec) : fuzz::cube_surface_domain(n);
  if (hole && dimension == 3) {
    fuzz::append_box_surface(g.domain, 2, n - 2, true);
    g.domain.holes = {n / 2.0, n / 2.0, n / 2.0};
  }
  RC_ASSERT(all_elements_positive(g.mesh));
  return g;
}

/// True when the finding names one of the mutated elements (as `element` or `other`) or
/// one of the mutated vertices.
inline bool points_at(const certificate::Finding& f, const fuzz::MutationSite& site) {
  const auto has = [](const std::vector<std::int64_t>& v, std::int64_t x) {
    return x >= 0 && std::find(v.begin(), v.end(), x) != v.end();
  };
  return has(site.elements, f.element) || has(site.elements, f.other) || has(site.vertices, f.vertex) ||
         has(site.vertices, f.other);
}

inline std::string describe(const certificate::Finding& f) {
  return std::string(certificate::defect_name(f.defect)) + " (element " + std::to_string(f.element) +
         ", other " + std::to_string(f.other) + ", vertex " + std::to_string(f.vertex) + "): " + f.message;
}

/// Asserts that `mesh` is rejected with one of `expected`; when `site` is given, that the
/// finding points at it.
inline void expect_rejected(const io::MeshData& mesh, const io::MeshData* domain,
                            const std::vector<certificate::Defect>& expected,
                            const fuzz::MutationSite* site) {
  const certificate::Report report = certificate::check_mesh(mesh, domain);
  if (report.valid) RC_FAIL("accepted; expected " + std::string(certificate::defect_name(expected[0])));
  if (std::find(expected.begin(), expected.end(), report.finding.defect) == expected.end())
    RC_FAIL("expected " + std::string(certificate::defect_name(expected[0])) + ", got " +
            describe(report.finding));
  if (site != nullptr && !points_at(report.finding, *site))
    RC_FAIL("right defect, wrong place: " + describe(report.finding));
}

inline void expect_rejected(const io::MeshData& mesh, const io::MeshData* domain,
                            certificate::Defect expected, const fuzz::MutationSite* site) {
  expect_rejected(mesh, domain, std::vector<certificate::Defect>{expected}, site);
}

inline void expect_accepted(const io::MeshData& mesh, const io::MeshData* domain) {
  const certificate::Report report = certificate::check_mesh(mesh, domain);
  if (!report.valid) RC_FAIL("rejected a valid mesh: " + describe(report.finding));
}

}  // namespace certimesh::testing
