// How the readers normalise label lists, shared by every text format.
#pragma once

#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::io::detail {

/// The label vector as the readers return it: empty when every label is 0 (MeshData's "empty
/// = all 0"), so that a file that lists zero labels and one that lists none read the same.
inline void drop_all_zero(std::vector<Label>& labels) {
  for (const Label label : labels) {
    if (label != 0) return;
  }
  labels.clear();
}

}  // namespace certimesh::io::detail
