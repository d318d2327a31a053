// The predicate calls of the flags consumer, in their own translation unit so that its
// object code holds nothing but what the certimesh headers inline into a consumer (the
// FMA scan reads it). Signs as ints: -1, 0, +1; "filtered" returns 2 for uncertain.
#pragma once

namespace fp_consumer {

int orient2d(const double* a, const double* b, const double* c);
int orient3d(const double* a, const double* b, const double* c, const double* d);
int incircle(const double* a, const double* b, const double* c, const double* d);
int insphere(const double* a, const double* b, const double* c, const double* d,
             const double* e);

int orient2d_filtered(const double* a, const double* b, const double* c);
int orient3d_filtered(const double* a, const double* b, const double* c, const double* d);
int incircle_filtered(const double* a, const double* b, const double* c, const double* d);
int insphere_filtered(const double* a, const double* b, const double* c, const double* d,
                      const double* e);

/// 1 when the certimesh headers chose their out-of-line filters in this build.
int filters_out_of_line();

}  // namespace fp_consumer
