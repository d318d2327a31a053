// Oracles and meshes shared by the imp_* tests of the local modifications and Algorithm 35.
// Everything here is independent of the code under test: exact areas in GMP rationals,
// boundary edges collected by scanning the neighbour array, validity by the certificate.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <set>
#include <utility>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/valid_meshes.h"
#include "certimesh/topology/local_facets.h"
#include "certimesh/topology/mesh_data_conversion.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::imp_testing {

using topology::ElementId;
using topology::TriangleMesh2;
using topology::VertexId;

inline TriangleMesh2 to_mesh(const io::MeshData& data) {
  auto converted = topology::from_mesh_data<TriangleMesh2>(data);
  if (!converted.ok()) throw std::runtime_error("fixture: " + converted.error->message);
  return std::move(*converted.mesh);
}

/// Twice the exact signed area of every live element, summed: the rational oracle.
inline mpq_class twice_signed_area(const TriangleMesh2& mesh) {
  mpq_class sum = 0;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    if (!mesh.is_live(ElementId{s})) continue;
    const auto v = mesh.vertices(ElementId{s});
    std::array<std::array<mpq_class, 2>, 3> p;
    for (std::size_t i = 0; i < 3; ++i) {
      const auto q = mesh.point(v[i]);
      p[i] = {mpq_class(q[0]), mpq_class(q[1])};
    }
    sum += (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
  }
  return sum;
}

using Segment = std::pair<std::array<double, 2>, std::array<double, 2>>;

/// The open facets (boundary edges) as coordinate pairs, each ordered, in a sorted set.
inline std::set<Segment> boundary_edges(const TriangleMesh2& mesh) {
  std::set<Segment> edges;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    const ElementId e{s};
    if (!mesh.is_live(e)) continue;
    for (int i = 0; i < 3; ++i)
      if (mesh.neighbour(e, i) == topology::no_element) {
        const auto f = mesh.facet(e, i);
        Segment seg{mesh.point(f[0]), mesh.point(f[1])};
        if (seg.second < seg.first) std::swap(seg.first, seg.second);
        edges.insert(seg);
      }
  }
  return edges;
}

/// The constrained interior facets held by live elements, as coordinate pairs: labelled ones
/// with their label, unlabelled ones between elements of different labels with label -1.
inline std::set<std::pair<Segment, topology::Label>> labelled_edges(const TriangleMesh2& mesh) {
  std::set<std::pair<Segment, topology::Label>> edges;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    const ElementId e{s};
    if (!mesh.is_live(e)) continue;
    for (int i = 0; i < 3; ++i) {
      const auto f = mesh.facet(e, i);
      const ElementId across = mesh.neighbour(e, i);
      if (across == topology::no_element) continue;
      topology::Label label = mesh.facet_label(f);
      if (label == 0 && mesh.label(across) != mesh.label(e)) label = -1;
      if (label != 0) {
        Segment seg{mesh.point(f[0]), mesh.point(f[1])};
        if (seg.second < seg.first) std::swap(seg.first, seg.second);
        edges.insert({seg, label});
      }
    }
  }
  return edges;
}

/// The certificate's verdict on the mesh against `domain` (nullptr: without a domain).
inline certificate::Report certify(const TriangleMesh2& mesh, const io::MeshData* domain) {
  return certificate::check_mesh(topology::to_mesh_data(mesh), domain);
}

/// Fewer property cases under the sanitizers (5-10x slower).
inline constexpr int sanitizer_divisor =
#if defined(__SANITIZE_ADDRESS__)
    5;
#else
    1;
#endif

}  // namespace certimesh::imp_testing
