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
#include "delaunay_completion.h"
#include "domain_triangulation.h"
#include "improvement_region.h"
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

// Times the stages (for the statistics only: no decision depends on time).
class StageClock {
 public:
  explicit StageClock(std::vector<StageTiming>& out) : out_(out), start_(Clock::now()) {}
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
  for (RegionSeed& r : domain.regions) r.point = scaled(r.point, e);
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
  std::vector<io::Label> labels;
  std::uint64_t completed_by_delaunay = 0;
  std::vector<DomainSegment> subsegments;  // empty: the discretized boundary's, unchanged
};

Generated advancing_front_stage(const detail::DomainTriangulation& dt, const detail::DiscretizedBoundary& boundary,
                                const MeshDomainOptions2& options, const ProgressCallback& progress,
                                StageClock& clock) {
  AdvancingFrontOptions front_options;
  front_options.size = options.size;
  front_options.max_global_retries = kMaxGlobalRetries;
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
  return out;
}

// Improvement where the quality is below the target (improvement_region.h).
void improvement_stage(Generated& g, const detail::DiscretizedBoundary& boundary, const MeshDomainOptions2& options,
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
  detail::smooth_poor_regions(soup, boundary.subsegments, improve.target_quality, kSmoothingSweeps,
                              improve.min_angle_floor);
  if (options.target_quality <= 0.0 && options.algorithm == MeshAlgorithm2::delaunay)
    improve.target_quality = kDelaunayTargetQuality;
  const detail::RegionImprovementStats r = detail::improve_bad_region(soup, boundary.subsegments, improve, progress);
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

// The output: used vertices only, renumbered in first-use order of their ids (deterministic).
io::MeshData to_output(const Generated& g, const detail::DiscretizedBoundary& boundary) {
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
  out.triangle_labels = g.labels;
  for (const DomainSegment& s : subsegments) {
    out.segments.push_back(new_id[s.a]);
    out.segments.push_back(new_id[s.b]);
    out.segment_labels.push_back(s.label);
  }
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

// The whole domain as its own boundary: the domain triangulation's refusals (open loops, an
// empty domain) then name the input's own coordinates.
detail::DiscretizedBoundary unsplit(const PlanarDomain& domain) {
  detail::DiscretizedBoundary boundary{domain.points, domain.segments, {}};
  for (std::uint32_t s = 0; s < domain.segments.size(); ++s) boundary.origin.push_back(s);
  return boundary;
}

void scale_back(io::MeshData& mesh, int e) {
  for (double& c : mesh.coordinates) c = std::ldexp(c, e);
}

}  // namespace

MeshDomainResult2 mesh_domain_2(const PlanarDomain& input, const MeshDomainOptions2& input_options,
                                const ProgressCallback& progress) {
  MeshDomainResult2 result;
  StageClock clock(result.stats.timings);
  refuse_if_invalid(input);
  detail::triangulate_domain(input, unsplit(input), progress);  // refusals in the input's coordinates
  clock.lap("validation");
  const int exponent = scale_exponent(input);
  const PlanarDomain domain = scaled(input, -exponent);
  MeshDomainOptions2 options = input_options;
  options.size = detail::boundary_adapted_policy(domain, scaled(input_options.size, -exponent));
  if (options.min_angle <= 0.0 && options.algorithm == MeshAlgorithm2::delaunay) options.min_angle = kDelaunayMinAngle;
  clock.lap("size field");
  const detail::DiscretizedBoundary boundary = discretize_valid_boundary(domain, options.size);
  result.stats.boundary_vertices = boundary.points.size();
  clock.lap("boundary");
  const detail::DomainTriangulation dt = detail::triangulate_domain(domain, boundary, progress);
  clock.lap("domain triangulation");
  Generated generated;
  const bool quality = options.min_angle > 0.0;
  if (options.algorithm == MeshAlgorithm2::advancing_front) {
    generated = advancing_front_stage(dt, boundary, options, progress, clock);
  } else if (!quality) {
    const detail::RefinedTriangulation refined = detail::refine_domain(domain, boundary, options.size, progress);
    generated = Generated{refined.points, refined.triangles, refined.labels, 0, {}};
    clock.lap("delaunay refinement");
  }
  if (options.improve && !generated.triangles.empty()) {
    improvement_stage(generated, boundary, options, progress, result.stats);
    clock.lap("improvement");
  }
  if (quality) {
    quality_stage(domain, boundary, options, progress, generated, result.stats);
    clock.lap("quality refinement");
  }
  result.mesh = to_output(generated, boundary);
  result.stats.completed_by_delaunay = generated.completed_by_delaunay;
  quality_statistics(result.mesh, result.stats);  // in the scaled copy: no area underflows at 2^-900
  scale_back(result.mesh, exponent);
  return result;
}

}  // namespace certimesh::generators
