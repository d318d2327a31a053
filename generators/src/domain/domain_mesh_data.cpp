// PlanarDomain <-> io::MeshData (the .poly exchange form). Structural refusals only; the
// geometry is validate_domain's.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/io/mesh_file.h"
#include "domain_text.h"

namespace certimesh::generators {

namespace {

[[noreturn]] void refuse_domain(DomainProblemKind kind, std::string message, std::vector<std::uint32_t> segments = {}) {
  throw InvalidDomain({DomainProblem{kind, std::move(segments), {}, std::move(message)}});
}

std::vector<Point2> points_of_xy(const std::vector<double>& xy) {
  std::vector<Point2> points(xy.size() / 2);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {xy[2 * i], xy[2 * i + 1]};
  return points;
}

// Region labels: the attributes themselves when every one is an integer in the range of
// io::Label (the usual material id); otherwise the region's 1-based index, and the real
// attribute travels beside it (RegionSeed::attribute, MeshData::triangle_attributes).
bool integral_label(double attribute) {
  return std::isfinite(attribute) && std::nearbyint(attribute) == attribute &&
         attribute >= static_cast<double>(std::numeric_limits<io::Label>::min()) &&
         attribute <= static_cast<double>(std::numeric_limits<io::Label>::max());
}

std::vector<RegionSeed> regions_of(const io::MeshData& data) {
  const std::vector<Point2> seeds = points_of_xy(data.region_points);
  std::vector<RegionSeed> regions(seeds.size());
  bool all_integral = true;
  for (std::size_t r = 0; r < seeds.size(); ++r) {
    const double attribute = r < data.region_attributes.size() ? data.region_attributes[r] : 0.0;
    if (!std::isfinite(attribute)) {
      std::string shown;
      io::append_double(shown, attribute);
      refuse_domain(DomainProblemKind::bad_region_attribute,
             "region point " + std::to_string(r) + " has attribute " + shown + ", which is not a finite number");
    }
    all_integral = all_integral && integral_label(attribute);
    const double area = r < data.region_max_measures.size() ? data.region_max_measures[r] : -1.0;
    regions[r] = {seeds[r], 0, attribute, std::isfinite(area) && area > 0 ? area : -1.0};
  }
  for (std::size_t r = 0; r < regions.size(); ++r) {
    regions[r].label = all_integral ? static_cast<io::Label>(regions[r].attribute) : static_cast<io::Label>(r + 1);
  }
  return regions;
}

}  // namespace

PlanarDomain planar_domain_from_mesh_data(const io::MeshData& data) {
  if (data.dimension != 2) {
    refuse_domain(DomainProblemKind::wrong_dimension,
           "a planar domain needs 2D points, the file has dimension " + std::to_string(data.dimension));
  }
  if (data.segment_count() == 0) {
    refuse_domain(DomainProblemKind::no_segments, "the file has no segments: nothing bounds a region");
  }
  PlanarDomain domain;
  domain.points = points_of_xy(data.coordinates);
  if (data.point_labels.size() == domain.points.size()) domain.point_labels = data.point_labels;
  const std::size_t n = domain.points.size();
  for (std::uint32_t s = 0; s < data.segment_count(); ++s) {
    const io::Index a = data.segments[2 * s];
    const io::Index b = data.segments[2 * s + 1];
    for (const io::Index v : {a, b}) {
      if (v >= n) {
        refuse_domain(DomainProblemKind::vertex_index_out_of_range,
               "segment " + std::to_string(s) + " names vertex " + std::to_string(v) +
                   " (0-based), but the file has only " + std::to_string(n) + " points",
               {s});
      }
    }
    const io::Label label = s < data.segment_labels.size() ? data.segment_labels[s] : 0;
    domain.segments.push_back({a, b, label});
  }
  domain.holes = points_of_xy(data.holes);
  domain.regions = regions_of(data);
  return domain;
}

io::MeshData to_mesh_data(const PlanarDomain& domain) {
  io::MeshData data;
  data.dimension = 2;
  for (const Point2& p : domain.points) {
    data.coordinates.push_back(p.x);
    data.coordinates.push_back(p.y);
  }
  data.point_labels = domain.point_labels;
  for (const DomainSegment& s : domain.segments) {
    data.segments.push_back(s.a);
    data.segments.push_back(s.b);
    data.segment_labels.push_back(s.label);
  }
  for (const Point2& h : domain.holes) {
    data.holes.push_back(h.x);
    data.holes.push_back(h.y);
  }
  for (const RegionSeed& r : domain.regions) {
    data.region_points.push_back(r.point.x);
    data.region_points.push_back(r.point.y);
    data.region_attributes.push_back(attribute_of(r));
    data.region_max_measures.push_back(r.max_area);
  }
  if (std::none_of(domain.regions.begin(), domain.regions.end(), [](const RegionSeed& r) { return r.max_area > 0; }))
    data.region_max_measures.clear();
  return data;
}

}  // namespace certimesh::generators
