// The constants of the semi-static filters, each proven by a Gappa script in proofs/gappa/.
//
// Every filter has the same shape (proofs/README.md gives the derivation):
//   1. the coordinate differences are rounded once each;
//   2. the determinant is evaluated in double in a fixed order, no FMA;
//   3. per axis, the largest rounded |difference| is taken (orient2d, orient3d), or one
//      largest over all axes (incircle, insphere, whose lifted column mixes the axes);
//   4. if those maxima lie inside [lower_guard, upper_guard] the computed determinant has
//      the exact sign whenever |det| > error_bound * (product of maxima, one per degree).
// The guards keep the scaling argument valid: below lower_guard an underflow could add an
// error the bound does not cover, above upper_guard a product could overflow.
//
// Values are hex-float literals rounded up. tests/proofs/constants_match_proofs checks
// that each one is the value its proof establishes; do not edit by hand.
#pragma once

namespace certimesh::predicates::filter_constants {

// orient2d: |det| > bound * maxx * maxy, maxx, maxy in [lower, upper].
inline constexpr double orient2d_error_bound = 0x1.0000000000001p-49;
inline constexpr double orient2d_lower_guard = 0x1p-480;
inline constexpr double orient2d_upper_guard = 0x1p+500;

// orient3d: |det| > bound * maxx * maxy * maxz.
inline constexpr double orient3d_error_bound = 0x1.0000000000001p-46;
inline constexpr double orient3d_lower_guard = 0x1p-320;
inline constexpr double orient3d_upper_guard = 0x1p+330;

// incircle: |det| > bound * m^4, m the largest |difference| over both axes.
inline constexpr double incircle_error_bound = 0x1.0000000000001p-43;
inline constexpr double incircle_lower_guard = 0x1p-240;
inline constexpr double incircle_upper_guard = 0x1p+250;

// insphere: |det| > bound * m^5, m the largest |difference| over all three axes.
inline constexpr double insphere_error_bound = 0x1.0000000000001p-40;
inline constexpr double insphere_lower_guard = 0x1p-190;
inline constexpr double insphere_upper_guard = 0x1p+200;

}  // namespace certimesh::predicates::filter_constants
