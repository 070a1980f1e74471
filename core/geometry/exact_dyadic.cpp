#include "core/geometry/exact_dyadic.h"

#include <algorithm>
#include <cmath>
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
  // |x| = m 2^e with m < 2^53 an integer (subnormals included: frexp normalises them).
  int k = 0;
  const double f = std::frexp(std::fabs(x), &k);
  const std::uint64_t m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  const int e = k - 53;  // in [-1126, 971]
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

Dyadic Dyadic::add_signed(const Dyadic& x, const Dyadic& y, bool negate_y) {
  const bool yneg = (y.neg_ != negate_y);
  if (y.n_ == 0) return x;
  if (x.n_ == 0) {
    Dyadic r = y;
    r.neg_ = yneg;
    return r;
  }
  const int lo = std::min(x.base_, y.base_);
  const int top = std::max(x.base_ + x.n_, y.base_ + y.n_);  // one past the highest limb
  const int width = top - lo + 1;                            // + 1 for a carry
  check_width(width);
  // The limb of v at absolute index lo + i (0 outside v's stored limbs).
  auto limb = [lo](const Dyadic& v, int i) -> std::uint64_t {
    const int j = lo + i - v.base_;
    return (j >= 0 && j < v.n_) ? v.w_[j] : 0;
  };
  Dyadic r;
  r.base_ = lo;
  r.n_ = width;
  if (x.neg_ == yneg) {  // same signs: add the magnitudes (Knuth's algorithm A)
    std::uint64_t carry = 0;
    for (int i = 0; i + 1 < width; ++i) {
      const u128 s = static_cast<u128>(limb(x, i)) + limb(y, i) + carry;
      r.w_[i] = static_cast<std::uint64_t>(s);
      carry = static_cast<std::uint64_t>(s >> 64);
    }
    r.w_[width - 1] = carry;
    r.neg_ = x.neg_;
  } else {  // opposite signs: subtract the smaller magnitude from the larger (algorithm S)
    int cmp = 0;
    for (int i = width - 2; i >= 0 && cmp == 0; --i) {
      const std::uint64_t a = limb(x, i), b = limb(y, i);
      cmp = (a > b) - (a < b);
    }
    if (cmp == 0) return Dyadic();
    const Dyadic& big = cmp > 0 ? x : y;
    const Dyadic& small = cmp > 0 ? y : x;
    std::uint64_t borrow = 0;
    for (int i = 0; i + 1 < width; ++i) {
      const std::uint64_t a = limb(big, i), b = limb(small, i);
      const u128 sub = static_cast<u128>(b) + borrow;
      r.w_[i] = a - static_cast<std::uint64_t>(sub);
      borrow = static_cast<u128>(a) < sub ? 1 : 0;
    }
    r.w_[width - 1] = 0;
    r.neg_ = cmp > 0 ? x.neg_ : yneg;
  }
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
