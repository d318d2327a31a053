// Condition 2: every facet is in one element (boundary) or two (interior) that induce
// opposite orientations on it. Facets are bucketed by their smallest vertex with a counting
// sort (linear, cache-friendly, no map, no per-facet allocation), then matched inside each
// small bucket by sorting on the remaining vertices.
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <new>
#include <stdexcept>
#ifdef __linux__
#include <sys/mman.h>
#endif
#include <utility>

#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

// The facet opposite corner i, oriented as the element induces it (outward in 3D for a
// positive tetrahedron: det[b-a, c-a, d-a] > 0; counterclockwise boundary in 2D).
constexpr int kEdge[3][2] = {{1, 2}, {2, 0}, {0, 1}};
constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct FacetPairingKey {
  Index v[3];   // sorted facet vertices (v[2] unused in 2D)
  int parity;   // 0: oriented facet is an even permutation of v, 1: odd
};

FacetPairingKey facet_key(const MeshView& m, std::size_t e, int i) {
  const Index* c = m.cell(e);
  FacetPairingKey k{};
  const int n = m.dim;
  for (int j = 0; j < n; ++j) k.v[j] = c[n == 2 ? kEdge[i][j] : kFace[i][j]];
  for (int a = 0; a < n; ++a)
    for (int b = n - 1; b > a; --b)
      if (k.v[b] < k.v[b - 1]) {
        std::swap(k.v[b], k.v[b - 1]);
        k.parity ^= 1;
      }
  return k;
}

// 12 bytes: the matching pass streams millions of these.
struct Record {
  Index hi0, hi1;       // facet vertices after the smallest one (bucket key)
  std::uint32_t packed;  // element << 3 | corner << 1 | parity
  std::uint32_t element() const { return packed >> 3; }
  int corner() const { return static_cast<int>(packed >> 1 & 3u); }
  int parity() const { return static_cast<int>(packed & 1u); }
};

// The smallest vertex of the facet opposite corner i: the smallest of the other corners.
Index facet_min(const Index* c, int corners, int i) {
  Index lo = c[i == 0 ? 1 : 0];
  for (int j = 0; j < corners; ++j)
    if (j != i && c[j] < lo) lo = c[j];
  return lo;
}

// The record array is the one big allocation (12 bytes per facet). Backing it with huge
// pages where the system offers them (Linux madvise mode) saves most of the page faults,
// which otherwise cost as much as the matching itself on a virtual machine.
using Records = std::unique_ptr<Record[], decltype(&std::free)>;
Records allocate_records(std::size_t count) {
  constexpr std::size_t kHuge = std::size_t{1} << 21;
  const std::size_t bytes = (std::max<std::size_t>(count, 1) * sizeof(Record) + kHuge - 1) / kHuge * kHuge;
  void* p = std::aligned_alloc(kHuge, bytes);
  if (p == nullptr) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  madvise(p, bytes, MADV_HUGEPAGE);
#endif
  return Records(static_cast<Record*>(p), &std::free);
}

struct Pass { Finding duplicate, non_manifold, inconsistent; };

std::string facet_text(const MeshView& m, Index lo, const Record& r) {
  std::string s = "facet (" + std::to_string(lo) + ", " + std::to_string(r.hi0);
  if (m.dim == 3) s += ", " + std::to_string(r.hi1);
  return s + ")";
}

Index apex(const MeshView& m, const Record& r) { return m.cell(r.element())[r.corner()]; }

// Two records of the group with the same apex (the same element listed twice), or -1: a sort
// of the apexes, so that a facet in 40,000 elements costs n log n, not n^2.
std::pair<std::size_t, std::size_t> same_apex(const MeshView& m, const Record* g, std::size_t n) {
  std::vector<std::pair<Index, std::size_t>> apexes(n);
  for (std::size_t a = 0; a < n; ++a) apexes[a] = {apex(m, g[a]), a};
  std::sort(apexes.begin(), apexes.end());
  for (std::size_t a = 1; a < n; ++a)
    if (apexes[a].first == apexes[a - 1].first) return {apexes[a - 1].second, apexes[a].second};
  return {SIZE_MAX, SIZE_MAX};
}

// One group of records naming the same facet.
void judge_group(const MeshView& m, Index lo, const Record* g, std::size_t n, Pass& pass) {
  if (const auto [a, b] = same_apex(m, g, n); a != SIZE_MAX && pass.duplicate.defect == Defect::none)
    pass.duplicate = finding(Defect::duplicate_element, g[b].element(), g[a].element(), -1,
                             "elements " + std::to_string(g[a].element()) + " and " +
                                 std::to_string(g[b].element()) + " have the same vertices");
  if (n > 2 && pass.non_manifold.defect == Defect::none)
    pass.non_manifold = finding(Defect::non_manifold_facet, g[2].element(), g[0].element(), lo,
                                facet_text(m, lo, g[0]) + " is in " + std::to_string(n) +
                                    " elements, among them " + std::to_string(g[0].element()) + ", " +
                                    std::to_string(g[1].element()) + " and " + std::to_string(g[2].element()));
  if (n == 2 && g[0].parity() == g[1].parity() && pass.inconsistent.defect == Defect::none)
    pass.inconsistent = finding(Defect::inconsistent_orientation, g[1].element(), g[0].element(), lo,
                                "elements " + std::to_string(g[0].element()) + " and " +
                                    std::to_string(g[1].element()) + " induce the same orientation on " +
                                    facet_text(m, lo, g[0]));
}

void add_boundary(const MeshView& m, const Record& r, FacetSet& boundary) {
  const Index* c = m.cell(r.element());
  for (int j = 0; j < m.dim; ++j)
    boundary.vertices.push_back(c[m.dim == 2 ? kEdge[r.corner()][j] : kFace[r.corner()][j]]);
  boundary.owner.push_back(r.element());
}

}  // namespace

Finding pair_facets(const MeshView& m, FacetSet& boundary, std::size_t& interior_facets) {
  const int k = m.corners();
  if (m.element_count >= std::size_t{1} << 29) throw std::length_error("the certificate checks at most 2^29 - 1 elements");
  std::vector<std::size_t> start(m.vertex_count + 1, 0);
  for (std::size_t e = 0; e < m.element_count; ++e)
    for (int i = 0; i < k; ++i) ++start[facet_min(m.cell(e), k, i) + 1];
  for (std::size_t v = 0; v < m.vertex_count; ++v) start[v + 1] += start[v];
  const auto records = allocate_records(start.back());  // no zero fill: every slot is written
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < m.element_count; ++e)
    for (int i = 0; i < k; ++i) {
      const FacetPairingKey key = facet_key(m, e, i);
      records[next[key.v[0]]++] = Record{key.v[1], m.dim == 3 ? key.v[2] : 0,
                                         static_cast<std::uint32_t>(e << 3 | static_cast<std::size_t>(i) << 1 |
                                                                    static_cast<std::size_t>(key.parity))};
    }
  boundary = FacetSet{m.dim, {}, {}};
  interior_facets = 0;
  Pass pass;
  for (Index lo = 0; lo < m.vertex_count; ++lo) {
    Record* first = records.get() + start[lo];
    Record* last = records.get() + start[lo + 1];
    std::sort(first, last, [](const Record& a, const Record& b) {
      return a.hi0 != b.hi0 ? a.hi0 < b.hi0 : (a.hi1 != b.hi1 ? a.hi1 < b.hi1 : a.packed < b.packed);
    });
    for (Record* g = first; g != last;) {
      Record* end = g + 1;
      while (end != last && end->hi0 == g->hi0 && end->hi1 == g->hi1) ++end;
      const auto n = static_cast<std::size_t>(end - g);
      if (n == 1) add_boundary(m, *g, boundary);
      if (n == 2) ++interior_facets;
      if (n >= 2) judge_group(m, lo, g, n, pass);
      if (pass.duplicate.defect != Defect::none) return pass.duplicate;
      g = end;
    }
  }
  if (pass.non_manifold.defect != Defect::none) return pass.non_manifold;
  return pass.inconsistent;
}

}  // namespace certimesh::certificate::detail
