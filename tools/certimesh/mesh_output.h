// What the 2D and 3D `certimesh mesh` paths share: progress at a terminal, writing the
// outputs, and the 3D path's entry (mesh_command_3.cpp).
#pragma once

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/progress.h"
#include "certimesh/io/mesh_data.h"
#include "cli.h"

namespace certimesh::cli {

/// Progress on standard error, only for a person at a terminal, at most every 0.2 s.
generators::ProgressCallback terminal_progress(bool quiet);

/// Writes the mesh and, when asked, its certificate, picture and domain; each file atomically.
void write_outputs(const MeshOptions& options, const io::MeshData& mesh, const io::MeshData& domain,
                   const certificate::Report& report);

/// Points only: no segment, facet or element (a .node file).
bool is_point_set(const io::MeshData& m);

/// `certimesh mesh` of a 3D input: a point set (its convex hull). Returns the exit status.
int mesh_solid_3(const MeshOptions& options, const io::MeshData& input);

}  // namespace certimesh::cli
