// Compile-time checks of the floating-point environment the filter proofs assume, and the
// choice between the inline filters and their out-of-line copies (proofs/README.md
// section 1, "The floating-point environment").
//
// The filters are proven for IEEE binary64 with round-to-nearest, no contraction of a*b+c
// into a fused multiply-add, no excess precision and no fast-math rewriting. Inline code
// takes the including translation unit's flags, which the library does not control, so:
//
// Refused (#error): -ffast-math (__FAST_MATH__), anywhere; excess precision
//   (__FLT_EVAL_METHOD__ != 0) inside the kernel itself.
// Routed to the out-of-line copies, compiled inside the kernel with -ffp-contract=off
//   (sound: the inline remainder then does no floating-point arithmetic at all):
//   - any sign that the target can fuse a*b+c (__FP_FAST_FMA, __FMA__, __FMA4__,
//     __ARM_FEATURE_FMA). No pragma can stop the fusion for every consumer flag: clang 14
//     honours `#pragma clang fp contract(off)` under its default -ffp-contract=on but
//     ignores it under -ffp-contract=fast (measured: 16 FMAs in the inlined filters at
//     -march=haswell -ffp-contract=fast, with or without the pragma), and GCC 12's
//     optimize("fp-contract=off") attribute only keeps the function from being inlined
//     (measured), i.e. it is this route with a copy per translation unit;
//   - excess precision (__FLT_EVAL_METHOD__ != 0, e.g. GCC -mfpmath=387);
//   - -ffinite-math-only (__FINITE_MATH_ONLY__): inline comparisons could assume no NaN,
//     and NaN input must come out uncertain;
//   - GCC's -fassociative-math (__ASSOCIATIVE_MATH__);
//   - compilers other than GCC and clang, whose contraction rules are not known here;
//   - CERTIMESH_FILTERS_ALWAYS_OUT_OF_LINE defined by the consumer (see below).
// Not detectable, documented: clang's -fassociative-math has no macro (the pragma below
// switches reassociation off inside the filters, which clang 14 honours); a function with
// __attribute__((target("fma"))) in a translation unit compiled without FMA flags sees
// none of the macros, and GCC then inlines and contracts the filters into it (measured: 5
// FMAs in orient3d). Define CERTIMESH_FILTERS_ALWAYS_OUT_OF_LINE, or compile such files
// with -ffp-contract=off. The rounding mode is checked at run time where it is cheap: a
// thread's first exact stage throws FpEnvironmentError unless the mode is round-to-nearest
// without flush-to-zero (fp_environment.h); the inline filters do not check.
#pragma once

#if defined(__FAST_MATH__)
#error "certimesh predicates need IEEE arithmetic: do not compile code that includes them with -ffast-math (or -Ofast); -ffp-contract=fast is fine"
#endif

#if defined(CERTIMESH_KERNEL_TU) && defined(__FLT_EVAL_METHOD__) && (__FLT_EVAL_METHOD__ != 0)
#error "the certimesh kernel must be built with binary64 evaluation (FLT_EVAL_METHOD == 0: SSE2 on x86, not -mfpmath=387)"
#endif

#if defined(__FP_FAST_FMA) || defined(__FMA__) || defined(__FMA4__) || defined(__ARM_FEATURE_FMA)
#define CERTIMESH_DETAIL_TARGET_CAN_FUSE 1
#else
#define CERTIMESH_DETAIL_TARGET_CAN_FUSE 0
#endif

#if defined(CERTIMESH_KERNEL_TU)
// The kernel's own flags pin the environment (cmake/CertimeshFloatingPoint.cmake).
#define CERTIMESH_FILTERS_OUT_OF_LINE 0
#elif defined(CERTIMESH_FILTERS_ALWAYS_OUT_OF_LINE) || CERTIMESH_DETAIL_TARGET_CAN_FUSE || \
    (defined(__FLT_EVAL_METHOD__) && (__FLT_EVAL_METHOD__ != 0)) ||                        \
    (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__) || defined(__ASSOCIATIVE_MATH__) || \
    !defined(__GNUC__)
#define CERTIMESH_FILTERS_OUT_OF_LINE 1
#else
#define CERTIMESH_FILTERS_OUT_OF_LINE 0
#endif

// First statement of every inline filter body. clang: contraction and reassociation off
// for the function, whatever its caller's target (a target("fma") caller under clang's
// default -ffp-contract=on would otherwise fuse). GCC has no per-function control that
// keeps a function inlinable, so nothing: the routing above covers it.
#if defined(__clang__)
#define CERTIMESH_FILTER_FP_STRICT _Pragma("clang fp contract(off) reassociate(off)")
#else
#define CERTIMESH_FILTER_FP_STRICT
#endif
