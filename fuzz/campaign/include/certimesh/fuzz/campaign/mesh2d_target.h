// The `mesh2d` target: the 2D pipeline (generators::mesh_domain_2, both algorithms) on
// generated valid planar domains, against the certificate and the scaling relation.
//
// A case draws a valid domain from fuzz/generators/planar_domains.h (star polygons, with a
// crack, combs, nested squares with holes and islands, near-collinear chains, cocircular
// lattice points with a hole, fans of cuts at tiny angles; 3 to 16 boundary vertices; scaled
// by 2^-35..2^45, 1 case in 8 by 2^-900..2^900), an algorithm (advancing front or Delaunay
// refinement) and a shift j in [-8, 8] \ {0}. Checked: the pipeline returns (no exception:
// the domain is valid); the certificate (certimesh::certificate::check_mesh, which shares
// nothing with the generators) accepts the mesh against the domain; and the domain scaled by
// 2^j gives the same triangles, labels and segments with every coordinate scaled by 2^j, bit
// for bit. Payload: "ALGORITHM J n x0 y0 .. m a0 b0 l0 .. h x0 y0 .." (%a hex floats).
#pragma once

#include <memory>
#include <string>

#include "certimesh/fuzz/campaign/target.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/mesh_domain_2.h"

namespace certimesh::fuzz::campaign {

/// The pipeline the target checks, so that a test can substitute a mutant.
struct Mesh2dKernel {
  io::MeshData (*mesh)(const generators::PlanarDomain& domain, generators::MeshAlgorithm2 algorithm);
};

/// generators::mesh_domain_2 with default options but the algorithm.
Mesh2dKernel certimesh_mesh2d_kernel();

std::unique_ptr<Target> make_mesh2d_target(const Mesh2dKernel& kernel, std::string name, std::string description);

/// The shipped target, named "mesh2d".
std::unique_ptr<Target> make_mesh2d_target();

}  // namespace certimesh::fuzz::campaign
