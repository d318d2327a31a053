// The exchange form of a mesh or a domain as the file formats hold it: plain arrays, no
// adjacency, no behaviour. Readers produce it, writers consume it; topology/ builds its mesh
// model from it and certificate/ checks it. Indices are 0-based here (the 1-based formats
// convert on reading and writing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace certimesh::io {

using Index = std::uint32_t;  // a vertex index; files naming an index >= 2^32 are refused
using Label = std::int32_t;   // material, boundary or point marker; 0 when the file has none

// A TetGen facet list (3D .poly and .smesh): each facet is a planar set of polygons (1 corner:
// an isolated point in the facet, 2: a segment, 3 or more: a closed polygon) with optional
// facet hole points and a boundary marker. Flat arrays: polygon p's corners are
// corners[polygon_end[p-1] .. polygon_end[p]) (from 0 for p = 0), facet f's polygons are
// polygons facet_end[f-1] .. facet_end[f]), its holes holes[3*hole_end[f-1] .. 3*hole_end[f]).
// Reading keeps the file's facets as they are: making triangles of them is geometry
// (certificate/), not file format.
struct FacetList {
  std::vector<Index> corners;
  std::vector<std::uint64_t> polygon_end;
  std::vector<std::uint64_t> facet_end;
  std::vector<double> holes;              // facet hole points, 3 coordinates each
  std::vector<std::uint64_t> hole_end;    // one per facet
  std::vector<Label> labels;              // one per facet, or empty (all 0)

  std::size_t facet_count() const { return facet_end.size(); }
  std::size_t polygon_count() const { return polygon_end.size(); }
  bool empty() const { return facet_end.empty(); }
  std::uint64_t polygon_begin(std::size_t f) const { return f == 0 ? 0 : facet_end[f - 1]; }
  std::uint64_t corner_begin(std::size_t p) const { return p == 0 ? 0 : polygon_end[p - 1]; }
  std::uint64_t hole_begin(std::size_t f) const { return f == 0 ? 0 : hole_end[f - 1]; }

  friend bool operator==(const FacetList&, const FacetList&) = default;
};

struct MeshData {
  int dimension = 2;  // coordinates per point: 2 or 3

  // Points: `dimension` coordinates each, interleaved (x0 y0 [z0] x1 y1 ...).
  std::vector<double> coordinates;
  std::vector<Label> point_labels;  // empty, or one per point

  // Cells, `k` vertex indices each, with one label per cell (empty = all 0).
  //   segments:   boundary/constraint edges (2D .poly segments, Gmsh/Medit edges)
  //   triangles:  2D elements, or boundary/surface faces in 3D
  //   tetrahedra: 3D elements
  std::vector<Index> segments;
  std::vector<Label> segment_labels;
  std::vector<Index> triangles;
  std::vector<Label> triangle_labels;
  std::vector<Index> tetrahedra;
  std::vector<Label> tetrahedron_labels;
  // A real element attribute of the 2D triangles (Triangle's regional attribute when it is not
  // an integer): empty, or one per triangle. The .ele format writes it instead of the labels;
  // the other formats keep only the labels, which are then labels_of_attributes(these).
  std::vector<double> triangle_attributes;

  // 3D domain facets as TetGen's .poly/.smesh give them (empty otherwise).
  FacetList facets;

  // Domain description (.poly/.smesh only): hole points (`dimension` coordinates each) and
  // region points with their attribute (Triangle/TetGen regional attributes) and their maximum
  // area (2D) or volume (3D): empty when no region gives one, else one per region, negative for
  // "no constraint" (Triangle's and TetGen's convention).
  std::vector<double> holes;
  std::vector<double> region_points;
  std::vector<double> region_attributes;
  std::vector<double> region_max_measures;

  std::size_t point_count() const { return coordinates.size() / static_cast<std::size_t>(dimension); }
  std::size_t segment_count() const { return segments.size() / 2; }
  std::size_t triangle_count() const { return triangles.size() / 3; }
  std::size_t tetrahedron_count() const { return tetrahedra.size() / 4; }
  std::size_t hole_count() const { return holes.size() / static_cast<std::size_t>(dimension); }

  friend bool operator==(const MeshData&, const MeshData&) = default;
};

/// Integer labels for real element attributes, for the formats that hold only integers: each
/// distinct value's 1-based rank in order of first appearance (deterministic; O(n log d)).
inline std::vector<Label> labels_of_attributes(const std::vector<double>& attributes) {
  std::map<double, Label> rank;
  std::vector<Label> labels;
  labels.reserve(attributes.size());
  for (const double a : attributes) labels.push_back(rank.emplace(a, static_cast<Label>(rank.size() + 1)).first->second);
  return labels;
}

}  // namespace certimesh::io
