// The `readers` target: every reader of io/ (Medit .mesh, Gmsh .msh, VTK .vtu, Triangle/TetGen
// .node/.ele/.poly/.smesh, OFF, STL ASCII and binary) on mutated valid files.
//
// A case draws a small random MeshData fitting one format, writes it with certimesh's writer
// (OFF and STL, which certimesh only reads, with a few lines of the target's own), then
// applies 0-3 mutations to the main file: a byte flipped, inserted or deleted, a line deleted,
// duplicated or swapped with the next, a number replaced by a hostile one (0, -1, 2^32, a
// 20-digit count, 1e999, nan, inf, -0, a fraction, the number + 1), the file cut short. Inputs
// stay under a few kilobytes. Checked:
//   - the reader returns, or throws io::FormatError; any other exception is a finding;
//   - a refusal names the file it read (or its companion) and a line that exists in it, in a
//     message of at most 512 bytes;
//   - accepted data meets io/mesh_data.h's invariants (oracles/mesh_data_invariants.h);
//   - round trip: writing the accepted data in its own format (OFF/STL: as Medit, or .smesh
//     for polygon facets) and reading that again gives the same data, coordinates bit for bit;
//   - an unmutated file of certimesh's writer, read and written again, gives the same bytes
//     (so it read back to the data it was written from).
// Payload: "pristine|mutated EXT HEX [EXT HEX]...": whether the file is a writer's unmutated
// output, the main file's extension and bytes in hex, then its companion files' ("-" for an
// empty file).
#pragma once

#include <memory>
#include <string>

#include "certimesh/fuzz/campaign/target.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::fuzz::campaign {

/// The reader the target calls for one format, so that a test can substitute a mutant. It
/// gets the extension ("mesh", "msh", "vtu", "node", "ele", "poly", "smesh", "off", "stl"),
/// the main file and a lookup of companion files by extension.
struct ReaderKernel {
  io::MeshData (*read)(const std::string& extension, const std::string& contents,
                       const std::vector<std::pair<std::string, std::string>>& companions);
};

/// certimesh's own readers.
ReaderKernel certimesh_reader_kernel();

std::unique_ptr<Target> make_readers_target(const ReaderKernel& kernel, std::string name, std::string description);

/// The shipped target, named "readers".
std::unique_ptr<Target> make_readers_target();

}  // namespace certimesh::fuzz::campaign
