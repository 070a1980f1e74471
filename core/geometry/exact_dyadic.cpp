#include "core/geometry/exact_dyadic.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

static_assert(std::numeric_limits<double>::is_iec559, "IEEE-754 doubles required");

namespace tecido {
namespace {

using u128 = unsigned __int128;

/// floor(e / 64) for any sign of e.
int floor_div64(int e) { return e >= 0 ? e / 64 : -((-e + 63) / 64); }

void check_width(int width) {
  if (width > Dyadic::kMaxLimbs) throw std::length_error("Dyadic: value wider than kMaxLimbs limbs");
}

}  // namespace

Dyadic::Dyadic(double x) {
  if (!std::isfinite(x)) throw std::domain_error("Dyadic: NaN or infinite double");
  if (x == 0.0) return;
  // |x| = m 2^e with m < 2^53 an integer, read from the bit pattern (IEEE-754 binary64).
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t frac = bits & ((1ULL << 52) - 1);
  const std::uint64_t m = biased == 0 ? frac : (frac | (1ULL << 52));  // subnormal: no hidden bit
  const int e = (biased == 0 ? 1 : biased) - 1075;                      // in [-1074, 971]
  const int q = floor_div64(e), r = e - 64 * q;
  w_[0] = m << r;
  w_[1] = r == 0 ? 0 : m >> (64 - r);
  n_ = 2;
  base_ = q;
  neg_ = x < 0.0;
  normalise();
}

Dyadic& Dyadic::operator=(const Dyadic& o) {
  if (this != &o) {
    std::copy(o.w_, o.w_ + o.n_, w_);
    n_ = o.n_;
    base_ = o.base_;
    neg_ = o.neg_;
  }
  return *this;
}

void Dyadic::normalise() {
  while (n_ > 0 && w_[n_ - 1] == 0) --n_;
  int lo = 0;
  while (lo < n_ && w_[lo] == 0) ++lo;
  if (lo > 0) {
    std::copy(w_ + lo, w_ + n_, w_);
    n_ -= lo;
    base_ += lo;
  }
  if (n_ == 0) {
    base_ = 0;
    neg_ = false;
  }
}

Dyadic Dyadic::operator-() const {
  Dyadic r = *this;
  if (r.n_ != 0) r.neg_ = !r.neg_;
  return r;
}

Dyadic Dyadic::abs() const {
  Dyadic r = *this;
  r.neg_ = false;
  return r;
}

Dyadic Dyadic::times_sign(int s) const {
  if (s == 0) return Dyadic();
  return s > 0 ? *this : -*this;
}

double Dyadic::approx_mantissa(long* exp2) const {
  if (n_ == 0) {
    *exp2 = 0;
    return 0.0;
  }
  double m = static_cast<double>(w_[n_ - 1]);
  if (n_ >= 2) m += std::ldexp(static_cast<double>(w_[n_ - 2]), -64);
  *exp2 = 64L * (base_ + n_ - 1);
  return neg_ ? -m : m;
}

int Dyadic::compare_magnitudes(const Dyadic& x, const Dyadic& y) {
  const int tx = x.base_ + x.n_, ty = y.base_ + y.n_;  // one past the highest (nonzero) limb
  if (tx != ty) return tx > ty ? 1 : -1;
  for (int i = tx - 1; i >= std::min(x.base_, y.base_); --i) {
    const int jx = i - x.base_, jy = i - y.base_;
    const std::uint64_t a = jx >= 0 ? x.w_[jx] : 0, b = jy >= 0 ? y.w_[jy] : 0;
    if (a != b) return a > b ? 1 : -1;
  }
  return 0;
}

Dyadic Dyadic::add_signed(const Dyadic& x, const Dyadic& y, bool negate_y) {
  const bool yneg = (y.neg_ != negate_y);
  if (y.n_ == 0) return x;
  if (x.n_ == 0) {
    Dyadic r = y;
    r.neg_ = yneg;
    return r;
  }
  const bool same_sign = x.neg_ == yneg;
  const int cmp = compare_magnitudes(x, y);
  if (!same_sign && cmp == 0) return Dyadic();
  // |result| = |big| + |small| or |big| - |small|: big's limbs laid out at their place, then
  // small's added or subtracted in place, the carry or borrow running upwards (Knuth's
  // algorithms A and S).
  const Dyadic& big = cmp >= 0 ? x : y;
  const Dyadic& small = cmp >= 0 ? y : x;
  const int lo = std::min(x.base_, y.base_);
  const int width = std::max(x.base_ + x.n_, y.base_ + y.n_) - lo + 1;  // + 1 for a carry
  check_width(width);
  Dyadic r;
  r.base_ = lo;
  r.n_ = width;
  std::fill(r.w_, r.w_ + width, 0);
  std::copy(big.w_, big.w_ + big.n_, r.w_ + (big.base_ - lo));
  std::uint64_t* w = r.w_ + (small.base_ - lo);
  const int room = width - (small.base_ - lo);
  std::uint64_t c = 0;  // carry or borrow
  for (int i = 0; i < room && (i < small.n_ || c != 0); ++i) {
    const u128 v = static_cast<u128>(i < small.n_ ? small.w_[i] : 0) + c;
    if (same_sign) {
      const u128 t = w[i] + v;
      w[i] = static_cast<std::uint64_t>(t);
      c = static_cast<std::uint64_t>(t >> 64);
    } else {
      c = static_cast<u128>(w[i]) < v ? 1 : 0;
      w[i] = static_cast<std::uint64_t>(w[i] - v);
    }
  }
  r.neg_ = same_sign ? x.neg_ : (cmp > 0 ? x.neg_ : yneg);
  r.normalise();
  return r;
}

Dyadic operator+(const Dyadic& x, const Dyadic& y) { return Dyadic::add_signed(x, y, false); }
Dyadic operator-(const Dyadic& x, const Dyadic& y) { return Dyadic::add_signed(x, y, true); }

Dyadic operator*(const Dyadic& x, const Dyadic& y) {
  if (x.n_ == 0 || y.n_ == 0) return Dyadic();
  const int width = x.n_ + y.n_;
  check_width(width);
  Dyadic r;
  std::fill(r.w_, r.w_ + width, 0);
  for (int i = 0; i < x.n_; ++i) {  // schoolbook product (Knuth's algorithm M)
    std::uint64_t carry = 0;
    for (int j = 0; j < y.n_; ++j) {
      const u128 t = static_cast<u128>(x.w_[i]) * y.w_[j] + r.w_[i + j] + carry;
      r.w_[i + j] = static_cast<std::uint64_t>(t);
      carry = static_cast<std::uint64_t>(t >> 64);
    }
    r.w_[i + y.n_] = carry;
  }
  r.n_ = width;
  r.base_ = x.base_ + y.base_;
  r.neg_ = x.neg_ != y.neg_;
  r.normalise();
  return r;
}

}  // namespace tecido
