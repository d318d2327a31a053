// The 2D pipeline (mesh_domain_2.h): validate, discretize, triangulate the domain, generate,
// complete, improve. Each stage is a function of its own; this file only sequences them.
#include "certimesh/generators/mesh_domain_2.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "boundary_discretization.h"
#include "boundary_size_field.h"
#include "certimesh/generators/advancing_front/advancing_front_2.h"
#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/improvement/quality_improvement_2.h"
#include "certimesh/topology/quality.h"
#include "area_bound.h"
#include "delaunay_completion.h"
#include "domain_triangulation.h"
#include "improvement_region.h"
#include "isolated_vertices.h"
#include "vertex_smoothing.h"
#include "refinement_stage.h"
#include "region_labels.h"

namespace certimesh::generators {

namespace {

using Clock = std::chrono::steady_clock;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

constexpr int kSmoothingSweeps = 3;  // ideal-point smoothing sweeps before Algorithm 35
// The improvement target after the advancing front: above Algorithm 35's default (0.9), so
// that the few triangles between 0.9 and 0.93 where fronts meet are smoothed too; they are a
// few hundred in 10^6, and the Delaunay path (most of its triangles below 0.9) keeps 0.9.
constexpr double kFrontTargetQuality = 0.93;
// After Delaunay refinement most triangles lie between 0.8 and 0.9: the smoothing still works
// on those below 0.9, Algorithm 35 only on those below 0.85. Measured on the unit square at
// h = 0.005 (bench/RESULTS.md, "Improvement bounded"): with 0.9 the improvement took 2.7 s of CPU
// for a worst of 0.81; with 0.85 the worst is the same and the stage costs a fifth of that.
constexpr double kDelaunayTargetQuality = 0.85;
// Full enumerations the advancing front may fall back to (O(front) each) before it hands the
// rest to the Delaunay completion, which needs no retry.
constexpr std::uint64_t kMaxGlobalRetries = 256;
// ... and the front edges they may enumerate together: O(1) retries of a huge front.
constexpr std::uint64_t kMaxGlobalRetryWork = std::uint64_t{1} << 22;

// Times the stages (for the statistics only: no decision depends on time).
class DomainStageClock {
 public:
  explicit DomainStageClock(std::vector<StageTiming>& out) : out_(out), start_(Clock::now()) {}
  void lap(const char* stage) {
    const auto now = Clock::now();
    out_.push_back({stage, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<StageTiming>& out_;
  Clock::time_point start_;
};

void refuse_if_invalid(const PlanarDomain& domain) {
  std::vector<DomainProblem> problems = validate_domain(domain);
  if (!problems.empty()) throw InvalidDomain(std::move(problems));
}

// Scale invariance: the pipeline meshes a copy of the domain scaled by 2^-e, e the binary
// exponent of its largest coordinate magnitude, and scales the mesh back by 2^e. Scaling by a
// power of two is exact for every normal double, so a domain scaled by 2^k (k within the
// normal range) gives the same scaled copy, the same mesh bit for bit, and the same mesh
// scaled by 2^k -- whatever absolute quantity a stage may use. The scaled copy's largest
// coordinate is in [1, 2): no squared length under- or overflows there.
int scale_exponent(const PlanarDomain& domain) {
  double largest = 0.0;
  const auto see = [&](const Point2& p) { largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)}); };
  for (const Point2& p : domain.points) see(p);
  for (const Point2& p : domain.holes) see(p);
  for (const RegionSeed& r : domain.regions) see(r.point);
  return largest > 0.0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
}

Point2 scaled(const Point2& p, int e) { return {std::ldexp(p.x, e), std::ldexp(p.y, e)}; }

PlanarDomain scaled(PlanarDomain domain, int e) {
  for (Point2& p : domain.points) p = scaled(p, e);
  for (Point2& p : domain.holes) p = scaled(p, e);
  for (RegionSeed& r : domain.regions) {
    r.point = scaled(r.point, e);
    if (r.max_area > 0.0) r.max_area = std::ldexp(r.max_area, 2 * e);  // an area: the square of the scale
  }
  return domain;
}

SizePolicy scaled(SizePolicy size, int e) {
  if (size.uniform_size > 0.0) size.uniform_size = std::ldexp(size.uniform_size, e);
  if (size.size_function) {
    size.size_function = [user = std::move(size.size_function), e](const Point2& p) {
      return std::ldexp(user(scaled(p, -e)), e);
    };
  }
  return size;
}

// Splits the boundary; a split whose rounded Steiner points would make the boundary invalid
// (a chain that crosses a neighbour at a tiny angle) is undone for the segments involved.
detail::DiscretizedBoundary discretize_valid_boundary(const PlanarDomain& domain, const SizePolicy& size) {
  std::vector<std::uint8_t> keep_whole(domain.segments.size(), 0);
  for (int round = 0;; ++round) {
    detail::DiscretizedBoundary boundary = detail::discretize_boundary(domain, size, keep_whole);
    if (boundary.subsegments.size() == domain.segments.size()) return boundary;  // nothing split
    PlanarDomain split{boundary.points, {}, boundary.subsegments, {}, {}};
    const std::vector<DomainProblem> problems = validate_domain(split);
    if (problems.empty()) return boundary;
    if (round == 3) throw InvalidDomain(problems);
    for (const DomainProblem& p : problems) {
      for (const std::uint32_t s : p.segments) keep_whole[boundary.origin[s]] = 1;
    }
  }
}

struct Generated {
  std::vector<Point2> points;
  Triangles triangles;
  std::vector<io::Label> labels;  // internal: the region's 1-based index, 0 for no region
  std::uint64_t completed_by_delaunay = 0;
  std::vector<DomainSegment> subsegments;  // empty: the discretized boundary's, unchanged
};

// Inside the pipeline a triangle's label is its region's 1-based index (0: no seed), so that
// each region's attribute, label and maximum area are looked up, whatever the seeds say.
PlanarDomain with_indexed_regions(PlanarDomain domain) {
  for (std::size_t r = 0; r < domain.regions.size(); ++r) domain.regions[r].label = static_cast<io::Label>(r + 1);
  return domain;
}

std::vector<double> max_area_by_index(const PlanarDomain& domain) {
  std::vector<double> out{-1.0};
  for (const RegionSeed& r : domain.regions) out.push_back(r.max_area);
  return out;
}

Generated advancing_front_stage(const detail::DomainTriangulation& dt, const detail::DiscretizedBoundary& boundary,
                                const detail::DomainClassification& c, const MeshDomainOptions2& options,
                                const ProgressCallback& progress, DomainStageClock& clock) {
  AdvancingFrontOptions front_options;
  front_options.size = options.size;
  front_options.max_global_retries = kMaxGlobalRetries;
  front_options.max_global_retry_work = kMaxGlobalRetryWork;
  AdvancingFrontResult front = advance_front_2(boundary.points, dt.front, front_options, progress);
  clock.lap("advancing front");
  Generated out{std::move(front.points), std::move(front.triangles), {}, 0, {}};
  if (!front.remaining_front.empty()) {
    report(progress, "completion", 0, front.remaining_front.size());
    const Triangles rest = detail::complete_by_delaunay(out.points, front.remaining_front);
    out.completed_by_delaunay = rest.size();
    out.triangles.insert(out.triangles.end(), rest.begin(), rest.end());
    clock.lap("delaunay completion");
  }
  out.labels = detail::region_labels(out.triangles, dt.front, dt.front_region, 0);
  if (!c.isolated.empty()) {
    detail::TriangleSoup soup{std::move(out.points), std::move(out.triangles), std::move(out.labels)};
    detail::insert_isolated_vertices(soup, boundary.subsegments, c.isolated);
    out.points = std::move(soup.points);
    out.triangles = std::move(soup.triangles);
    out.labels = std::move(soup.labels);
    clock.lap("isolated vertices");
  }
  return out;
}

// Improvement where the quality is below the target (improvement_region.h).
void improvement_stage(Generated& g, const detail::DiscretizedBoundary& boundary,
                       std::span<const std::uint32_t> isolated, const MeshDomainOptions2& options,
                       const ProgressCallback& progress, MeshDomainStats2& stats) {
  ImprovementOptions2 improve;
  // Shape quality (improve.size left empty), not the size-aware one: the generator has
  // already placed the vertices for the size, the improvement works only on the poor
  // triangles and two rings around them, and what the pipeline reports and promises is shape
  // quality. Measured on the unit square (bench_mesh_2d, h = 0.01 ... 0.00125): with the
  // size-aware quality the front's worst shape stalled at 0.86-0.88 (Algorithm 35 worked on
  // triangles of poor size-aware but good shape quality), with shape quality 0.92-0.93; the
  // Delaunay path's worst went from 0.62 to 0.84 at h = 0.01.
  if (options.target_quality > 0.0) {
    improve.target_quality = options.target_quality;
  } else if (options.algorithm == MeshAlgorithm2::advancing_front) {
    improve.target_quality = kFrontTargetQuality;
  }
  detail::TriangleSoup soup{std::move(g.points), std::move(g.triangles), std::move(g.labels)};
  std::vector<DomainSegment> kept = boundary.subsegments;  // and an edge at each isolated vertex pins it
  const std::vector<DomainSegment> pins = detail::pin_edges(soup, isolated);
  kept.insert(kept.end(), pins.begin(), pins.end());
  detail::smooth_poor_regions(soup, kept, improve.target_quality, kSmoothingSweeps, improve.min_angle_floor);
  if (options.target_quality <= 0.0 && options.algorithm == MeshAlgorithm2::delaunay)
    improve.target_quality = kDelaunayTargetQuality;
  const detail::RegionImprovementStats r = detail::improve_bad_region(soup, kept, improve, progress);
  stats.improved_region = r.region_triangles;
  stats.improvement_iterations = r.improvement.iterations;
  for (const std::uint64_t n : r.improvement.successes) stats.improvement_operations += n;
  g.points = std::move(soup.points);
  g.triangles = std::move(soup.triangles);
  g.labels = std::move(soup.labels);
}

// Stage 6: the constrained Delaunay triangulation of the vertices the mesh has so far (none
// after --algorithm delaunay: then it is the whole Delaunay path, the size included), refined
// to the smallest angle. The generated triangles are replaced: the earlier stages only chose
// where the vertices go.
void quality_stage(const PlanarDomain& domain, const detail::DiscretizedBoundary& boundary,
                   const MeshDomainOptions2& options, const ProgressCallback& progress, Generated& g,
                   MeshDomainStats2& stats) {
  std::vector<std::uint8_t> used(g.points.size(), 0);
  for (const auto& t : g.triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  std::vector<Point2> interior;
  for (std::size_t v = boundary.points.size(); v < g.points.size(); ++v)
    if (used[v]) interior.push_back(g.points[v]);
  const SizePolicy size = g.triangles.empty() ? options.size : SizePolicy{};  // the front met the size
  detail::RefinedTriangulation refined = detail::refine_domain_quality(
      domain, boundary, interior, size, options.min_angle, options.max_steiner, progress);
  stats.quality_refined = true;
  stats.quality = refined.quality;
  g = Generated{std::move(refined.points), std::move(refined.triangles), std::move(refined.labels),
                g.completed_by_delaunay, std::move(refined.subsegments)};
}

// The output: used vertices only, renumbered in first-use order of their ids (deterministic);
// the domain's point markers on its vertices, a segment's marker on the Steiner points of its
// subsegments (as Triangle does); region labels, and real attributes when some region's
// attribute is not an integer.
io::MeshData to_output(const Generated& g, const detail::DiscretizedBoundary& boundary, const PlanarDomain& domain) {
  const std::vector<DomainSegment>& subsegments = g.subsegments.empty() ? boundary.subsegments : g.subsegments;
  constexpr std::uint32_t unused = UINT32_MAX;
  std::vector<std::uint32_t> new_id(g.points.size(), unused);
  for (std::uint32_t v = 0; v < boundary.points.size(); ++v) new_id[v] = v;  // boundary first, as given
  std::uint32_t next = static_cast<std::uint32_t>(boundary.points.size());
  for (const auto& t : g.triangles) {
    for (const std::uint32_t v : t) {
      if (new_id[v] == unused) new_id[v] = next++;
    }
  }
  io::MeshData out;
  out.dimension = 2;
  out.coordinates.resize(2 * static_cast<std::size_t>(next));
  for (std::uint32_t v = 0; v < g.points.size(); ++v) {
    if (new_id[v] == unused) continue;
    out.coordinates[2 * new_id[v]] = g.points[v].x;
    out.coordinates[2 * new_id[v] + 1] = g.points[v].y;
  }
  out.triangles.reserve(3 * g.triangles.size());
  for (const auto& t : g.triangles) {
    for (const std::uint32_t v : t) out.triangles.push_back(new_id[v]);
  }
  const bool real = std::any_of(domain.regions.begin(), domain.regions.end(), [](const RegionSeed& r) {
    return attribute_of(r) != static_cast<double>(r.label);
  });
  for (const io::Label index : g.labels) {  // the internal 1-based region index
    const RegionSeed* r = index > 0 ? &domain.regions[static_cast<std::size_t>(index - 1)] : nullptr;
    out.triangle_labels.push_back(r ? r->label : 0);
    if (real) out.triangle_attributes.push_back(r ? attribute_of(*r) : 0.0);
  }
  if (real) out.triangle_labels = io::labels_of_attributes(out.triangle_attributes);  // as the .ele reader makes them
  out.point_labels.assign(next, 0);
  for (const DomainSegment& s : subsegments) {
    out.segments.push_back(new_id[s.a]);
    out.segments.push_back(new_id[s.b]);
    out.segment_labels.push_back(s.label);
    for (const std::uint32_t v : {s.a, s.b})
      if (v >= domain.points.size()) out.point_labels[new_id[v]] = s.label;
  }
  for (std::uint32_t v = 0; v < domain.point_labels.size(); ++v) out.point_labels[v] = domain.point_labels[v];
  if (std::all_of(out.point_labels.begin(), out.point_labels.end(), [](io::Label l) { return l == 0; })) out.point_labels.clear();
  if (std::all_of(out.segment_labels.begin(), out.segment_labels.end(), [](io::Label l) { return l == 0; })) out.segment_labels.clear();
  if (std::all_of(out.triangle_labels.begin(), out.triangle_labels.end(), [](io::Label l) { return l == 0; })) out.triangle_labels.clear();
  return out;
}

void quality_statistics(const io::MeshData& mesh, MeshDomainStats2& stats) {
  stats.vertices = mesh.point_count();
  stats.triangles = mesh.triangle_count();
  double worst = 1.0, sum = 0.0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    topology::Point2d p[3];
    for (int i = 0; i < 3; ++i) {
      const io::Index v = mesh.triangles[3 * t + static_cast<std::size_t>(i)];
      p[i] = {mesh.coordinates[2 * v], mesh.coordinates[2 * v + 1]};
    }
    const double q = topology::triangle_quality(p[0], p[1], p[2]);
    worst = std::min(worst, q);
    sum += q;
  }
  stats.worst_quality = mesh.triangle_count() ? worst : 0.0;
  stats.mean_quality = mesh.triangle_count() ? sum / static_cast<double>(mesh.triangle_count()) : 0.0;
}

void scale_back(io::MeshData& mesh, int e) {
  for (double& c : mesh.coordinates) c = std::ldexp(c, e);
}

}  // namespace

MeshDomainResult2 mesh_domain_2(const PlanarDomain& input, const MeshDomainOptions2& input_options,
                                const ProgressCallback& progress) {
  MeshDomainResult2 result;
  DomainStageClock clock(result.stats.timings);
  refuse_if_invalid(input);
  detail::classify_domain(with_indexed_regions(input), progress);  // refusals in the input's coordinates
  clock.lap("validation");
  const int exponent = scale_exponent(input);
  const detail::DomainClassification c = detail::classify_domain(with_indexed_regions(scaled(input, -exponent)), progress);
  result.stats.eaten_segments = c.eaten_segments;
  result.stats.dropped_vertices = c.dropped_vertices;
  result.stats.isolated_vertices = c.isolated.size();
  const PlanarDomain& domain = c.kept;
  clock.lap("domain triangulation");
  MeshDomainOptions2 options = input_options;
  options.size = detail::boundary_adapted_policy(domain, scaled(input_options.size, -exponent));
  const std::vector<double> max_area = max_area_by_index(domain);
  MeshDomainOptions2 sized = options;  // aiming at the regions' maximum areas, if any
  sized.size = detail::size_for_max_areas(options.size, domain, max_area);
  clock.lap("size field");
  detail::DiscretizedBoundary boundary = discretize_valid_boundary(domain, sized.size);
  result.stats.boundary_vertices = boundary.points.size() - c.isolated.size();
  clock.lap("boundary");
  Generated generated;
  const bool quality = options.min_angle > 0.0;
  const bool has_max_area = std::any_of(max_area.begin(), max_area.end(), [](double a) { return a > 0; });
  if (options.algorithm == MeshAlgorithm2::advancing_front) {
    generated = advancing_front_stage(detail::front_of(c, boundary), boundary, c, sized, progress, clock);
  } else if (!quality || has_max_area) {  // with maximum areas the vertices follow the sizes first
    const detail::RefinedTriangulation refined = detail::refine_domain(domain, boundary, sized.size, progress);
    generated = Generated{refined.points, refined.triangles, refined.labels, 0, {}};
    clock.lap("delaunay refinement");
  }
  if (options.improve && !generated.triangles.empty()) {
    improvement_stage(generated, boundary, c.isolated, options, progress, result.stats);
    clock.lap("improvement");
  }
  // The maximum areas, by bisection of the mesh. With a minimum angle the quality refinement
  // re-triangulates the vertices instead (from the discretized boundary, which the bisection
  // would change under it): the areas are aimed at (the vertices follow the sized policy) but
  // not promised (the angle guarantee comes last).
  if (has_max_area && !quality) {
    detail::TriangleSoup soup{std::move(generated.points), std::move(generated.triangles), std::move(generated.labels)};
    result.stats.area_bisections = detail::enforce_max_areas(soup, boundary, domain, max_area);
    generated.points = std::move(soup.points);
    generated.triangles = std::move(soup.triangles);
    generated.labels = std::move(soup.labels);
    clock.lap("maximum areas");
  }
  if (quality) {
    quality_stage(domain, boundary, sized, progress, generated, result.stats);
    clock.lap("quality refinement");
  }
  PlanarDomain labelled = domain;  // the seeds' own labels for the output
  labelled.regions = input.regions;
  result.mesh = to_output(generated, boundary, labelled);
  result.stats.completed_by_delaunay = generated.completed_by_delaunay;
  quality_statistics(result.mesh, result.stats);  // in the scaled copy: no area underflows at 2^-900
  scale_back(result.mesh, exponent);
  return result;
}

}  // namespace certimesh::generators
