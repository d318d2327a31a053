// The constants of the semi-static filters, each proven by a Gappa script in proofs/gappa/.
//
// The orient3d, incircle and insphere filters have the same shape (proofs/README.md gives
// the derivation; orient2d has Ozaki et al.'s shape, below):
//   1. the coordinate differences are rounded once each;
//   2. the determinant is evaluated in double in a fixed order, no FMA;
//   3. per axis, the largest rounded |difference| is taken (orient3d), or one
//      largest over all axes (incircle, insphere, whose lifted column mixes the axes);
//   4. if those maxima lie inside [lower_guard, upper_guard] the computed determinant has
//      the exact sign whenever |det| > error_bound * (product of maxima, one per degree),
//      that product and the multiplication by error_bound being evaluated in double as
//      filters.h writes them.
// The proof divides every quantity by the product of the maxima of its degree: then each
// rounding is a relative error of at most 2^-53 and the error bound E does not depend on
// the scale. The guards keep that argument valid: below lower_guard an underflowing
// product could add an absolute error that does not scale (the proofs charge it at
// 2^-1074 / lower_guard^degree), above upper_guard an intermediate could overflow.
// error_bound is E / (1 - 2^-53)^r rounded up to a double, r being the number of roundings
// in the computation of the bound itself.
//
// Values are hex-float literals. The CTest test proofs.constants_match
// (proofs/check_constants.py) checks that each one is the value its proof establishes;
// do not edit by hand: change the proof (proofs/gappa/generate.py), then copy its values.
#pragma once

namespace certimesh::predicates::filter_constants {

// orient2d (Ozaki et al.'s filter, its own shape): with dl = fl(acx * bcy),
// dr = fl(acy * bcx) and det = fl(dl - dr), the sign of det is exact when
// |det| > fl(fl(theta * |fl(dl + dr)|) + underflow_bound). No guards: an overflow makes
// the comparison false. proofs/gappa/orient2d_ozaki.g proves it for these two values;
// theta is (1/(1 - 2^-53)^3 - 1) (1 + 2^-53) / (1 - 2^-53)^3 rounded up (3u + 20u^2),
// proofs/README.md section 10.
inline constexpr double orient2d_theta = 0x1.8000000000005p-52;  // 3.330669073875472e-16
inline constexpr double orient2d_underflow_bound = 0x1p-1073;
// The guards of the orient2d second stage (below), in the form of the other filters'.
inline constexpr double orient2d_lower_guard = 0x1p-480;
inline constexpr double orient2d_upper_guard = 0x1p+500;

// orient3d: |det| > bound * maxx * maxy * maxz.
// proofs/gappa/orient3d.g: E = 0x1.7000000000005p-48 (about 46.0 * 2^-53).
inline constexpr double orient3d_error_bound = 0x1.7000000000008p-48;  // 5.1070259132757264e-15
inline constexpr double orient3d_lower_guard = 0x1p-320;
inline constexpr double orient3d_upper_guard = 0x1p+330;

// incircle: |det| > bound * m^4, m the largest |difference| over both axes.
// proofs/gappa/incircle.g: E = 0x1.0000000000005p-46 (about 128.0 * 2^-53).
inline constexpr double incircle_error_bound = 0x1.0000000000008p-46;  // 1.4210854715202029e-14
inline constexpr double incircle_lower_guard = 0x1p-240;
inline constexpr double incircle_upper_guard = 0x1p+250;

// insphere: |det| > bound * m^5, m the largest |difference| over all three axes.
// proofs/gappa/insphere.g (with insphere_minors.g, insphere_lifts.g):
// E = 0x1.1400000000008p-43 (about 1104.0 * 2^-53).
inline constexpr double insphere_error_bound = 0x1.140000000000bp-43;  // 1.2256862191861756e-13
inline constexpr double insphere_lower_guard = 0x1p-190;
inline constexpr double insphere_upper_guard = 0x1p+200;

// Second stages of the exact predicates (predicates/src/orient2d.cpp, orient3d.cpp), tried
// before full expansion arithmetic. With rounded differences h and their exact tails t
// (h + t exact), E = det(h) in exact arithmetic plus the first-order tail correction
// evaluated in double; the sign of E is certified when |E| > bound * (product of the
// maxima of |h|, one per axis, evaluated in double left to right), the maxima inside the
// filter's guards, compared exactly. The proofs bound the rounding error of the correction
// plus the exact higher-order tail terms by E2 * (product of maxima); bound is
// E2 / (1 - 2^-53)^r rounded up as above, after adding 2^-1074 / lower_guard^degree to E2
// because the last rounding of the bound's computation can underflow at the lower guard
// (proofs/README.md, section 9).
// orient2d: proofs/gappa/orient2d_stage2.g: E2 = 0x1.c080000000001p-103 (about 14.0 * 2^-106).
inline constexpr double orient2d_stage2_bound = 0x1.c0a0000000003p-103;  // 1.728040642601448e-31
// orient3d: proofs/gappa/orient3d_stage2.g: E2 = 0x1.0812000000002p-99 (about 132.0 * 2^-106).
inline constexpr double orient3d_stage2_bound = 0x1.0814000000004p-99;  // 1.627507099504435e-30
// orient3d's compensated stage (orient3d.cpp, tried before the second stage): the pair
// (y, lo), det(h) in double-double plus the tails and the correction, is within E3 *
// (product of maxima) of the true determinant; the sign of est = fl(y + lo) is certified
// when |est| > bound * maxx * maxy * maxz. bound is (E3 + the underflow charge) / (1 -
// 2^-53)^4 rounded up: three roundings of the bound and the relative rounding of est
// (proofs/README.md, section 11).
// proofs/gappa/orient3d_compensated.g: E3 = 0x1.5906000000002p-97 (about 690 * 2^-106).
inline constexpr double orient3d_compensated_bound = 0x1.5906800000005p-97;  // 8.505532561645966e-30
// incircle's compensated stage (incircle.cpp, tried first in the exact stage): the same
// shape with one maximum m over both axes; the sign of est = fl(y + lo) is certified when
// |est| > bound * m2 * m2, m2 = fl(m * m). bound is (E3 + the underflow charge) / (1 -
// 2^-53)^5 rounded up: four roundings of the bound (m2 twice) and the relative rounding of
// est (proofs/README.md, section 12).
// proofs/gappa/incircle_compensated.g: E3 = 0x1.6981800000003p-95 (about 2892 * 2^-106).
inline constexpr double incircle_compensated_bound = 0x1.6981a00000007p-95;  // 3.5647278081906436e-29

}  // namespace certimesh::predicates::filter_constants
