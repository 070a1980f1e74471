#pragma once
// Shared by the geometric fuzz targets (fuzz_tritri_vs_exact, fuzz_ccd_vs_exact,
// fuzz_plane_vs_exact, fuzz_selfcollide_continuous): the fuzzer's bytes read as coordinates
// so that degenerate, touching and coplanar inputs are common, not of measure zero.
// Each coordinate is a mode byte m then a payload chosen by m % 8:
//   0  raw double, 8 bytes little-endian
//   1  small integer -4..4, 1 byte
//   2  dyadic n / 2^k, n in -128..127, k in 0..10, 2 bytes
//   3  a copy of an earlier coordinate, 1 byte (index mod count so far)
//   4  an earlier coordinate moved by -4..3 ulps, 2 bytes
//   5  n * 2^e, n in -128..127, e in -1100..1031 (subnormals to near overflow), 3 bytes
//   6  small integer plus a tiny dyadic offset n * 2^-(10..69), 3 bytes
//   7  +0 or -0, 1 byte
// Missing bytes read as 0. A payload may decode to NaN or Inf; the targets skip such inputs.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace tecido::fuzz {

/// The fuzzer's bytes, read front to back; past the end every byte is 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t u8() { return i_ < n_ ? d_[i_++] : 0; }
  std::int8_t s8() { return static_cast<std::int8_t>(u8()); }
  std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | (u8() << 8)); }
  double raw() {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= static_cast<std::uint64_t>(u8()) << (8 * k);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
  bool done() const { return i_ >= n_; }

 private:
  const std::uint8_t* d_;
  std::size_t n_, i_ = 0;
};

/// One coordinate in the layout above; `earlier` holds the `count` coordinates decoded so far.
inline double decode_coordinate(Bytes& in, const double* earlier, int count) {
  const std::uint8_t mode = in.u8();
  switch (mode % 8) {
    case 0: return in.raw();
    case 1: return static_cast<double>(in.u8() % 9) - 4.0;
    case 2: {
      const int n = in.s8();
      return std::ldexp(static_cast<double>(n), -(in.u8() % 11));
    }
    case 3: {
      const std::uint8_t k = in.u8();
      return count > 0 ? earlier[k % count] : 0.0;
    }
    case 4: {
      const std::uint8_t k = in.u8();
      const int steps = in.s8() / 32;  // -4..3
      double x = count > 0 ? earlier[k % count] : 0.0;
      for (int s = 0; s < (steps < 0 ? -steps : steps); ++s) x = std::nextafter(x, steps < 0 ? -INFINITY : INFINITY);
      return x;
    }
    case 5: {
      const int n = in.s8();
      const int e = static_cast<int>(in.u16() % 2132) - 1100;
      return std::ldexp(static_cast<double>(n), e);
    }
    case 6: {
      const double base = static_cast<double>(in.u8() % 9) - 4.0;
      const int n = in.s8();
      return base + std::ldexp(static_cast<double>(n), -(10 + in.u8() % 60));
    }
    default: return (in.u8() & 1) ? -0.0 : 0.0;
  }
}

/// Decodes n coordinates into c[0..n).
inline void decode_coordinates(Bytes& in, double* c, int n) {
  for (int k = 0; k < n; ++k) c[k] = decode_coordinate(in, c, k);
}

/// Binary exponents (std::ilogb) of the smallest and largest nonzero |x| among c[0..n); both 0
/// when all are zero. Their difference bounds the size of the integers an exact referee works
/// with once the input is scaled to integers (its cost grows with it).
inline int exponent_spread(const double* c, int n) {
  int lo = 0, hi = 0;
  bool any = false;
  for (int k = 0; k < n; ++k) {
    if (c[k] == 0.0) continue;
    const int e = std::ilogb(c[k]);
    lo = any && lo < e ? lo : e;
    hi = any && hi > e ? hi : e;
    any = true;
  }
  return hi - lo;
}

}  // namespace tecido::fuzz
