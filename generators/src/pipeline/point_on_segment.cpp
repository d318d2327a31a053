#include "point_on_segment.h"

#include <gmp.h>
#include <mpfr.h>

namespace certimesh::generators::detail {

namespace {

// The correctly rounded double of an exact rational, subnormals included: MPFR rounds to
// 53 bits inside double's exponent range, then mpfr_subnormalize fixes the subnormal range.
double round_mpq_to_nearest(const mpq_t value) {
  const mpfr_exp_t saved_emin = mpfr_get_emin();
  const mpfr_exp_t saved_emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  mpfr_t rounded;
  mpfr_init2(rounded, 53);
  const int ternary = mpfr_set_q(rounded, value, MPFR_RNDN);
  mpfr_subnormalize(rounded, ternary, MPFR_RNDN);
  const double result = mpfr_get_d(rounded, MPFR_RNDN);
  mpfr_clear(rounded);
  mpfr_set_emin(saved_emin);
  mpfr_set_emax(saved_emax);
  return result;
}

// a + f·(b − a) for one coordinate, exactly, then rounded once.
double coordinate_on_segment(double a, double b, double f) {
  if (a == b || f == 0.0) return a;
  if (f == 1.0) return b;
  mpq_t qa, qb, qf;
  mpq_inits(qa, qb, qf, nullptr);
  mpq_set_d(qa, a);
  mpq_set_d(qb, b);
  mpq_set_d(qf, f);
  mpq_sub(qb, qb, qa);  // b − a
  mpq_mul(qb, qb, qf);  // f·(b − a)
  mpq_add(qb, qb, qa);  // a + f·(b − a)
  const double result = round_mpq_to_nearest(qb);
  mpq_clears(qa, qb, qf, nullptr);
  return result;
}

}  // namespace

predicates::Point2 point_on_segment(const predicates::Point2& a, const predicates::Point2& b, double f) {
  return {coordinate_on_segment(a.x, b.x, f), coordinate_on_segment(a.y, b.y, f)};
}

}  // namespace certimesh::generators::detail
