// Exact integer determinants for inputs whose exponent range defeats expansion arithmetic,
// and for the minors of the symbolic perturbation (private to the kernel; GMP lives only in
// integer_matrix.cpp).
//
// Every finite double is m * 2^e with an integer m of at most 53 bits. Scaling all
// coordinates by 2^-emin (emin the least exponent among them) turns them into integers of
// at most ~2150 bits without changing the sign of any determinant below: each column is
// scaled by a positive constant (the lifted column by 2^-2emin).
#pragma once

#include <memory>
#include <span>

#include "certimesh/predicates/sign.h"

namespace certimesh::predicates::detail {

class IntegerMatrix {
 public:
  /// Rows: the points; columns: the coordinates, then |p|^2 if `lifted`, then 1.
  IntegerMatrix(std::span<const double> coordinates, int dim, bool lifted);
  ~IntegerMatrix();
  IntegerMatrix(const IntegerMatrix&) = delete;
  IntegerMatrix& operator=(const IntegerMatrix&) = delete;

  int size() const noexcept { return size_; }
  /// Sign of the minor keeping the rows and columns whose bits are set.
  Sign minor_sign(unsigned row_mask, unsigned column_mask) const;
  Sign determinant_sign() const { return minor_sign((1u << size_) - 1, (1u << size_) - 1); }

 private:
  struct Entries;
  int size_;
  std::unique_ptr<Entries> entries_;
};

/// Sign of the (lifted) determinant of the points, in exact integer arithmetic.
inline Sign integer_determinant_sign(std::span<const double> coordinates, int dim, bool lifted) {
  return IntegerMatrix(coordinates, dim, lifted).determinant_sign();
}

}  // namespace certimesh::predicates::detail
