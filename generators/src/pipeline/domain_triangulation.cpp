#include "domain_triangulation.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/io/mesh_file.h"

namespace certimesh::generators::detail {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

std::string point_text(const Point2& p) {
  std::string s;
  io::append_double(s, p.x);
  s += ' ';
  io::append_double(s, p.y);
  return s;
}

// Which sides of each subsegment are inside, and the front edges they give.
struct SideScan {
  std::vector<std::uint8_t> inside_sides;  // per subsegment: bit 0 = a->b side, bit 1 = b->a
  struct Oriented {
    std::uint32_t subsegment;
    std::uint8_t reversed;
    FrontEdge edge;
    io::Label region;
  };
  std::vector<Oriented> front;
};

SideScan scan_sides(const ConstrainedDelaunay2& cdt, const std::vector<int>& labels,
                    const DiscretizedBoundary& boundary) {
  std::unordered_map<std::uint64_t, std::uint32_t> subsegment_of;
  subsegment_of.reserve(boundary.subsegments.size() * 2);
  for (std::uint32_t s = 0; s < boundary.subsegments.size(); ++s) {
    subsegment_of.emplace(edge_key(boundary.subsegments[s].a, boundary.subsegments[s].b), s);
  }
  SideScan scan;
  scan.inside_sides.assign(boundary.subsegments.size(), 0);
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t) || labels[t] < 0) continue;
    const auto v = cdt.vertices(t);
    for (int i = 0; i < 3; ++i) {
      if (!cdt.is_constrained(t, i)) continue;
      const std::uint32_t p = v[static_cast<std::size_t>((i + 1) % 3)];
      const std::uint32_t q = v[static_cast<std::size_t>((i + 2) % 3)];
      const auto found = subsegment_of.find(edge_key(p, q));
      if (found == subsegment_of.end()) continue;  // cannot happen: every constraint is a subsegment
      const std::uint32_t s = found->second;
      const std::uint8_t reversed = boundary.subsegments[s].a == p ? 0 : 1;
      scan.inside_sides[s] |= static_cast<std::uint8_t>(1u << reversed);
      scan.front.push_back({s, reversed, FrontEdge{p, q}, labels[t]});
    }
  }
  std::sort(scan.front.begin(), scan.front.end(), [](const auto& x, const auto& y) {
    return x.subsegment != y.subsegment ? x.subsegment < y.subsegment : x.reversed < y.reversed;
  });
  return scan;
}

void refuse_open_boundary(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                          const std::vector<std::uint8_t>& inside_sides) {
  std::vector<DomainProblem> problems;
  std::uint32_t last_reported = UINT32_MAX;
  for (std::uint32_t s = 0; s < inside_sides.size() && problems.size() < 16; ++s) {
    const std::uint32_t original = boundary.origin[s];
    if (inside_sides[s] != 0 || original == last_reported) continue;
    last_reported = original;
    const DomainSegment& seg = domain.segments[original];
    DomainProblem p;
    p.kind = DomainProblemKind::open_boundary;
    p.segments = {original};
    p.vertices = {seg.a, seg.b};
    p.message = "segment " + std::to_string(original) + " (" + point_text(domain.points[seg.a]) + ")-(" +
                point_text(domain.points[seg.b]) +
                ") has the domain on neither side: an open loop, or a segment outside the domain or in a hole";
    problems.push_back(std::move(p));
  }
  if (!problems.empty()) throw InvalidDomain(std::move(problems));
}

bool has_bounded_face(const ConstrainedDelaunay2& cdt) {
  const std::vector<int> without_holes = cdt.classify({}, {});
  return std::any_of(without_holes.begin(), without_holes.end(), [](int label) { return label >= 0; });
}

}  // namespace

DomainTriangulation triangulate_domain(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                       const ProgressCallback& progress) {
  ConstrainedDelaunay2 cdt(boundary.points, progress);
  for (const DomainSegment& s : boundary.subsegments) cdt.insert_constraint(s.a, s.b);
  std::vector<int> labels = cdt.classify(domain.holes, domain.regions);
  const SideScan scan = scan_sides(cdt, labels, boundary);
  if (scan.front.empty()) {
    // No bounded face at all: the segments enclose nothing (open loops). Bounded faces that
    // the hole points all ate: an empty domain.
    if (!has_bounded_face(cdt)) refuse_open_boundary(domain, boundary, scan.inside_sides);
    DomainProblem p;
    p.kind = DomainProblemKind::empty_domain;
    p.message = "the domain is empty: every face of the segments is unbounded or contains a hole point";
    throw InvalidDomain({std::move(p)});
  }
  refuse_open_boundary(domain, boundary, scan.inside_sides);
  DomainTriangulation out{std::move(cdt), std::move(labels), {}, {}};
  out.front.reserve(scan.front.size());
  out.front_region.reserve(scan.front.size());
  for (const auto& f : scan.front) {
    out.front.push_back(f.edge);
    out.front_region.push_back(f.region);
  }
  return out;
}

}  // namespace certimesh::generators::detail
