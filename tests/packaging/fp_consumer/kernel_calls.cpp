// Compiled with the consumer's flags (-O3 -march=native -ffp-contract=fast in the test):
// whatever the certimesh headers inline lands here.
#include "kernel_calls.h"

#include <certimesh/predicates/incircle.h>
#include <certimesh/predicates/insphere.h>
#include <certimesh/predicates/orient2d.h>
#include <certimesh/predicates/orient3d.h>

namespace cp = certimesh::predicates;

namespace fp_consumer {
namespace {

cp::Point2 p2(const double* p) { return {p[0], p[1]}; }
cp::Point3 p3(const double* p) { return {p[0], p[1], p[2]}; }
int code(cp::FilteredSign s) { return cp::is_certain(s) ? cp::to_int(cp::certain_sign(s)) : 2; }

}  // namespace

int orient2d(const double* a, const double* b, const double* c) {
  return cp::to_int(cp::orient2d(p2(a), p2(b), p2(c)));
}
int orient3d(const double* a, const double* b, const double* c, const double* d) {
  return cp::to_int(cp::orient3d(p3(a), p3(b), p3(c), p3(d)));
}
int incircle(const double* a, const double* b, const double* c, const double* d) {
  return cp::to_int(cp::incircle(p2(a), p2(b), p2(c), p2(d)));
}
int insphere(const double* a, const double* b, const double* c, const double* d,
             const double* e) {
  return cp::to_int(cp::insphere(p3(a), p3(b), p3(c), p3(d), p3(e)));
}

int orient2d_filtered(const double* a, const double* b, const double* c) {
  return code(cp::orient2d_filtered(p2(a), p2(b), p2(c)));
}
int orient3d_filtered(const double* a, const double* b, const double* c, const double* d) {
  return code(cp::orient3d_filtered(p3(a), p3(b), p3(c), p3(d)));
}
int incircle_filtered(const double* a, const double* b, const double* c, const double* d) {
  return code(cp::incircle_filtered(p2(a), p2(b), p2(c), p2(d)));
}
int insphere_filtered(const double* a, const double* b, const double* c, const double* d,
                      const double* e) {
  return code(cp::insphere_filtered(p3(a), p3(b), p3(c), p3(d), p3(e)));
}

int filters_out_of_line() { return CERTIMESH_FILTERS_OUT_OF_LINE; }

}  // namespace fp_consumer
