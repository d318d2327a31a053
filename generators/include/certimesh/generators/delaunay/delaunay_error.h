// The error of the Delaunay triangulations (2D and 3D) for input they cannot take.
#pragma once

#include <stdexcept>

namespace certimesh::generators {

/// Thrown for input a triangulation cannot take: non-finite or duplicate points, too few
/// points or points in too few dimensions, or (2D) a constraint that crosses another
/// constraint or passes through a vertex. The message names the ids involved.
class DelaunayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace certimesh::generators
