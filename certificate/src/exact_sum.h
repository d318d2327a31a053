// Internal: the exact sum of many products of two doubles, without a rational per term. Each
// double is m 2^e with an integer m < 2^53; the sum is kept as one integer in units of the
// smallest product exponent seen so far (shifted up when a smaller one arrives), so adding a
// term costs a 106-bit product and one shifted addition: linear in the terms, with no gcd.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <utility>

namespace certimesh::certificate::detail {

__extension__ typedef __int128 Int128;             // GCC and Clang: products of two 53-bit mantissas
__extension__ typedef unsigned __int128 UInt128;

/// m 2^e, exactly: what sums and products of doubles are.
struct Dyadic {
  mpz_class m = 0;
  long e = 0;
};
inline Dyadic operator*(const Dyadic& a, const Dyadic& b) { return {a.m * b.m, a.e + b.e}; }
inline Dyadic operator+(Dyadic a, Dyadic b) {
  if (a.m == 0) return b;
  if (b.m == 0) return a;
  if (a.e > b.e) std::swap(a, b);
  b.m <<= static_cast<mp_bitcnt_t>(b.e - a.e);
  return {a.m + b.m, a.e};
}
inline Dyadic abs(Dyadic a) {
  mpz_abs(a.m.get_mpz_t(), a.m.get_mpz_t());
  return a;
}
/// Also sums integers times powers of two (m 2^e), in the same units. Products of doubles whose
/// exponents lie within kReach bits of the first one are summed in a fixed 384-bit two's
/// complement integer (no allocation: the rounding-box tests and the chain measures sum a few
/// dozen such products per vertex); the first term outside that window, or an integer term,
/// moves the sum to GMP. Both paths are exact, and `sign`, `dyadic`, `value` read either.
class ExactProductSum {
 public:
  ExactProductSum() = default;
  // A copy touches GMP only when the sum has spilled there: copying a zero mpz_class allocates a
  // limb, and the rounding-box tests copy a partial sum per corner.
  ExactProductSum(const ExactProductSum& o)
      : small_(o.small_), acc_(o.acc_), small_base_(o.small_base_), count_(o.count_), base_(o.base_), empty_(o.empty_),
        spilled_(o.spilled_), unit_(o.unit_) {
    std::copy(o.limb_, o.limb_ + kLimbs, limb_);
    if (spilled_) sum_ = o.sum_;
  }
  ExactProductSum& operator=(const ExactProductSum& o) {
    if (this != &o) {
      ExactProductSum copy(o);
      *this = std::move(copy);
    }
    return *this;
  }
  ExactProductSum(ExactProductSum&&) noexcept = default;
  ExactProductSum& operator=(ExactProductSum&&) noexcept = default;
  ~ExactProductSum() = default;
  /// Adds factor * a * b exactly (a, b finite; factor -2 .. 2). The 128-bit path is inlined
  /// at every call (the rounding-box tests and chain bounds add a few dozen terms per vertex);
  /// the rest is one call.
  [[gnu::always_inline]] void add(double a, double b, int factor = 1) {
    if (a == 0 || b == 0 || factor == 0) return;
    long ea = 0, eb = 0;
    const std::int64_t ma = decompose(a, ea), mb = decompose(b, eb);  // a = ma 2^ea, |ma| < 2^53
    Int128 product = static_cast<Int128>(ma) * mb;                // |product| < 2^106
    product *= factor;  // |product| < 2^107
    if (small_) {  // up to 15 terms with exponents within 8 of the first: one 128-bit sum, below 2^127
      if (count_ == 0) small_base_ = ea + eb - 8;
      const long offset = ea + eb - small_base_;
      if (offset >= 0 && offset <= 16 && count_ < 15) {
        acc_ += static_cast<Int128>(static_cast<UInt128>(product) << offset);  // no signed shift
        ++count_;
        return;
      }
    }
    add_beyond_small(product, ea + eb);
  }
  /// Adds m * 2^exponent exactly.
  void add(const mpz_class& m, long exponent) {
    if (m == 0) return;
    spill();
    term_ = m;
    add_term(exponent);
  }
  /// The sum as m 2^e.
  Dyadic dyadic() const {
    settle();
    if (!spilled_) return empty_ ? Dyadic{} : Dyadic{fixed_value(), base_};
    return {sum_, unit_ == LONG_MAX ? 0 : unit_};
  }
  /// The sign of the sum: -1, 0 or +1.
  int sign() const {
    if (small_) return acc_ > 0 ? 1 : (acc_ < 0 ? -1 : 0);
    if (spilled_) return sgn(sum_);
    if (limb_[kLimbs - 1] >> 63) return -1;
    for (std::uint64_t w : limb_)
      if (w != 0) return 1;
    return 0;
  }
  /// |sum| as d 2^e with d in [0.5, 1) truncated to 53 bits (mpz_get_d_2exp's reading), and
  /// whether bits were cut; d = 0 for a zero sum.
  double magnitude_2exp(long& e, bool& cut) const {
    settle();
    e = 0, cut = false;
    if (spilled_) {
      if (sum_ == 0) return 0.0;
      const double d = std::fabs(mpz_get_d_2exp(&e, sum_.get_mpz_t()));
      cut = static_cast<long>(mpz_scan1(sum_.get_mpz_t(), 0)) < e - 53;
      e += unit_;
      return d;
    }
    std::uint64_t magnitude[kLimbs];
    magnitude_of(magnitude);
    int top = kLimbs - 1;
    while (top >= 0 && magnitude[top] == 0) --top;
    if (top < 0) return 0.0;
    const int zeros = std::countl_zero(magnitude[top]);
    const long bits = 64L * top + 64 - zeros;  // |sum| < 2^bits, bit bits - 1 set
    // The top 64 bits, left-aligned, and whether anything below them is non-zero.
    std::uint64_t high = magnitude[top] << zeros, rest = 0;
    if (top > 0) {
      high |= zeros == 0 ? 0 : magnitude[top - 1] >> (64 - zeros);
      rest = zeros == 0 ? magnitude[top - 1] : magnitude[top - 1] << zeros;
      for (int i = 0; i < top - 1; ++i) rest |= magnitude[i];
    }
    cut = (high & 0x7ff) != 0 || rest != 0;
    e = bits + base_;
    return std::ldexp(static_cast<double>(high >> 11), -53);  // 53 bits: exact
  }
  /// The sum, exactly.
  mpq_class value() const {
    const Dyadic d = dyadic();
    mpq_class q(d.m);
    if (d.e > 0) mpz_mul_2exp(q.get_num_mpz_t(), q.get_num_mpz_t(), static_cast<mp_bitcnt_t>(d.e));
    else if (d.e < 0) mpz_mul_2exp(q.get_den_mpz_t(), q.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-d.e));
    q.canonicalize();
    return q;
  }

 private:
  static constexpr int kLimbs = 6;     // 384 bits, two's complement
  static constexpr long kBelow = 96;   // bit 0 is 2^(first exponent - kBelow)
  static constexpr long kReach = 192;  // a term's lowest bit at 0 .. kReach: below 2^(107 + 192)
  // product 2^e outside the 128-bit stage: the fixed limbs, or GMP.
  [[gnu::noinline]] void add_beyond_small(Int128 product, long e) {
    settle();
    if (!spilled_ && add_fixed(product, e)) return;
    spill();
    term_ = mpz_of(product);
    add_term(e);
  }
  // A finite double as m 2^e with an integer |m| < 2^53, from its bits (IEEE binary64).
  static std::int64_t decompose(double a, long& e) {
    const auto bits = std::bit_cast<std::uint64_t>(a);
    const auto biased = static_cast<long>((bits >> 52) & 0x7ff);
    std::int64_t m = static_cast<std::int64_t>(bits & ((std::uint64_t{1} << 52) - 1));
    if (biased == 0) e = -1074;  // subnormal (or zero)
    else m |= std::int64_t{1} << 52, e = biased - 1075;
    return bits >> 63 ? -m : m;
  }
  static mpz_class mpz_of(Int128 x) {
    const bool negative = x < 0;
    const auto magnitude = static_cast<UInt128>(negative ? -x : x);
    const std::uint64_t words[2] = {static_cast<std::uint64_t>(magnitude), static_cast<std::uint64_t>(magnitude >> 64)};
    mpz_class z;
    mpz_import(z.get_mpz_t(), 2, -1, sizeof(std::uint64_t), 0, 0, words);
    if (negative) z = -z;
    return z;
  }
  // Adds x 2^e to the fixed sum when e is in its window; false (nothing added) when not. The
  // sum of fewer than 2^83 terms below 2^(107 + kReach) stays below 2^383 in magnitude.
  bool add_fixed(Int128 x, long e) {
    if (empty_) base_ = e - kBelow, empty_ = false;
    const long offset = e - base_;
    if (offset < 0 || offset > kReach) return false;
    const int q = static_cast<int>(offset / 64), r = static_cast<int>(offset % 64);
    const auto lo = static_cast<std::uint64_t>(x), hi = static_cast<std::uint64_t>(x >> 64);
    const std::uint64_t ext = x < 0 ? ~std::uint64_t{0} : 0;  // sign extension
    // x 2^r in three words, then ext above: added from limb q up, the limbs below unchanged.
    const std::uint64_t w[3] = {lo << r, r == 0 ? hi : (hi << r) | (lo >> (64 - r)), r == 0 ? ext : (ext << r) | (hi >> (64 - r))};
    std::uint64_t carry = 0;
    for (int i = q; i < kLimbs; ++i) {
      const UInt128 s = static_cast<UInt128>(limb_[i]) + (i - q < 3 ? w[i - q] : ext) + carry;
      limb_[i] = static_cast<std::uint64_t>(s);
      carry = static_cast<std::uint64_t>(s >> 64);
    }
    return true;
  }
  // |two's complement|: invert and add one when negative. Returns whether it was.
  bool magnitude_of(std::uint64_t* magnitude) const {
    const bool negative = limb_[kLimbs - 1] >> 63;
    unsigned carry = 1;
    for (int i = 0; i < kLimbs; ++i) {
      const UInt128 s = static_cast<UInt128>(negative ? ~limb_[i] : limb_[i]) + (negative ? carry : 0);
      magnitude[i] = static_cast<std::uint64_t>(s);
      carry = static_cast<unsigned>(s >> 64);
    }
    return negative;
  }
  mpz_class fixed_value() const {
    std::uint64_t magnitude[kLimbs];
    const bool negative = magnitude_of(magnitude);
    mpz_class z;
    mpz_import(z.get_mpz_t(), kLimbs, -1, sizeof(std::uint64_t), 0, 0, magnitude);
    if (negative) z = -z;
    return z;
  }
  // The 128-bit sum of the first terms into the limbs (at offset kBelow - 8 = 88: the first
  // term's exponent is small_base_ + 8), after which terms go to the limbs directly.
  void settle() const {
    if (!small_) return;
    small_ = false;
    if (count_ == 0) return;
    base_ = small_base_ + 8 - kBelow, empty_ = false;
    const_cast<ExactProductSum*>(this)->add_fixed(acc_, small_base_);  // offset 88: always in the window
  }
  void spill() {
    settle();
    if (spilled_) return;
    spilled_ = true;
    if (empty_) return;
    sum_ = fixed_value();
    unit_ = base_;
  }
  void add_term(long exponent) {
    if (exponent < unit_) {
      if (unit_ != LONG_MAX) sum_ <<= static_cast<mp_bitcnt_t>(unit_ - exponent);
      unit_ = exponent;
    }
    if (exponent > unit_) term_ <<= static_cast<mp_bitcnt_t>(exponent - unit_);
    sum_ += term_;
  }

  // The first terms are summed in acc_ (small_), then moved to the limbs by settle(), which a
  // reader may call: these members are mutable, the sum they hold does not change.
  mutable bool small_ = true;
  Int128 acc_ = 0;
  long small_base_ = 0;
  int count_ = 0;
  mutable std::uint64_t limb_[kLimbs] = {};
  mutable long base_ = 0;
  mutable bool empty_ = true;
  bool spilled_ = false;
  mpz_class sum_, term_;  // zero; default-constructed, they allocate nothing until a spill writes them
  long unit_ = LONG_MAX;  // the spilled sum is sum_ * 2^unit_
};

/// (b - a) x (p - a), exactly (2D points: x, y).
inline ExactProductSum cross_from(const double* a, const double* b, const double* p) {
  ExactProductSum s;
  s.add(b[0], p[1]), s.add(b[0], a[1], -1), s.add(a[0], p[1], -1);
  s.add(b[1], p[0], -1), s.add(b[1], a[0]), s.add(a[1], p[0]);
  return s;
}
/// (q - p) . (b - a), exactly (2D).
inline ExactProductSum dot_of_differences(const double* p, const double* q, const double* a, const double* b) {
  ExactProductSum s;
  for (int k = 0; k < 2; ++k) s.add(q[k], b[k]), s.add(q[k], a[k], -1), s.add(p[k], b[k], -1), s.add(p[k], a[k]);
  return s;
}

/// The nearest double to |a| / sqrt(b), b > 0, with no overflow or underflow on the way (a
/// statistic: mantissas truncated to 53 bits, the exponents apart).
/// b given as b.magnitude_2exp reads it (mb, eb): for many a over one b.
inline double ratio_to_root(const ExactProductSum& a, double mb, long eb) {
  long ea = 0;
  bool cut = false;
  const double ma = a.magnitude_2exp(ea, cut);
  if (ma == 0) return 0.0;
  if (eb % 2 != 0) mb *= 2, eb -= 1;
  return std::ldexp(ma / std::sqrt(mb), static_cast<int>(ea - eb / 2));
}
inline double ratio_to_root(const ExactProductSum& a, const ExactProductSum& b) {
  long eb = 0;
  bool cut = false;
  const double mb = b.magnitude_2exp(eb, cut);
  return ratio_to_root(a, mb, eb);
}

/// |sum| rounded outward to doubles, lo <= |sum| <= hi, when |sum| is 0 or within
/// [2^-480, 2^480] (so products and sums of such bounds stay normal doubles); false otherwise.
inline bool magnitude_bounds(const ExactProductSum& s, double& lo, double& hi) {
  long e = 0;
  bool cut = false;
  const double d = s.magnitude_2exp(e, cut);
  if (d == 0) return lo = hi = 0, true;
  if (e < -479 || e > 480) return false;
  lo = std::ldexp(d, static_cast<int>(e));  // exact: 53 bits, normal
  hi = cut ? std::nextafter(lo, INFINITY) : lo;
  return true;
}

}  // namespace certimesh::certificate::detail
