#pragma once
/// Exact dyadic numbers: sums, differences and products of doubles, without rounding, for any
/// finite inputs (no overflow, no underflow), with an exact sign.
///
/// Every finite double is an integer times a power of two (m 2^e, |m| < 2^53, e >= -1074), so
/// every polynomial with integer coefficients in doubles is one too. A Dyadic stores that value
/// as a sign and a magnitude sum_i w[i] 2^(64 (base + i)): unsigned 64-bit limbs whose exponent
/// is a multiple of 64, so aligning two numbers for a sum moves whole limbs and never shifts
/// bits. Only the limbs between the lowest and the highest nonzero one are stored, so numbers
/// of similar magnitude stay a few limbs long and cost a few integer operations each; widely
/// spread ones (1e-300 + 1e300) grow as needed. Arbitrary-precision integer arithmetic on
/// limbs, schoolbook product (Knuth, TAOCP vol. 2, section 4.3.1, algorithms A, S and M).
///
/// Capacity: kMaxLimbs limbs of storage, enough for the value of any polynomial of total
/// degree <= 6 in doubles with up to 2^16 monomials, and for every partial result on the way
/// to it: its nonzero bits lie between 2^(-6 * 1074) and 2^(6 * 1024 + 16), limbs -103 to 97
/// at most, 201 limbs, and a sum or a product before trimming needs at most one limb more.
/// Exceeding it throws std::length_error; it cannot happen within that degree. NaN and infinity
/// are rejected by the constructor (std::domain_error).
#include <cstdint>

namespace tecido {

class Dyadic {
 public:
  static constexpr int kMaxLimbs = 208;

  /// Zero.
  Dyadic() = default;
  /// The exact value of the finite double x. Throws std::domain_error for NaN or infinity.
  explicit Dyadic(double x);
  Dyadic(const Dyadic& o) { *this = o; }
  Dyadic& operator=(const Dyadic& o);

  /// -1, 0 or +1: the exact sign.
  int sign() const { return n_ == 0 ? 0 : (neg_ ? -1 : 1); }
  Dyadic operator-() const;
  /// The absolute value.
  Dyadic abs() const;
  /// The value times s, for s = -1, 0 or +1 (a sign, as returned by sign()).
  Dyadic times_sign(int s) const;

  /// An approximation m 2^e of the value with m in [1, 2^64) (or 0 for zero), m correct to
  /// about 2^-53 relative; e may lie far outside the range of double. For ratios of values
  /// whose quotient is a double even when the values are not.
  double approx_mantissa(long* exp2) const;

  friend Dyadic operator+(const Dyadic& x, const Dyadic& y);
  friend Dyadic operator-(const Dyadic& x, const Dyadic& y);
  friend Dyadic operator*(const Dyadic& x, const Dyadic& y);

  /// Number of stored limbs (0 for zero); for tests of the capacity bound.
  int limbs() const { return n_; }

 private:
  static Dyadic add_signed(const Dyadic& x, const Dyadic& y, bool negate_y);
  /// Sign of |x| - |y|.
  static int compare_magnitudes(const Dyadic& x, const Dyadic& y);
  void normalise();

  std::uint64_t w_[kMaxLimbs];  ///< w_[0 .. n_) are meaningful; w_[0] and w_[n_ - 1] nonzero
  int n_ = 0;                   ///< number of limbs; 0 means the value zero
  int base_ = 0;                ///< the limb w_[i] weighs 2^(64 (base_ + i))
  bool neg_ = false;
};

/// Sign of x - y, exactly.
inline int compare(const Dyadic& x, const Dyadic& y) { return (x - y).sign(); }

}  // namespace tecido
