// Shared by the Triangle/TetGen and Medit tests: generators of arbitrary (not necessarily
// geometrically valid) MeshData, a bit-exact comparison, and a scratch folder.
#pragma once

#include <rapidcheck.h>

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "certimesh/fuzz/rc_generators.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::io::testing {

/// Coordinates from every binade the format must carry (the shared adversarial classes) plus
/// the values a decimal writer gets wrong first: signed zeros, extremes, the smallest subnormal.
inline rc::Gen<double> coordinate() {
  using fuzz::DoubleClass;
  using fuzz::rcgen::double_of_class;
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kDenorm = std::numeric_limits<double>::denorm_min();
  constexpr double kMinNormal = std::numeric_limits<double>::min();
  return rc::gen::oneOf(
      double_of_class(DoubleClass::normal), double_of_class(DoubleClass::subnormal),
      double_of_class(DoubleClass::huge), double_of_class(DoubleClass::tiny),
      double_of_class(DoubleClass::overflow2), double_of_class(DoubleClass::overflow3),
      rc::gen::element(0.0, -0.0, 1e300, -1e300, 1e-300, -1e-300, kDenorm, -kDenorm, kMax, -kMax,
                       kMinNormal, 0.1, 1.0 / 3.0));
}

inline rc::Gen<Label> label() {
  return rc::gen::oneOf(rc::gen::element<Label>(0, 1, -1, std::numeric_limits<Label>::min(),
                                                std::numeric_limits<Label>::max()),
                        rc::gen::arbitrary<Label>());
}

/// Empty, or one label per item with at least one non-zero (the readers' normal form:
/// an all-zero label list reads back as empty).
inline std::vector<Label> labels_for(std::size_t count) {
  if (count == 0 || *rc::gen::inRange(0, 3) == 0) return {};
  auto labels = *rc::gen::container<std::vector<Label>>(count, label());
  if (std::all_of(labels.begin(), labels.end(), [](Label l) { return l == 0; })) labels[0] = 7;
  return labels;
}

inline std::vector<Index> cells(std::size_t count, std::size_t corners, std::size_t points) {
  return *rc::gen::container<std::vector<Index>>(
      count * corners, rc::gen::inRange<Index>(0, static_cast<Index>(points)));
}

inline std::vector<double> coordinates(std::size_t count) {
  return *rc::gen::container<std::vector<double>>(count, coordinate());
}

/// A TetGen facet list over `points` points: `count` facets of 1 to 3 polygons, each of 1 to 6
/// distinct corners (consecutive indices from a random start), 0 to 2 facet holes, labels.
inline io::FacetList facets_of(std::size_t count, std::size_t points) {
  io::FacetList f;
  for (std::size_t i = 0; i < count; ++i) {
    const auto polygons = *rc::gen::inRange<std::size_t>(1, 4);
    for (std::size_t p = 0; p < polygons; ++p) {
      const auto k = *rc::gen::inRange<std::size_t>(1, std::min<std::size_t>(points, 6) + 1);
      const auto start = *rc::gen::inRange<std::size_t>(0, points);
      for (std::size_t c = 0; c < k; ++c) f.corners.push_back(static_cast<Index>((start + c) % points));
      f.polygon_end.push_back(f.corners.size());
    }
    f.facet_end.push_back(f.polygon_end.size());
    const std::vector<double> holes = coordinates(3 * *rc::gen::inRange<std::size_t>(0, 3));
    f.holes.insert(f.holes.end(), holes.begin(), holes.end());
    f.hole_end.push_back(f.holes.size() / 3);
  }
  f.labels = labels_for(count);
  return f;
}

/// What a mesh file holds: points, and cells over them with random valid indices.
/// 2D: triangles and segments; 3D: tetrahedra, boundary triangles and segments.
inline rc::Gen<MeshData> mesh_of(int dimension) {
  return rc::gen::exec([dimension] {
    MeshData m;
    m.dimension = dimension;
    const auto dim = static_cast<std::size_t>(dimension);
    const auto n = *rc::gen::inRange<std::size_t>(1, 25);
    m.coordinates = coordinates(n * dim);
    m.point_labels = labels_for(n);
    const auto nt = *rc::gen::inRange<std::size_t>(0, 25);
    m.triangles = cells(nt, 3, n);
    m.triangle_labels = labels_for(nt);
    const auto ns = *rc::gen::inRange<std::size_t>(0, 10);
    m.segments = cells(ns, 2, n);
    m.segment_labels = labels_for(ns);
    if (dimension == 3) {
      const auto nk = *rc::gen::inRange<std::size_t>(0, 25);
      m.tetrahedra = cells(nk, 4, n);
      m.tetrahedron_labels = labels_for(nk);
    }
    return m;
  });
}

/// What a .poly holds: points, segments (2D) or boundary triangles (3D), holes, regions.
inline rc::Gen<MeshData> domain_of(int dimension) {
  return rc::gen::exec([dimension] {
    MeshData m;
    m.dimension = dimension;
    const auto dim = static_cast<std::size_t>(dimension);
    const auto n = *rc::gen::inRange<std::size_t>(1, 25);
    m.coordinates = coordinates(n * dim);
    m.point_labels = labels_for(n);
    const auto nc = *rc::gen::inRange<std::size_t>(0, 25);
    if (dimension == 2) {
      m.segments = cells(nc, 2, n);
      m.segment_labels = labels_for(nc);
    } else {
      m.facets = facets_of(nc, n);
    }
    m.holes = coordinates(*rc::gen::inRange<std::size_t>(0, 4) * dim);
    const auto nr = *rc::gen::inRange<std::size_t>(0, 4);
    m.region_points = coordinates(nr * dim);
    m.region_attributes = coordinates(nr);
    if (nr > 0 && *rc::gen::arbitrary<bool>()) {  // some constraints ("none" is -1, and not all none)
      for (std::size_t r = 0; r < nr; ++r) m.region_max_measures.push_back(r % 2 == 0 ? 0.5 + double(r) : -1.0);
    }
    return m;
  });
}

/// MeshData's == compares doubles by value (0.0 == -0.0); the formats must keep the bits.
inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

inline bool identical(const MeshData& a, const MeshData& b) {
  return a == b && same_bits(a.coordinates, b.coordinates) && same_bits(a.holes, b.holes) &&
         same_bits(a.region_points, b.region_points) &&
         same_bits(a.region_attributes, b.region_attributes) && same_bits(a.facets.holes, b.facets.holes) &&
         same_bits(a.region_max_measures, b.region_max_measures);
}

/// A fresh, empty folder for one test program's files under the system's temporary folder,
/// removed with everything in it when the program ends.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("certimesh-io-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace certimesh::io::testing
