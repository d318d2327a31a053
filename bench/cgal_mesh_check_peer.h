// The peer of bench_certificate: the reference mesh check of the design notes'
// fuzz-cert-style.md §3.2 prototype -- CGAL::orientation (Epick) on every element, then
// std::sort facet pairing -- built in its own translation unit (CGAL needs -frounding-math).
// It checks conditions (a) and (b) only (positive elements; every facet on one element, or
// on two with opposite orientations), which is what the prototype's numbers measured.
#pragma once

#include <cstddef>

#include "certimesh/io/mesh_data.h"

namespace certimesh_bench {

struct PeerVerdict {
  bool all_positive = false;          // every element positively oriented (exact, CGAL)
  bool paired = false;                // no facet on 3+ elements, no same-orientation pair
  std::size_t boundary_facets = 0;
  std::size_t interior_facets = 0;
};

PeerVerdict cgal_reference_check(const certimesh::io::MeshData& mesh);

}  // namespace certimesh_bench
