// The certificate: an independent exact check that a mesh is a valid simplicial mesh of its
// domain. It shares nothing with the generators: it reads MeshData (io/) and decides every
// sign with the exact predicates (predicates/). The argument that its O(N log N) local and
// global conditions imply an exact single cover of the domain is proofs/mesh_certificate.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "certimesh/certificate/defect.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::certificate {

/// The first defect found, located: `element`/`facet`/`vertex` are 0-based indices into the
/// checked MeshData (or into the domain's arrays for domain defects), -1 when not applicable.
struct Finding {
  Defect defect = Defect::none;
  std::int64_t element = -1;  // element (triangle in 2D, tetrahedron in 3D)
  std::int64_t other = -1;    // a second element, facet or vertex involved, when there is one
  std::int64_t vertex = -1;
  std::string message;        // one line for a person: what is wrong and where
};

/// How far from the domain boundary a mesh boundary vertex may lie. The default is design
/// decision 2's exact rule: the domain segment / triangle must meet the vertex's rounding box
/// (half an ulp per coordinate). Meshes written by other tools (Triangle's Steiner points a few
/// 1e-17 off their segment, Gmsh's 14 digits) need more: with `absolute` > 0 a vertex is on a
/// segment / triangle when each coordinate is within `absolute` of a point of it (max-norm);
/// with `ulps` > 0.5, within that many ulps of its own coordinate. A mesh vertex with the
/// coordinates of a domain vertex is on a domain simplex only exactly, whatever the tolerance.
struct BoundaryTolerance {
  double absolute = 0.0;
  double ulps = 0.0;
  bool active() const { return absolute > 0 || ulps > 0.5; }
};

struct Statistics {
  int dimension = 0;                 // 2 (triangles) or 3 (tetrahedra)
  std::size_t vertices = 0;
  std::size_t elements = 0;
  std::size_t interior_facets = 0;
  std::size_t boundary_facets = 0;
  std::size_t boundary_components = 0;
  double worst_quality = 0.0;        // min over elements, 12√3|S|/P² or 6⁴√2|V|/P³ (approximate)
  std::int64_t worst_element = -1;
  // With a domain: boundary vertices on domain segments/faces.
  std::size_t vertices_exactly_on_domain_boundary = 0;
  std::size_t vertices_in_rounding_box_only = 0;  // on it only within half an ulp per coordinate
  double max_boundary_deviation = 0.0;            // distance to the segment/face, for those vertices
  // With a 2D domain: the meshed area, the area of the domain as its segments bound it (the
  // side the mesh takes), their difference computed exactly (then rounded) and the exact bound
  // on it that the box-only vertices allow (proofs/mesh_certificate.md section 4).
  double measure = 0.0;
  double domain_measure = 0.0;
  double measure_difference = 0.0;
  double measure_difference_bound = 0.0;
  BoundaryTolerance boundary_tolerance;  // the one the check used
};

struct CheckOptions {
  BoundaryTolerance boundary_tolerance;
};

struct Report {
  bool valid = false;
  Finding finding;        // defect == none when valid
  Statistics statistics;  // complete when valid; partial otherwise
  std::string mesh_sha256;  // of the canonical binary form of the mesh (see certificate_json)
};

/// Checks `mesh` (2D triangles or 3D tetrahedra; segments / boundary triangles in the file are
/// ignored) against `domain` when non-null (2D: segments and holes of a .poly; 3D: a closed
/// surface mesh, triangles, with optional holes). Never throws on bad geometry: every defect
/// is a Finding.
Report check_mesh(const io::MeshData& mesh, const io::MeshData* domain = nullptr, const CheckOptions& options = {});

/// The JSON certificate: counts, worst quality, the mesh hash, the verdict and the certimesh
/// version. Deterministic: same report, same bytes.
std::string certificate_json(const Report& report, const std::string& certimesh_version);

}  // namespace certimesh::certificate
