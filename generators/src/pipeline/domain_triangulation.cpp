#include "domain_triangulation.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/predicates/orient2d.h"

namespace certimesh::generators::detail {

namespace {

std::uint64_t triangulation_edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

std::string point2_text(const Point2& p) {
  std::string s;
  io::append_double(s, p.x);
  s += ' ';
  io::append_double(s, p.y);
  return s;
}

// Which sides of each domain segment are inside, with the region label on that side.
struct SideScan {
  std::vector<std::uint8_t> inside_sides;  // per segment: bit 0 = the a->b side, bit 1 = b->a
  std::vector<std::array<io::Label, 2>> region;
};

SideScan scan_sides(const ConstrainedDelaunay2& cdt, const std::vector<int>& labels, const PlanarDomain& domain) {
  std::unordered_map<std::uint64_t, std::uint32_t> segment_of;
  segment_of.reserve(domain.segments.size() * 2);
  for (std::uint32_t s = 0; s < domain.segments.size(); ++s) {
    segment_of.emplace(triangulation_edge_key(domain.segments[s].a, domain.segments[s].b), s);
  }
  SideScan scan;
  scan.inside_sides.assign(domain.segments.size(), 0);
  scan.region.assign(domain.segments.size(), {0, 0});
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t) || labels[t] < 0) continue;
    const auto v = cdt.vertices(t);
    for (int i = 0; i < 3; ++i) {
      if (!cdt.is_constrained(t, i)) continue;
      const std::uint32_t p = v[static_cast<std::size_t>((i + 1) % 3)];
      const std::uint32_t q = v[static_cast<std::size_t>((i + 2) % 3)];
      const auto found = segment_of.find(triangulation_edge_key(p, q));
      if (found == segment_of.end()) continue;  // cannot happen: every constraint is a segment
      const std::uint32_t s = found->second;
      const std::size_t side = domain.segments[s].a == p ? 0 : 1;  // t is left of p -> q
      scan.inside_sides[s] |= static_cast<std::uint8_t>(1u << side);
      scan.region[s][side] = labels[t];
    }
  }
  return scan;
}

void refuse_open_boundary(const PlanarDomain& domain, const std::vector<std::uint8_t>& inside_sides) {
  std::vector<DomainProblem> problems;
  for (std::uint32_t original = 0; original < inside_sides.size() && problems.size() < 16; ++original) {
    if (inside_sides[original] != 0) continue;
    const DomainSegment& seg = domain.segments[original];
    DomainProblem p;
    p.kind = DomainProblemKind::open_boundary;
    p.segments = {original};
    p.vertices = {seg.a, seg.b};
    p.message = "segment " + std::to_string(original) + " (" + point2_text(domain.points[seg.a]) + ")-(" +
                point2_text(domain.points[seg.b]) +
                ") has the domain on neither side: an open loop, or a segment outside the domain or in a hole";
    problems.push_back(std::move(p));
  }
  if (!problems.empty()) throw InvalidDomain(std::move(problems));
}

bool has_bounded_face(const ConstrainedDelaunay2& cdt) {
  const std::vector<int> without_holes = cdt.classify({}, {});
  return std::any_of(without_holes.begin(), without_holes.end(), [](int label) { return label >= 0; });
}

// Whether p, in the closed triangle t, lies on a segment: then on a constrained edge of t (every
// segment is one), or at a vertex of t that is on a segment. Empty if not, else what it is on.
std::string on_a_segment(const ConstrainedDelaunay2& cdt, std::uint32_t t, const Point2& p,
                         const std::vector<std::uint8_t>& on_segment) {
  const auto v = cdt.vertices(t);
  for (int i = 0; i < 3; ++i) {
    const Point2& a = cdt.point(v[static_cast<std::size_t>((i + 1) % 3)]);
    const Point2& b = cdt.point(v[static_cast<std::size_t>((i + 2) % 3)]);
    if (cdt.is_constrained(t, i) && predicates::orient2d(a, b, p) == predicates::Sign::zero)
      return "the segment (" + point2_text(a) + ")-(" + point2_text(b) + ")";
  }
  for (const std::uint32_t w : v)
    if (cdt.point(w) == p && w < on_segment.size() && on_segment[w]) return "vertex " + std::to_string(w) + " of a segment";
  return {};
}

// A hole point in no bounded face (outside the hull, or in a triangle the hull reaches
// without crossing a segment) is a user error (design decision 8); so is one on a segment.
void refuse_holes_outside(const ConstrainedDelaunay2& cdt, const PlanarDomain& domain) {
  const std::vector<int> unbounded = cdt.classify({}, {});
  std::vector<std::uint8_t> on_segment(domain.points.size(), 0);
  for (const DomainSegment& s : domain.segments) on_segment[s.a] = on_segment[s.b] = 1;
  std::vector<DomainProblem> problems;
  for (std::uint32_t h = 0; h < domain.holes.size() && problems.size() < 16; ++h) {
    const auto t = cdt.locate(domain.holes[h]);
    if (t != ConstrainedDelaunay2::none && !cdt.is_ghost(t) && unbounded[t] >= 0) {
      if (const std::string on = on_a_segment(cdt, t, domain.holes[h], on_segment); !on.empty()) {
        DomainProblem p;
        p.kind = DomainProblemKind::hole_outside_domain;
        p.message = "hole point " + std::to_string(h) + " (" + point2_text(domain.holes[h]) + ") lies on " + on +
                    ": it does not say which face it empties";
        problems.push_back(std::move(p));
      }
      continue;
    }
    DomainProblem p;
    p.kind = DomainProblemKind::hole_outside_domain;
    p.message = "hole point " + std::to_string(h) + " (" + point2_text(domain.holes[h]) +
                ") is outside every face the segments bound: it makes no hole";
    problems.push_back(std::move(p));
  }
  if (!problems.empty()) throw InvalidDomain(std::move(problems));
}

// Which input vertices are in a triangle of the domain (label >= 0).
std::vector<std::uint8_t> vertices_in_domain(const ConstrainedDelaunay2& cdt, const std::vector<int>& labels,
                                             std::size_t vertex_count) {
  std::vector<std::uint8_t> inside(vertex_count, 0);
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t) || labels[t] < 0) continue;
    for (const std::uint32_t v : cdt.vertices(t)) {
      if (v < vertex_count) inside[v] = 1;
    }
  }
  return inside;
}

// The meshed part of the domain: kept segments (inside on a side), their vertices and the
// isolated vertices inside, in input order.
void keep_meshed_part(const PlanarDomain& domain, const SideScan& scan, const std::vector<std::uint8_t>& in_domain,
                      DomainClassification& out) {
  std::vector<std::uint8_t> on_segment(domain.points.size(), 0), keep(domain.points.size(), 0);
  for (std::uint32_t s = 0; s < domain.segments.size(); ++s) {
    on_segment[domain.segments[s].a] = on_segment[domain.segments[s].b] = 1;
    if (scan.inside_sides[s] == 0) continue;
    keep[domain.segments[s].a] = keep[domain.segments[s].b] = 1;
  }
  constexpr DomainVertex unused = UINT32_MAX;
  std::vector<DomainVertex> new_id(domain.points.size(), unused);
  const bool labelled = domain.point_labels.size() == domain.points.size();
  for (DomainVertex v = 0; v < domain.points.size(); ++v) {
    const bool isolated = !on_segment[v];
    if (!keep[v] && !(isolated && in_domain[v])) {
      ++out.dropped_vertices;
      continue;
    }
    new_id[v] = static_cast<DomainVertex>(out.kept.points.size());
    if (isolated) out.isolated.push_back(new_id[v]);
    out.kept.points.push_back(domain.points[v]);
    if (labelled) out.kept.point_labels.push_back(domain.point_labels[v]);
    out.vertex_origin.push_back(v);
  }
  for (std::uint32_t s = 0; s < domain.segments.size(); ++s) {
    if (scan.inside_sides[s] == 0) {
      ++out.eaten_segments;
      continue;
    }
    const DomainSegment& seg = domain.segments[s];
    out.kept.segments.push_back({new_id[seg.a], new_id[seg.b], seg.label});
    out.inside_sides.push_back(scan.inside_sides[s]);
    out.region.push_back(scan.region[s]);
  }
  out.kept.holes = domain.holes;
  out.kept.regions = domain.regions;
}

}  // namespace

DomainClassification classify_domain(const PlanarDomain& domain, const ProgressCallback& progress) {
  ConstrainedDelaunay2 cdt(domain.points, progress);
  for (const DomainSegment& s : domain.segments) cdt.insert_constraint(s.a, s.b);
  if (!has_bounded_face(cdt)) refuse_open_boundary(domain, std::vector<std::uint8_t>(domain.segments.size(), 0));
  refuse_holes_outside(cdt, domain);
  const std::vector<int> labels = cdt.classify(domain.holes, domain.regions);
  const SideScan scan = scan_sides(cdt, labels, domain);
  const bool any_inside = std::any_of(scan.inside_sides.begin(), scan.inside_sides.end(),
                                      [](std::uint8_t sides) { return sides != 0; });
  if (!any_inside) {  // bounded faces that the hole points all ate
    DomainProblem p;
    p.kind = DomainProblemKind::empty_domain;
    p.message = "the domain is empty: every face of the segments is unbounded or contains a hole point";
    throw InvalidDomain({std::move(p)});
  }
  DomainClassification out;
  keep_meshed_part(domain, scan, vertices_in_domain(cdt, labels, domain.points.size()), out);
  return out;
}

// F(P) over the discretized boundary: every inside side of a segment contributes its chain
// of subsegments, run in the direction that has that side on its left.
DomainTriangulation front_of(const DomainClassification& c, const DiscretizedBoundary& boundary) {
  DomainTriangulation out;
  std::vector<std::uint32_t> first(c.inside_sides.size() + 1, 0);  // subsegments of segment s
  for (const std::uint32_t s : boundary.origin) ++first[s + 1];
  for (std::size_t s = 0; s < c.inside_sides.size(); ++s) first[s + 1] += first[s];
  for (std::uint32_t s = 0; s < c.inside_sides.size(); ++s) {
    if (c.inside_sides[s] & 1u) {
      for (std::uint32_t k = first[s]; k < first[s + 1]; ++k) {
        out.front.push_back({boundary.subsegments[k].a, boundary.subsegments[k].b});
        out.front_region.push_back(c.region[s][0]);
      }
    }
    if (c.inside_sides[s] & 2u) {
      for (std::uint32_t k = first[s + 1]; k-- > first[s];) {
        out.front.push_back({boundary.subsegments[k].b, boundary.subsegments[k].a});
        out.front_region.push_back(c.region[s][1]);
      }
    }
  }
  return out;
}

}  // namespace certimesh::generators::detail
