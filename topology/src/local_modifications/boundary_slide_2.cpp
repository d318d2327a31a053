// Algorithm 32 for a boundary node (local_modifications_2.h; digest D §2.1 2D-3, "boundary
// nodes may move only along boundary edges"): a Steiner vertex inside an input segment moves
// along that segment, between its two boundary neighbours. The search runs over the fraction f
// of the segment; every trial position is the rounding of the exact point of the segment at f
// (design decision 2), so the vertex stays on the input segment in the certificate's sense.
// Along a line the worst quality of the star is quasi-concave for the shape quality (as in the
// interior shift), so a golden-section search over the open interval between the neighbours'
// fractions finds its maximum; each trial point is checked exactly (strictly between the
// neighbours, every star triangle strictly counterclockwise).
#include <algorithm>
#include <limits>

#include "golden_section_search.h"
#include "input_segment_run_2.h"

namespace certimesh::topology {

namespace {

constexpr double invalid_slide_quality = -1.0;

// v's star with v at a trial position.
class SlidingStar {
 public:
  SlidingStar(const TriangleMesh2& mesh, VertexId v, const local::SegmentRun2& run,
              const LocalModificationOptions2& options)
      : run_(run), options_(options), before_(mesh.point(run.before)), after_(mesh.point(run.after)) {
    for (const ElementId e : run.star.elements) {
      triangles_.push_back(local::virtual_triangle(mesh, mesh.vertices(e), mesh.label(e)));
      moving_.push_back(static_cast<std::size_t>(local::local_index(mesh, e, v)));
    }
  }

  /// The star's worst quality with v at x, or `invalid_slide_quality` when x is not strictly between the
  /// neighbours along the segment or some star triangle is not strictly counterclockwise.
  double quality(const Point2d& x) {
    if (!local::strictly_between(before_, x, after_, run_.segment)) return invalid_slide_quality;
    double q = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < triangles_.size(); ++k) {
      triangles_[k].points[moving_[k]] = x;
      if (!local::is_positive(triangles_[k])) return invalid_slide_quality;
      q = std::min(q, local::quality_of(triangles_[k], options_));
    }
    return q;
  }

  Point2d at(double f) const { return options_.input_segments.point_on(run_.segment, f); }

 private:
  const local::SegmentRun2& run_;
  const LocalModificationOptions2& options_;
  Point2d before_, after_;
  std::vector<local::VirtualTriangle> triangles_;
  std::vector<std::size_t> moving_;
};

// The best fraction in the open interval between the neighbours' fractions by golden-section
// search, and the star's quality there (q0 and NaN when nothing beats q0).
std::pair<double, double> search_segment(SlidingStar& star, double lo, double hi, double q0) {
  return local::golden_section_best([&](double f) { return star.quality(star.at(f)); }, lo, hi, q0,
                                    std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

std::optional<LocalChange2> try_boundary_slide(TriangleMesh2& mesh, VertexId v, const Point2d& target,
                                               const LocalModificationOptions2& options) {
  const auto run = local::segment_run(mesh, v, options.input_segments);
  if (!run || target == mesh.point(v) || !local::lies_on(target, run->segment, options.input_segments))
    return std::nullopt;
  SlidingStar star(mesh, v, *run, options);
  const double q0 = star.quality(mesh.point(v));
  const double q1 = star.quality(target);
  if (q0 == invalid_slide_quality || !(q1 > q0 + options.minimum_shift_gain)) return std::nullopt;
  mesh.move_vertex(v, target);
  return LocalChange2{run->star.elements, run->star.elements};
}

std::optional<LocalChange2> local::slide_along_segment(TriangleMesh2& mesh, VertexId v,
                                                      const LocalModificationOptions2& options) {
  const auto run = local::segment_run(mesh, v, options.input_segments);
  if (!run) return std::nullopt;
  SlidingStar star(mesh, v, *run, options);
  const double q0 = star.quality(mesh.point(v));
  if (q0 == invalid_slide_quality) return std::nullopt;
  const double f_before = local::fraction_along(mesh.point(run->before), run->segment);
  const double f_after = local::fraction_along(mesh.point(run->after), run->segment);
  const auto [f, q1] = search_segment(star, std::min(f_before, f_after), std::max(f_before, f_after), q0);
  if (!(q1 > q0 + options.minimum_shift_gain)) return std::nullopt;
  const Point2d target = star.at(f);
  if (target == mesh.point(v)) return std::nullopt;
  mesh.move_vertex(v, target);
  return LocalChange2{run->star.elements, run->star.elements};
}

}  // namespace certimesh::topology
