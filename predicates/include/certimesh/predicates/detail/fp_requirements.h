// Compile-time checks of the floating-point environment the filter proofs assume, and the
// choice between the inline filters and their out-of-line copies.
//
// The filters are proven for IEEE binary64 with round-to-nearest and *no* contraction of
// a*b+c into a fused multiply-add. Inline code takes the including translation unit's
// flags, which the library does not control. On a target without FMA (x86-64 baseline)
// no contraction can happen, so the inline filters are safe and fast. Where the target
// has FMA (__FP_FAST_FMA: -mfma, -march=native, aarch64), the header calls the copies
// compiled inside the kernel with -ffp-contract=off instead.
#pragma once

#if defined(__FAST_MATH__)
#error "certimesh predicates need IEEE arithmetic: do not compile them with -ffast-math"
#endif

#if defined(__FLT_EVAL_METHOD__) && (__FLT_EVAL_METHOD__ != 0) && !defined(CERTIMESH_KERNEL_TU)
// x87 excess precision: only the kernel's own translation units are built with the flags
// that pin double evaluation.
#define CERTIMESH_FILTERS_OUT_OF_LINE 1
#elif defined(__FP_FAST_FMA) && !defined(CERTIMESH_KERNEL_TU)
#define CERTIMESH_FILTERS_OUT_OF_LINE 1
#else
#define CERTIMESH_FILTERS_OUT_OF_LINE 0
#endif
