// The error the mesh model throws when a caller asks for something the model cannot
// represent (a facet shared by a third element, a repeated or dead vertex, a dead id).
// The message names the problem and the element or vertex concerned.
#pragma once

#include <stdexcept>
#include <string>

namespace certimesh::topology {

class TopologyError : public std::runtime_error {
 public:
  explicit TopologyError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace certimesh::topology
