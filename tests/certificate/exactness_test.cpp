// The certificate decides signs exactly: an element one ulp from flat is accepted when it
// is positive and rejected as inverted when it is negative, and exact maps (translation by
// a power of two, scaling by 2^±k) leave the verdict unchanged at any magnitude. A checker
// with a tolerance, or one whose arithmetic overflows or underflows, fails these.
#include "rc_support.h"

#include <cmath>

namespace certimesh::testing {
namespace {

using Defect = certificate::Defect;

// Moves an interior vertex v of some element e onto e's opposite facet (exactly), then one
// ulp along the first axis that gives e the sign `wanted` (by the oracle). Returns e, or -1
// when no axis does.
std::int64_t one_ulp_from_flat(io::MeshData& m, std::uint64_t choice, int wanted) {
  const auto corner = fuzz::pick(fuzz::interior_corners(m), choice);
  RC_PRE(corner.has_value());
  const auto [e, k] = *corner;
  const fuzz::Simplex s = fuzz::element(m, e);
  const fuzz::Point3 on_facet = fuzz::point_inside_facet(m, fuzz::facet_opposite(s, k));
  for (std::size_t axis = 0; axis < static_cast<std::size_t>(m.dimension); ++axis)
    for (double toward : {-INFINITY, INFINITY}) {
      fuzz::Point3 p = on_facet;
      p[axis] = std::nextafter(p[axis], toward);
      fuzz::set_point(m, s[k], p);
      if (oracle_element_sign(m, s) == wanted) return static_cast<std::int64_t>(e);
    }
  return -1;
}

void nearly_flat_accepted(int dim) {
  DrawnGrid g = draw_grid(dim, *rc::gen::arbitrary<bool>());
  const std::int64_t e = one_ulp_from_flat(g.mesh, *rc::gen::inRange<std::uint64_t>(0, 1u << 20), +1);
  RC_PRE(e >= 0);
  RC_PRE(all_elements_positive(g.mesh));  // the star of the moved vertex stayed valid
  RC_PRE(!has_coincident_vertices(g.mesh));
  expect_accepted(g.mesh, nullptr);
}

void one_ulp_inverted_rejected(int dim) {
  DrawnGrid g = draw_grid(dim, *rc::gen::arbitrary<bool>());
  const std::int64_t e = one_ulp_from_flat(g.mesh, *rc::gen::inRange<std::uint64_t>(0, 1u << 20), -1);
  RC_PRE(e >= 0);
  RC_PRE(elements_with_sign(g.mesh, 0).empty());
  RC_PRE(!has_coincident_vertices(g.mesh));
  const fuzz::MutationSite negative{elements_with_sign(g.mesh, -1), {}};
  expect_rejected(g.mesh, nullptr, Defect::inverted_element, &negative);
}

RC_GTEST_PROP(Exactness, NearlyFlatElementAccepted2d, ()) { nearly_flat_accepted(2); }
RC_GTEST_PROP(Exactness, NearlyFlatElementAccepted3d, ()) { nearly_flat_accepted(3); }
RC_GTEST_PROP(Exactness, OneUlpInvertedElementRejected2d, ()) { one_ulp_inverted_rejected(2); }
RC_GTEST_PROP(Exactness, OneUlpInvertedElementRejected3d, ()) { one_ulp_inverted_rejected(3); }

// Exact maps: x -> 2^s x + 2^t (every grid coordinate has at most 3 + 8 significant bits,
// so with t <= 40 the sum is exact; 2^s scaling is exact away from overflow/underflow).
io::MeshData mapped(io::MeshData m, int scale_exponent, double shift) {
  for (double& x : m.coordinates) x = std::ldexp(x, scale_exponent) + shift;
  for (double& x : m.holes) x = std::ldexp(x, scale_exponent) + shift;
  return m;
}

void verdicts_survive_exact_maps(int dim) {
  const DrawnGrid g = draw_grid(dim, true, true);
  const int scale = *rc::gen::element(-900, -400, -60, 0, 60, 300, 400, 900);
  const double shift = scale == 0 ? std::ldexp(1.0, *rc::gen::element(20, 30, 40)) : 0.0;
  const io::MeshData mesh = mapped(g.mesh, scale, shift);
  const io::MeshData domain = mapped(g.domain, scale, shift);
  RC_ASSERT(all_elements_positive(mesh));
  const certificate::Report alone = certificate::check_mesh(mesh);
  if (!alone.valid) RC_FAIL("rejected after x -> 2^" + std::to_string(scale) + " x + " + std::to_string(shift) +
                            ": " + describe(alone.finding));
  expect_accepted(mesh, &domain);
  io::MeshData swapped = mesh;
  fuzz::swap_two_vertices(swapped, 0);
  expect_rejected(swapped, nullptr, Defect::inconsistent_orientation, nullptr);
}

RC_GTEST_PROP(Exactness, VerdictsSurviveExactMaps2d, ()) { verdicts_survive_exact_maps(2); }
RC_GTEST_PROP(Exactness, VerdictsSurviveExactMaps3d, ()) { verdicts_survive_exact_maps(3); }

// Quality is scale-invariant: after x -> 2^s x it must be the unscaled value (up to the
// rounding of an approximate formula), not Inf, NaN or null from overflowing or underflowing
// lengths, areas and volumes. Kept apart from the verdicts: quality is reported, not decided.
void quality_is_scale_invariant(int dim) {
  const DrawnGrid g = draw_grid(dim);
  const int scale = *rc::gen::element(-900, -500, -400, -60, 60, 400, 500, 900);
  const double reference = certificate::check_mesh(g.mesh).statistics.worst_quality;
  const double scaled = certificate::check_mesh(mapped(g.mesh, scale, 0.0)).statistics.worst_quality;
  RC_LOG() << "scale 2^" << scale << ": quality " << scaled << " vs " << reference << "\n";
  RC_ASSERT(std::abs(scaled - reference) <= 1e-9 * reference);
}

RC_GTEST_PROP(Exactness, QualityIsScaleInvariant2d, ()) { quality_is_scale_invariant(2); }
RC_GTEST_PROP(Exactness, QualityIsScaleInvariant3d, ()) { quality_is_scale_invariant(3); }

}  // namespace
}  // namespace certimesh::testing
