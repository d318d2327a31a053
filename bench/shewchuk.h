// Shewchuk's predicates.c, the bench's optional reference peer (bench/CMakeLists.txt,
// CERTIMESH_BENCH_SHEWCHUK_SOURCE). Without it the shewchuk implementation reports
// itself unavailable and its benchmarks are not registered.
#pragma once

#ifndef CERTIMESH_BENCH_HAVE_SHEWCHUK
#define CERTIMESH_BENCH_HAVE_SHEWCHUK 0
#endif

#if CERTIMESH_BENCH_HAVE_SHEWCHUK
namespace certimesh_bench::shewchuk {
extern "C" {
void exactinit();
double orient2d(double* pa, double* pb, double* pc);
double orient3d(double* pa, double* pb, double* pc, double* pd);
double incircle(double* pa, double* pb, double* pc, double* pd);
double insphere(double* pa, double* pb, double* pc, double* pd, double* pe);
}
}  // namespace certimesh_bench::shewchuk
#endif
