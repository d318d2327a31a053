// Out-of-line entry points of the kernel: the exact stages (run when a filter is
// uncertain), the symbolic perturbation, and the filters compiled inside the kernel for
// translation units that cannot inline them safely (detail/fp_requirements.h).
#pragma once

#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"

namespace certimesh::predicates::detail {

// Exact sign without a filter in front: expansions when the input's exponent range
// allows it, GMP integers otherwise. Throw NonFiniteInput on NaN or infinity.
Sign orient2d_exact_stage(const Point2& a, const Point2& b, const Point2& c);
Sign orient3d_exact_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d);
Sign incircle_exact_stage(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
Sign insphere_exact_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                          const Point3& e);

// The filters, compiled with the kernel's floating-point flags.
FilteredSign orient2d_filter_out_of_line(const Point2& a, const Point2& b, const Point2& c) noexcept;
FilteredSign orient3d_filter_out_of_line(const Point3& a, const Point3& b, const Point3& c,
                                         const Point3& d) noexcept;
FilteredSign incircle_filter_out_of_line(const Point2& a, const Point2& b, const Point2& c,
                                         const Point2& d) noexcept;
FilteredSign insphere_filter_out_of_line(const Point3& a, const Point3& b, const Point3& c,
                                         const Point3& d, const Point3& e) noexcept;

}  // namespace certimesh::predicates::detail
