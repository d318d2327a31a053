// The certimesh side of the benchmark: naive double determinants, the certimesh
// predicates (filter + exact stage, filter only, exact stage only) and the bench-only
// prototype filters, each inlined into the shared loop of loop.h.
//
// Built with the kernel's floating-point flags (certimesh_kernel_fp): the inline
// filters then run under exactly the flags their proofs assume, as in the kernel's own
// translation units. The naive loops live here too, so they are compiled with the same
// flags and the same loop.
#include <cstdint>

#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "impls.h"
#include "loop.h"
#include "prototype_filters.h"
#include "shewchuk.h"

namespace certimesh_bench {
namespace {

namespace cp = certimesh::predicates;
namespace cd = certimesh::predicates::detail;

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// ---- Shewchuk's predicates.c: arrays of doubles, the result's sign ---------------------

#if CERTIMESH_BENCH_HAVE_SHEWCHUK

inline int sk_orient2d(const Point2* t) {
  double a[2] = {t[0].x, t[0].y}, b[2] = {t[1].x, t[1].y}, c[2] = {t[2].x, t[2].y};
  return sign_of(shewchuk::orient2d(a, b, c));
}
inline int sk_incircle(const Point2* t) {
  double a[2] = {t[0].x, t[0].y}, b[2] = {t[1].x, t[1].y}, c[2] = {t[2].x, t[2].y},
         d[2] = {t[3].x, t[3].y};
  return sign_of(shewchuk::incircle(a, b, c, d));
}
inline int sk_orient3d(const Point3* t) {
  double a[3] = {t[0].x, t[0].y, t[0].z}, b[3] = {t[1].x, t[1].y, t[1].z},
         c[3] = {t[2].x, t[2].y, t[2].z}, d[3] = {t[3].x, t[3].y, t[3].z};
  return sign_of(shewchuk::orient3d(a, b, c, d));
}
inline int sk_insphere(const Point3* t) {
  double a[3] = {t[0].x, t[0].y, t[0].z}, b[3] = {t[1].x, t[1].y, t[1].z},
         c[3] = {t[2].x, t[2].y, t[2].z}, d[3] = {t[3].x, t[3].y, t[3].z},
         e[3] = {t[4].x, t[4].y, t[4].z};
  return sign_of(shewchuk::insphere(a, b, c, d, e));
}
#else
// Not built (no CERTIMESH_BENCH_SHEWCHUK_SOURCE): never registered, never called.
inline int sk_orient2d(const Point2*) { return 0; }
inline int sk_incircle(const Point2*) { return 0; }
inline int sk_orient3d(const Point3*) { return 0; }
inline int sk_insphere(const Point3*) { return 0; }
#endif

// ---- naive: the filters' own determinant formulas (detail/filters.h), no bound ----------

inline int naive_orient2d(const Point2* t) {
  const Point2 &a = t[0], &b = t[1], &c = t[2];
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  return sign_of(acx * bcy - acy * bcx);
}

inline int naive_orient3d(const Point3* t) {
  const Point3 &a = t[0], &b = t[1], &c = t[2], &d = t[3];
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  return sign_of(adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
                 cdx * (ady * bdz - adz * bdy));
}

inline int naive_incircle(const Point2* t) {
  const Point2 &a = t[0], &b = t[1], &c = t[2], &d = t[3];
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  return sign_of(alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                 clift * (adx * bdy - bdx * ady));
}

inline int naive_insphere(const Point3* t) {
  const Point3 &a = t[0], &b = t[1], &c = t[2], &d = t[3], &e = t[4];
  const double aex = a.x - e.x, bex = b.x - e.x, cex = c.x - e.x, dex = d.x - e.x;
  const double aey = a.y - e.y, bey = b.y - e.y, cey = c.y - e.y, dey = d.y - e.y;
  const double aez = a.z - e.z, bez = b.z - e.z, cez = c.z - e.z, dez = d.z - e.z;
  const double ab = aex * bey - bex * aey;
  const double bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey;
  const double da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey;
  const double bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  return sign_of((dlift * abc - clift * dab) + (blift * cda - alift * bcd));
}

// ---- dispatch: one switch per pass, the loop below it is the shared template -------------

template <std::size_t K, class P, class F>
long long run(const void* pts, std::size_t n, std::int8_t* out, F f) {
  const auto* q = static_cast<const P*>(pts);
  if (out == nullptr) return sum_signs<K>(q, n, f);
  store_signs<K>(q, n, out, f);
  return 0;
}

#define CM_LAMBDA2(expr) [](const Point2* t) { return (expr); }
#define CM_LAMBDA3(expr) [](const Point3* t) { return (expr); }

long long dispatch(Predicate p, Impl impl, const void* pts, std::size_t n, std::int8_t* out) {
  // Each (predicate, impl) pair gets its own instantiation of the loop, with the
  // predicate inlined; the switch runs once per pass.
  switch (p) {
    case Predicate::orient2d:
      switch (impl) {
        case Impl::naive:
          return run<3, Point2>(pts, n, out, CM_LAMBDA2(naive_orient2d(t)));
        case Impl::filtered:
          return run<3, Point2>(pts, n, out,
                                CM_LAMBDA2(cp::to_int(cp::orient2d(t[0], t[1], t[2]))));
        case Impl::filteronly:
          return run<3, Point2>(pts, n, out,
                                CM_LAMBDA2(cp::to_int(cp::orient2d_filtered(t[0], t[1], t[2]))));
        case Impl::exact:
          return run<3, Point2>(pts, n, out,
                                CM_LAMBDA2(cp::to_int(cd::orient2d_exact_stage(t[0], t[1], t[2]))));
        case Impl::prototype_ozaki:
          return run<3, Point2>(
              pts, n, out, CM_LAMBDA2(cp::to_int(prototype::orient2d_ozaki(t[0], t[1], t[2]))));
        case Impl::prototype_fastexact:
          return run<3, Point2>(
              pts, n, out,
              CM_LAMBDA2(cp::to_int(prototype::orient2d_fastexact(t[0], t[1], t[2]))));
        case Impl::shewchuk:
          return run<3, Point2>(pts, n, out, CM_LAMBDA2(sk_orient2d(t)));
      }
      break;
    case Predicate::orient3d:
      switch (impl) {
        case Impl::naive:
          return run<4, Point3>(pts, n, out, CM_LAMBDA3(naive_orient3d(t)));
        case Impl::filtered:
          return run<4, Point3>(pts, n, out,
                                CM_LAMBDA3(cp::to_int(cp::orient3d(t[0], t[1], t[2], t[3]))));
        case Impl::filteronly:
          return run<4, Point3>(
              pts, n, out, CM_LAMBDA3(cp::to_int(cp::orient3d_filtered(t[0], t[1], t[2], t[3]))));
        case Impl::exact:
          return run<4, Point3>(
              pts, n, out,
              CM_LAMBDA3(cp::to_int(cd::orient3d_exact_stage(t[0], t[1], t[2], t[3]))));
        case Impl::prototype_ozaki:
        case Impl::prototype_fastexact:
          break;  // orient2d only
        case Impl::shewchuk:
          return run<4, Point3>(pts, n, out, CM_LAMBDA3(sk_orient3d(t)));
      }
      break;
    case Predicate::incircle:
      switch (impl) {
        case Impl::naive:
          return run<4, Point2>(pts, n, out, CM_LAMBDA2(naive_incircle(t)));
        case Impl::filtered:
          return run<4, Point2>(pts, n, out,
                                CM_LAMBDA2(cp::to_int(cp::incircle(t[0], t[1], t[2], t[3]))));
        case Impl::filteronly:
          return run<4, Point2>(
              pts, n, out, CM_LAMBDA2(cp::to_int(cp::incircle_filtered(t[0], t[1], t[2], t[3]))));
        case Impl::exact:
          return run<4, Point2>(
              pts, n, out,
              CM_LAMBDA2(cp::to_int(cd::incircle_exact_stage(t[0], t[1], t[2], t[3]))));
        case Impl::prototype_ozaki:
        case Impl::prototype_fastexact:
          break;  // orient2d only
        case Impl::shewchuk:
          return run<4, Point2>(pts, n, out, CM_LAMBDA2(sk_incircle(t)));
      }
      break;
    case Predicate::insphere:
      switch (impl) {
        case Impl::naive:
          return run<5, Point3>(pts, n, out, CM_LAMBDA3(naive_insphere(t)));
        case Impl::filtered:
          return run<5, Point3>(pts, n, out,
                                CM_LAMBDA3(cp::to_int(cp::insphere(t[0], t[1], t[2], t[3], t[4]))));
        case Impl::filteronly:
          return run<5, Point3>(
              pts, n, out,
              CM_LAMBDA3(cp::to_int(cp::insphere_filtered(t[0], t[1], t[2], t[3], t[4]))));
        case Impl::exact:
          return run<5, Point3>(
              pts, n, out,
              CM_LAMBDA3(cp::to_int(cd::insphere_exact_stage(t[0], t[1], t[2], t[3], t[4]))));
        case Impl::prototype_ozaki:
        case Impl::prototype_fastexact:
          break;  // orient2d only
        case Impl::shewchuk:
          return run<5, Point3>(pts, n, out, CM_LAMBDA3(sk_insphere(t)));
      }
      break;
  }
  return 0;
}

}  // namespace

long long certimesh_sum(Predicate p, Impl impl, const void* points, std::size_t ntuples) {
  return dispatch(p, impl, points, ntuples, nullptr);
}

void certimesh_signs(Predicate p, Impl impl, const void* points, std::size_t ntuples,
                     std::int8_t* out) {
  dispatch(p, impl, points, ntuples, out);
}

}  // namespace certimesh_bench
