// The campaign driver bites: deliberately broken kernels (mutants, compiled only here, never
// in the shipped CLI) are found by short campaigns, the real kernel runs clean for a fixed
// seed, the first finding is the same for 1 and 2 jobs, a written reproducer replays to the
// same finding, and the scaled-integer oracle agrees with the rational oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>
#include <string>
#include <thread>
#include <vector>

#include "certimesh/fuzz/campaign/campaign.h"
#include "certimesh/fuzz/campaign/case_seed.h"
#include "certimesh/fuzz/campaign/delaunay2d_target.h"
#include "certimesh/fuzz/campaign/intersection_target.h"
#include "certimesh/fuzz/campaign/mesh2d_target.h"
#include "certimesh/fuzz/campaign/predicates_target.h"
#include "certimesh/fuzz/campaign/readers_target.h"
#include "certimesh/fuzz/campaign/reproducer.h"
#include "certimesh/fuzz/recipes.h"
#include "certimesh/generators/delaunay/point_set_2.h"
#include "certimesh/predicates/filter_constants.h"
#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "rational_oracle.h"
#include "scaled_integer_oracle.h"

namespace {

namespace fc = certimesh::fuzz::campaign;
namespace pr = certimesh::predicates;
using P2 = pr::Point2;
using P3 = pr::Point3;

pr::FilteredSign certify(double det, double bound) {
  return det > bound ? pr::FilteredSign::positive : (det < -bound ? pr::FilteredSign::negative : pr::FilteredSign::uncertain);
}

// ---- The mutants: each one a single plausible mistake in the kernel.

// An orient2d filter whose error bound is zero: any non-zero rounded determinant is trusted.
pr::FilteredSign orient2d_zero_bound(const P2& a, const P2& b, const P2& c) {
  const double dl = (a.x - c.x) * (b.y - c.y);
  const double dr = (a.y - c.y) * (b.x - c.x);
  return certify(dl - dr, 0.0);
}

// An orient3d filter with its proven bound divided by 2^30 ("a filter bound too tight").
pr::FilteredSign orient3d_tight_bound(const P3& a, const P3& b, const P3& c, const P3& d) {
  namespace k = pr::filter_constants;
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy);
  const double maxx = std::max({std::fabs(adx), std::fabs(bdx), std::fabs(cdx)});
  const double maxy = std::max({std::fabs(ady), std::fabs(bdy), std::fabs(cdy)});
  const double maxz = std::max({std::fabs(adz), std::fabs(bdz), std::fabs(cdz)});
  const double lo = std::min({maxx, maxy, maxz}), hi = std::max({maxx, maxy, maxz});
  if (!(lo >= k::orient3d_lower_guard && hi <= k::orient3d_upper_guard)) return pr::FilteredSign::uncertain;
  return certify(det, std::ldexp(k::orient3d_error_bound * maxx * maxy * maxz, -30));
}

fc::PredicateKernel zero_bound_kernel() {
  auto k = fc::certimesh_predicate_kernel();
  k.orient2d_filtered = orient2d_zero_bound;
  k.orient2d = [](const P2& a, const P2& b, const P2& c) {
    const auto f = orient2d_zero_bound(a, b, c);
    return pr::is_certain(f) ? pr::certain_sign(f) : pr::detail::orient2d_exact_stage(a, b, c);
  };
  return k;
}

fc::PredicateKernel tight_bound_kernel() {
  auto k = fc::certimesh_predicate_kernel();
  k.orient3d_filtered = orient3d_tight_bound;
  return k;
}

// incircle "SoS" that forgets the perturbation: zero for distinct cocircular points.
fc::PredicateKernel unperturbed_sos_kernel() {
  auto k = fc::certimesh_predicate_kernel();
  k.incircle_sos = [](const P2& a, const P2& b, const P2& c, const P2& d) { return pr::incircle(a, b, c, d); };
  return k;
}

// orient2d SoS that breaks every tie towards positive, whatever the order of the points:
// never zero, right whenever the exact sign is not zero -- only a swap shows it.
fc::PredicateKernel constant_tiebreak_kernel() {
  auto k = fc::certimesh_predicate_kernel();
  k.orient2d_sos = [](const P2& a, const P2& b, const P2& c) {
    const pr::Sign s = pr::orient2d(a, b, c);
    return s == pr::Sign::zero && !(a == b || b == c || a == c) ? pr::Sign::positive : s;
  };
  return k;
}

struct Mutant {
  const char* name;
  fc::PredicateKernel (*kernel)();
  const char* expected;  // a substring of the first finding's message
};

const Mutant kMutants[] = {
    {"orient2d-zero-bound", zero_bound_kernel, "orient2d: the filter "},  // first: an infinite det trusted
    {"orient3d-bound-2^-30", tight_bound_kernel, "orient3d: the filter contradicts the exact sign"},
    {"incircle-sos-unperturbed", unperturbed_sos_kernel, "incircle: SoS is zero for distinct points"},
    {"orient2d-sos-constant-tiebreak", constant_tiebreak_kernel, "orient2d: SoS is not negated after swapping"},
};

constexpr std::uint64_t kSeed = 0x5eed;
constexpr std::uint64_t kMutantBudget = 2000;  // cases each mutant must be found within

fc::CampaignResult run(const fc::Target& t, std::uint64_t cases, unsigned jobs, bool keep_going = false,
                       std::uint64_t seed = kSeed) {
  fc::CampaignOptions o;
  o.cases = cases;
  o.seed = seed;
  o.jobs = jobs;
  o.keep_going = keep_going;
  o.chunk = 64;
  return fc::run_campaign(t, o);
}

// A mutant's campaign (kMutantBudget cases, one job), timed and printed for the README's
// table; the test fails when nothing is found.
std::optional<fc::CampaignResult> campaign_against(const fc::Target& mutant) {
  const auto t0 = std::chrono::steady_clock::now();
  auto r = run(mutant, kMutantBudget, 1);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (r.findings.size() != 1u) {
    ADD_FAILURE() << mutant.name() << ": not found within " << kMutantBudget << " cases";
    return std::nullopt;
  }
  const auto& f = r.findings.front();
  std::printf("mutant %-38s first finding at case %llu (%.0f ms): %s\n", std::string(mutant.name()).c_str(),
              static_cast<unsigned long long>(f.case_index), ms, f.finding.message.c_str());
  return r;
}

TEST(Campaign, EveryMutantIsFoundAndItsReproducerReplays) {
  for (const Mutant& m : kMutants) {
    SCOPED_TRACE(m.name);
    const auto target = fc::make_predicates_target(m.kernel(), m.name, "mutant");
    const auto r = campaign_against(*target);
    ASSERT_TRUE(r.has_value());
    const auto& f = r->findings.front();
    EXPECT_NE(f.finding.message.find(m.expected), std::string::npos) << f.finding.message;
    EXPECT_EQ(r->cases_run, f.case_index + 1) << "cases after the first finding were run";
    EXPECT_EQ(f.case_seed, fc::case_seed(kSeed, f.case_index));

    // The reproducer, through its text, replays to the same finding -- from the payload and
    // from the case seed.
    fc::Reproducer rep{fc::kReproducerFormatVersion, m.name, kSeed, f.case_index, f.case_seed,
                       f.finding.message, f.finding.payload};
    const fc::Reproducer back = fc::parse_reproducer(fc::write_reproducer(rep));
    EXPECT_EQ(back, rep);
    const auto replayed = target->replay(back.payload);
    ASSERT_TRUE(replayed.has_value());
    EXPECT_EQ(*replayed, f.finding);
    EXPECT_EQ(target->run_case(back.case_seed), f.finding);
    // The real kernel passes the same input: the finding is the mutant's.
    EXPECT_EQ(fc::make_predicates_target()->replay(back.payload), std::nullopt);
  }
}

// An intersection rule that drops the touching case: segments with an endpoint exactly on
// the other's line (touching, collinear overlap) answer disjoint, in both modes.
fc::IntersectionKernel dropped_touching_kernel() {
  auto k = fc::certimesh_intersection_kernel();
  k.segment_segment_2d = [](const std::array<pr::Vertex2, 2>& s, const std::array<pr::Vertex2, 2>& t, pr::IntersectionMode m) {
    const auto on_line = [](const std::array<pr::Vertex2, 2>& l, const pr::Vertex2& v) {
      return pr::orient2d(l[0].point, l[1].point, v.point) == pr::Sign::zero;
    };
    const bool finite = std::isfinite(s[0].point.x + s[0].point.y + s[1].point.x + s[1].point.y + t[0].point.x + t[0].point.y +
                                      t[1].point.x + t[1].point.y);
    if (finite && (on_line(s, t[0]) || on_line(s, t[1]) || on_line(t, s[0]) || on_line(t, s[1]))) return pr::Overlap::disjoint;
    return pr::segment_segment_2d(s, t, m);
  };
  return k;
}

// Conservative triangle_triangle_3d that skips the coplanar case: `disjoint` whenever the
// second triangle lies exactly in the first one's plane (exact mode untouched).
fc::IntersectionKernel skipped_coplanar_kernel() {
  auto k = fc::certimesh_intersection_kernel();
  k.triangle_triangle_3d = [](const std::array<pr::Vertex3, 3>& a, const std::array<pr::Vertex3, 3>& b, pr::IntersectionMode m) {
    if (m == pr::IntersectionMode::conservative) {
      bool coplanar = true;
      for (const auto& v : b)
        coplanar = coplanar && pr::orient3d_filtered(a[0].point, a[1].point, a[2].point, v.point) == pr::FilteredSign::uncertain &&
                   std::isfinite(v.point.x + v.point.y + v.point.z) &&
                   pr::orient3d(a[0].point, a[1].point, a[2].point, v.point) == pr::Sign::zero;
      if (coplanar) return pr::Overlap::disjoint;
    }
    return pr::triangle_triangle_3d(a, b, m);
  };
  return k;
}

TEST(Campaign, IntersectionMutantsAreFoundAndReplay) {
  const struct {
    const char* name;
    fc::IntersectionKernel (*kernel)();
    const char* expected;
  } mutants[] = {{"seg_seg2d-drops-touching", dropped_touching_kernel, "seg_seg2d: exact mode says disjoint, the exact oracle intersect"},
                 {"tri_tri3d-conservative-skips-coplanar", skipped_coplanar_kernel,
                  "tri_tri3d: conservative mode says disjoint for an intersecting pair"}};
  for (const auto& m : mutants) {
    SCOPED_TRACE(m.name);
    const auto target = fc::make_intersection_target(m.kernel(), m.name, "mutant");
    const auto r = campaign_against(*target);
    ASSERT_TRUE(r.has_value());
    const auto& f = r->findings.front();
    EXPECT_EQ(f.finding.message, m.expected);
    EXPECT_EQ(target->replay(f.finding.payload), f.finding);
    EXPECT_EQ(target->run_case(f.case_seed), f.finding);
    EXPECT_EQ(fc::make_intersection_target()->replay(f.finding.payload), std::nullopt);
  }
}

// A reader that parses numbers as floats, not doubles: every coordinate rounded to float.
// The round trip cannot see it (the rounded data re-reads the same); the invariants see the
// huge ones become inf, and re-writing an unmutated file certimesh wrote sees the others.
certimesh::io::MeshData float_coordinates_reader(const std::string& ext, const std::string& contents,
                                                 const std::vector<std::pair<std::string, std::string>>& companions) {
  auto m = fc::certimesh_reader_kernel().read(ext, contents, companions);
  for (double& v : m.coordinates) v = static_cast<double>(static_cast<float>(v));
  return m;
}

// A Delaunay triangulation whose flip test is inverted once: the first interior edge whose
// quadrilateral is strictly convex is flipped, from Delaunay to (usually) not.
certimesh::io::MeshData flipped_once(const certimesh::io::MeshData& points) {
  auto m = certimesh::generators::delaunay_of_points(points);
  const auto pt = [&](std::uint32_t i) { return P2{m.coordinates[2 * i], m.coordinates[2 * i + 1]}; };
  auto& t = m.triangles;
  for (std::size_t a = 0; a < m.triangle_count(); ++a)
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t b = 0; b < m.triangle_count(); ++b)
        for (std::size_t j = 0; j < 3; ++j) {
          const auto u = t[3 * a + i], v = t[3 * a + (i + 1) % 3], c = t[3 * a + (i + 2) % 3];
          if (t[3 * b + j] != v || t[3 * b + (j + 1) % 3] != u) continue;
          const auto d = t[3 * b + (j + 2) % 3];  // triangles (u v c), (v u d): flip uv to cd
          if (pr::orient2d(pt(u), pt(d), pt(c)) != pr::Sign::positive || pr::orient2d(pt(d), pt(v), pt(c)) != pr::Sign::positive) continue;
          t[3 * a] = u, t[3 * a + 1] = d, t[3 * a + 2] = c;
          t[3 * b] = d, t[3 * b + 1] = v, t[3 * b + 2] = c;
          return m;
        }
  return m;
}

// A pipeline whose last local modification skips its validity test: the last vertex (an
// interior or Steiner one) is moved to its mirror image through vertex 0, a boundary vertex.
certimesh::io::MeshData unchecked_last_move(const certimesh::generators::PlanarDomain& domain,
                                            certimesh::generators::MeshAlgorithm2 algorithm) {
  auto m = fc::certimesh_mesh2d_kernel().mesh(domain, algorithm);
  const std::size_t last = m.coordinates.size() - 2;
  for (std::size_t k = 0; k < 2; ++k) m.coordinates[last + k] = 2 * m.coordinates[k] - m.coordinates[last + k];
  return m;
}

TEST(Campaign, ReaderDelaunayAndMeshMutantsAreFoundAndReplay) {
  const struct {
    std::unique_ptr<fc::Target> mutant, real;
    const char* expected;
  } cases[] = {{fc::make_readers_target({float_coordinates_reader}, "readers-float-coordinates", "mutant"), fc::make_readers_target(),
                "readers ."},  // inf for the coordinates near 2^1000, other bytes for the rest
               {fc::make_delaunay2d_target({flipped_once}, "delaunay2d-inverted-flip", "mutant"), fc::make_delaunay2d_target(),
                "circumcircle"},
               {fc::make_mesh2d_target({unchecked_last_move}, "mesh2d-unchecked-move", "mutant"), fc::make_mesh2d_target(),
                "mesh2d: the certificate refuses the mesh"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(c.mutant->name()));
    const auto r = campaign_against(*c.mutant);
    ASSERT_TRUE(r.has_value());
    const auto& f = r->findings.front();
    EXPECT_NE(f.finding.message.find(c.expected), std::string::npos) << f.finding.message;
    EXPECT_LT(f.case_index, 200u) << "found, but not quickly";
    EXPECT_EQ(c.mutant->replay(f.finding.payload), f.finding);
    EXPECT_EQ(c.mutant->run_case(f.case_seed), f.finding);
    EXPECT_EQ(c.real->replay(f.finding.payload), std::nullopt);
  }
}

TEST(Campaign, RealKernelRunsCleanForAFixedSeed) {
  const auto registry = fc::builtin_targets();
  ASSERT_EQ(registry.all().size(), 5u);
  for (const auto& [name, cases] : {std::pair<const char*, std::uint64_t>{"predicates", 5000}, {"intersection", 1000},
                                    {"readers", 100}, {"delaunay2d", 1000}, {"mesh2d", 8}}) {
    const fc::Target* target = registry.find(name);
    ASSERT_NE(target, nullptr) << name;
    const auto r = run(*target, cases, 2);
    EXPECT_EQ(r.cases_run, cases) << name;
    for (const auto& f : r.findings) ADD_FAILURE() << name << " case " << f.case_index << ": " << f.finding.message << "\n  " << f.finding.payload;
  }
}

TEST(Campaign, FirstFindingIsTheSameForOneAndTwoJobs) {
  const auto target = fc::make_predicates_target(zero_bound_kernel(), "orient2d-zero-bound", "mutant");
  const auto one = run(*target, kMutantBudget, 1);
  const auto two = run(*target, kMutantBudget, 2);
  ASSERT_EQ(one.findings.size(), 1u);
  ASSERT_EQ(two.findings.size(), 1u);
  EXPECT_EQ(one.findings[0].case_index, two.findings[0].case_index);
  EXPECT_EQ(one.findings[0].finding, two.findings[0].finding);
  // With keep-going and a cases budget every finding is the same set, in the same order.
  const auto all1 = run(*target, 2000, 1, true), all2 = run(*target, 2000, 2, true);
  ASSERT_EQ(all1.findings.size(), all2.findings.size());
  ASSERT_GT(all1.findings.size(), 1u);
  for (std::size_t i = 0; i < all1.findings.size(); ++i) {
    EXPECT_EQ(all1.findings[i].case_index, all2.findings[i].case_index);
    EXPECT_EQ(all1.findings[i].finding, all2.findings[i].finding);
  }
  EXPECT_EQ(all1.cases_run, 2000u);
  // Not only non-finite input: the zero bound certifies wrong signs of finite points too.
  EXPECT_TRUE(std::any_of(all1.findings.begin(), all1.findings.end(), [](const fc::CaseFinding& f) {
    return f.finding.message == "orient2d: the filter contradicts the exact sign";
  }));
  EXPECT_EQ(all2.cases_run, 2000u);
}

TEST(Campaign, AThrowingTargetIsAFindingAndBadOptionsAreRefused) {
  struct Throws final : fc::Target {
    std::string_view name() const override { return "throws"; }
    std::string_view description() const override { return "throws at case seed % 7 == 3"; }
    std::optional<fc::Finding> run_case(std::uint64_t seed) const override {
      if (seed % 7 == 3) throw std::runtime_error("boom");
      return std::nullopt;
    }
    std::optional<fc::Finding> replay(std::string_view) const override { return std::nullopt; }
  } t;
  const auto r = run(t, 1000, 2);
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].finding.message, "exception: boom");
  // Independently: the lowest index whose seed is 3 mod 7.
  std::uint64_t first = 0;
  while (fc::case_seed(kSeed, first) % 7 != 3) ++first;
  EXPECT_EQ(r.findings[0].case_index, first);
  fc::CampaignOptions none;
  EXPECT_THROW(fc::run_campaign(t, none), std::invalid_argument);
}

// A seconds budget ends at the deadline (a spin once kept a 600 s campaign to 630 s) and
// reports progress on the calling thread at the interval asked for.
TEST(Campaign, SecondsBudgetStopsAtTheDeadlineWithProgress) {
  const auto target = fc::make_predicates_target();
  fc::CampaignOptions o;
  o.seconds = 0.5;
  o.jobs = 2;
  o.progress_interval = 0.1;
  std::vector<fc::CampaignProgress> reports;
  const auto caller = std::this_thread::get_id();
  bool same_thread = true;
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = fc::run_campaign(*target, o, [&](const fc::CampaignProgress& p) {
    reports.push_back(p);
    same_thread = same_thread && std::this_thread::get_id() == caller;
  });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_GE(wall, 0.5);
  EXPECT_LT(wall, 2.5) << "the campaign overran its deadline";
  EXPECT_GT(r.cases_run, 0u);
  EXPECT_TRUE(r.findings.empty());
  EXPECT_GE(reports.size(), 2u);
  EXPECT_TRUE(same_thread);
  for (std::size_t i = 1; i < reports.size(); ++i) EXPECT_GE(reports[i].cases_run, reports[i - 1].cases_run);
  // Without a progress callback (the case that hung before the fix).
  o.seconds = 0.3;
  const auto t1 = std::chrono::steady_clock::now();
  EXPECT_GT(fc::run_campaign(*target, o).cases_run, 0u);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count(), 2.3);
}

TEST(Reproducer, MalformedFilesNameTheLine) {
  const std::string good = fc::write_reproducer({1, "predicates", 42, 7, 0xabc, "m", "orient2d 0x1p+0 0x0p+0 0x1p+0 0x1p+0 0x0p+0 0x0p+0"});
  EXPECT_EQ(fc::parse_reproducer(good).seed, 42u);
  EXPECT_EQ(fc::parse_reproducer("# comment\n\n" + good).case_index, 7u);
  const auto error_of = [](const std::string& text) {
    try {
      (void)fc::parse_reproducer(text);
    } catch (const fc::MalformedReproducer& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error_of(""), "line 0: empty file (expected 'certimesh-fuzz-reproducer 1')");
  EXPECT_EQ(error_of("hello\n"), "line 1: not a certimesh fuzz reproducer (expected 'certimesh-fuzz-reproducer 1')");
  EXPECT_EQ(error_of("certimesh-fuzz-reproducer 2\n"), "line 1: format version 2 (this build reads version 1)");
  std::string bad_seed = good;
  bad_seed.replace(bad_seed.find("seed 0x2a"), 9, "seed 0xzz");
  EXPECT_EQ(error_of(bad_seed), "line 3: field 'seed' is not a 64-bit number: '0xzz'");
  EXPECT_EQ(error_of(good + "case 8\n"), "line 8: field 'case' given twice");
  EXPECT_EQ(error_of(good + "colour red\n"), "line 8: unknown field 'colour'");
  std::string no_payload = good.substr(0, good.find("payload"));
  EXPECT_EQ(error_of(no_payload), "line 6: field 'payload' missing");
  EXPECT_THROW((void)fc::write_reproducer({1, "t", 0, 0, 0, "two\nlines", "p"}), std::invalid_argument);
  const auto t = fc::make_predicates_target();
  EXPECT_THROW((void)t->replay("orient2d 1 2 3"), fc::MalformedPayload);
  EXPECT_THROW((void)t->replay("orient2d 1 2 3 4 5 six"), fc::MalformedPayload);
  EXPECT_THROW((void)t->replay("orient2d 1 2 3 4 5 6 7"), fc::MalformedPayload);
  EXPECT_THROW((void)t->replay("orient4d 1 2 3 4 5 6"), fc::MalformedPayload);
}

// The fast oracle against the rational one, on the campaign's own inputs: both arithmetic
// paths, every predicate.
template <std::size_t N, std::size_t Dim, class Gen>
void agree(Gen gen, bool lifted, int& int128_cases, int& mpz_cases) {
  for (std::uint64_t i = 0; i < 1200; ++i) {
    fc::SplitMixSource src(fc::case_seed(99, i));
    const auto c = gen(src);
    if (!certimesh::fuzz::all_finite(c.p)) continue;
    bool small = false;
    const int fast = certimesh::testing::scaled_integer_sign<Dim, N>(c.p, lifted, &small);
    ASSERT_EQ(fast, (certimesh::testing::oracle_sign<Dim, N>(c.p, lifted))) << c.family << " case " << i;
    ++(small ? int128_cases : mpz_cases);
  }
}

TEST(ScaledIntegerOracle, AgreesWithTheRationalOracle) {
  namespace fz = certimesh::fuzz;
  int small = 0, big = 0;
  agree<3, 2>([](auto& s) { return fz::any_orient2d(s); }, false, small, big);
  agree<4, 3>([](auto& s) { return fz::any_orient3d(s); }, false, small, big);
  agree<4, 2>([](auto& s) { return fz::any_incircle(s); }, true, small, big);
  agree<5, 3>([](auto& s) { return fz::any_insphere(s); }, true, small, big);
  std::printf("scaled-integer oracle: %d cases in __int128, %d in mpz\n", small, big);
  EXPECT_GT(small, 400);
  EXPECT_GT(big, 400);
}

// ---- The CLI (the shipped targets only).

struct CliRun {
  int status;
  std::string out;
};

CliRun cli(const std::string& args) {
  const std::string command = std::string(CERTIMESH_CLI) + " " + args + " 2>&1";
  FILE* p = popen(command.c_str(), "r");
  std::string out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, p)) out.append(buffer, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(Cli, ExitStatusListReportAndReplay) {
  const auto dir = std::filesystem::temp_directory_path() / ("certimesh_fuzz_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const CliRun list = cli("fuzz --list");
  EXPECT_EQ(list.status, 0);
  EXPECT_EQ(list.out.rfind("predicates ", 0), 0u) << list.out;

  const std::string report = (dir / "r.json").string();
  const CliRun clean = cli("fuzz predicates --cases 1000 --seed 0x10 --jobs 2 --report " + report + " --out " + dir.string());
  EXPECT_EQ(clean.status, 0) << clean.out;
  EXPECT_NE(clean.out.find("fuzz predicates: 1000 cases in "), std::string::npos) << clean.out;
  std::ifstream in(report);
  std::stringstream json;
  json << in.rdbuf();
  for (const char* key : {"\"target\": \"predicates\"", "\"seed\": \"0x10\"", "\"cases\": 1000", "\"seconds\": ",
                          "\"cases_per_second\": ", "\"commit\": ", "\"findings\": []"})
    EXPECT_NE(json.str().find(key), std::string::npos) << key << " in\n" << json.str();

  for (const char* bad : {"fuzz", "fuzz nosuchtarget", "fuzz predicates --cases 0", "fuzz predicates --cases 5 --seconds 1",
                          "fuzz predicates --jobs 0", "fuzz predicates --seed -1", "fuzz --list predicates",
                          "fuzz predicates --out /nonexistent/dir"}) {
    const CliRun r = cli(bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(r.out.rfind("error: ", 0), 0u) << bad << ": " << r.out;
  }

  // A reproducer whose input the real kernel passes (a mutant's, retargeted): exit 0.
  const auto mutant = fc::make_predicates_target(zero_bound_kernel(), "predicates", "mutant");
  const auto r = run(*mutant, kMutantBudget, 1);
  ASSERT_EQ(r.findings.size(), 1u);
  const auto repro = dir / "m.repro";
  std::ofstream(repro) << fc::write_reproducer({1, "predicates", kSeed, r.findings[0].case_index, r.findings[0].case_seed,
                                                r.findings[0].finding.message, r.findings[0].finding.payload});
  const CliRun replay = cli("fuzz --replay " + repro.string());
  EXPECT_EQ(replay.status, 0) << replay.out;
  EXPECT_NE(replay.out.find("now:      no finding"), std::string::npos) << replay.out;
  EXPECT_NE(replay.out.find("through this build's generators: no finding"), std::string::npos) << replay.out;
  std::ofstream(dir / "bad.repro") << "certimesh-fuzz-reproducer 1\ntarget predicates\n";
  const CliRun bad = cli("fuzz --replay " + (dir / "bad.repro").string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("error: "), std::string::npos);
  EXPECT_NE(bad.out.find("line 2: field 'seed' missing"), std::string::npos) << bad.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
