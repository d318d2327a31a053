// The 2D meshing pipeline, from a planar domain to a mesh that `certimesh check --domain`
// certifies:
//   1. validate the boundary exactly (domain_validation.h);
//   2. discretize long segments to the size policy (Steiner points on a segment are the
//      rounding of exact points of it -- design decision 2);
//   3. constrained Delaunay triangulation of the boundary, classified into inside/outside and
//      regions: this decides open loops and empty domains, and gives each region its label;
//   4. the elements: advancing front (with Delaunay completion of whatever it leaves) or
//      Delaunay refinement;
//   5. quality improvement by local modifications, boundary trace kept;
//   6. the regions' maximum areas enforced by longest-edge bisection (with 7 instead, aimed at by
//      the size only);
//   7. with a minimum angle: the constrained Delaunay triangulation of the mesh's vertices,
//      refined until every triangle meets the angle or is exempt (quality_refinement_2.h).
//      It runs last, so nothing after it can lower an angle; after --algorithm delaunay it
//      replaces stages 4's size-only refinement and 5 (the quality refinement meets the size).
// Triangle's .poly semantics throughout (planar_domain.h): isolated vertices inside the domain
// are mesh vertices, segments inside it are mesh edges, segments with the domain on neither
// side are eaten, a hole point outside every face is refused.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "certimesh/generators/delaunay/quality_refinement_2.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::generators {

enum class MeshAlgorithm2 { advancing_front, delaunay };

struct MeshDomainOptions2 {
  MeshAlgorithm2 algorithm = MeshAlgorithm2::advancing_front;
  SizePolicy size;
  bool improve = true;           // run the local-modification improvement
  double target_quality = 0.0;   // 0 = 0.93 after the advancing front; after Delaunay refinement
                                 // 0.9 for the smoothing, 0.85 for Algorithm 35
  /// The smallest angle wanted, degrees, in (0, 60); 0 = no guarantee (stage 6 off).
  double min_angle = 0.0;
  /// Stage 6's Steiner point cap (quality_refinement_2.h).
  std::uint64_t max_steiner = 4'000'000;
};

struct StageTiming {
  std::string stage;
  double seconds = 0.0;
};

struct MeshDomainStats2 {
  std::uint64_t boundary_vertices = 0;
  std::uint64_t vertices = 0;
  std::uint64_t triangles = 0;
  std::uint64_t completed_by_delaunay = 0;  // triangles the Delaunay completion added
  std::uint64_t improved_region = 0;        // triangles the improvement stage worked on
  std::uint64_t improvement_iterations = 0; // Algorithm 35 iterations
  std::uint64_t improvement_operations = 0; // local modifications committed
  std::uint64_t isolated_vertices = 0;      // input vertices on no segment, made mesh vertices
  std::uint64_t dropped_vertices = 0;       // input vertices outside the domain (not in the mesh)
  std::uint64_t eaten_segments = 0;         // input segments with the domain on neither side
  std::uint64_t area_bisections = 0;        // splits that enforced the regions' maximum areas
  double worst_quality = 0.0;
  double mean_quality = 0.0;
  bool quality_refined = false;             // stage 6 ran; then `quality` says how it ended
  QualityRefinementStats quality;
  std::vector<StageTiming> timings;
};

struct MeshDomainResult2 {
  // Dimension 2: triangles with region labels (and real attributes when some region's is not an
  // integer), boundary and cut segments with their markers, point markers. Vertices: the
  // domain's kept vertices first, in input order, then the Steiner and interior vertices.
  io::MeshData mesh;
  MeshDomainStats2 stats;
};

/// Meshes `domain`. Throws InvalidDomain (domain_problem.h) for an invalid domain; never
/// returns an invalid mesh.
MeshDomainResult2 mesh_domain_2(const PlanarDomain& domain, const MeshDomainOptions2& options,
                                const ProgressCallback& progress = {});

}  // namespace certimesh::generators
