// libFuzzer target: the core triangle-triangle test (tecido::tri_tri_intersect) must give the
// exact referee's answer (tecido::reference::exact_tri_tri, CGAL) on every finite input, and
// must not depend on the order of the triangles or of their vertices. A disagreement prints
// the 18 coordinates (hex floats, exact) and traps.
//
// Input layout (so that degenerate, touching and coplanar pairs are common, not measure zero):
//   byte 0: structure flags, applied after the 18 coordinates are decoded (see apply_flags)
//   then 18 coordinates a0.x a0.y a0.z a1.x ... b2.z, each as fuzz_coordinates.h reads them
//   (raw doubles, small integers, dyadics, copies, ulp nudges, extreme exponents, signed zeros)
//   then up to 3 bytes of parameters for the flags. Missing bytes read as 0.
// Non-finite inputs (a payload may decode to NaN or Inf) are skipped: the contract is for finite ones.
#include "fuzz_coordinates.h"

#include "core/geometry/tri_tri_intersect.h"
#include "reference/exact_referee.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>

namespace {

using tecido::Triangle;
using tecido::Vec3;

using tecido::fuzz::Bytes;

/// Structure flags: bit 0 b0 = a0 (shared vertex); bit 1 b1 = a1 (with bit 0: shared edge);
/// bit 2 every z = a0.z (coplanar, axis-aligned plane); bit 3 b2 = a0 + s(a1-a0) + t(a2-a0)
/// and bit 5 the same for b1 (coplanar with a, exactly so for small integer inputs); bit 4 b0
/// on the edge a0a1 at w/256; bit 6 a degenerate: a2 = 2 a1 - a0 (collinear) or a2 = a1;
/// bit 7 scale all by 2^e, e in -600..599 (exact unless it under- or overflows).
void apply_flags(std::uint8_t flags, Bytes& in, Triangle& a, Triangle& b) {
  const std::uint8_t p0 = in.u8(), p1 = in.u8(), p2 = in.u8();
  auto in_plane = [&](std::uint8_t p) {
    const double s = (p & 15) / 8.0 - 0.5, t = (p >> 4) / 8.0 - 0.5;
    return Vec3(a[0] + s * (a[1] - a[0]) + t * (a[2] - a[0]));
  };
  if (flags & 64) a[2] = (p2 & 1) ? Vec3(2.0 * a[1] - a[0]) : a[1];
  if (flags & 1) b[0] = a[0];
  if (flags & 2) b[1] = a[1];
  if (flags & 16) b[0] = a[0] + (p0 / 256.0) * (a[1] - a[0]);
  if (flags & 8) b[2] = in_plane(p1);
  if (flags & 32) b[1] = in_plane(static_cast<std::uint8_t>(p1 * 7 + 3));
  if (flags & 4)
    for (Triangle* t : {&a, &b})
      for (Vec3& v : *t) v.z() = a[0].z();
  if (flags & 128) {
    const int e = static_cast<int>(p2 % 200) * 6 - 600;
    for (Triangle* t : {&a, &b})
      for (Vec3& v : *t) v = Vec3(std::ldexp(v.x(), e), std::ldexp(v.y(), e), std::ldexp(v.z(), e));
  }
}

bool finite(const Triangle& t) { return t[0].allFinite() && t[1].allFinite() && t[2].allFinite(); }

[[noreturn]] void report(const char* what, const Triangle& a, const Triangle& b, bool exact, bool core) {
  std::fprintf(stderr, "\nfuzz_tritri_vs_exact: FINDING: %s: exact %d, core %d\n", what, exact, core);
  const char* names[] = {"a0", "a1", "a2", "b0", "b1", "b2"};
  for (int k = 0; k < 6; ++k) {
    const Vec3& v = k < 3 ? a[k] : b[k - 3];
    std::fprintf(stderr, "  %s = [%a, %a, %a]  (%.17g, %.17g, %.17g)\n", names[k], v.x(), v.y(), v.z(), v.x(), v.y(), v.z());
  }
  std::fflush(stderr);
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::uint8_t flags = in.u8();
  double c[18];
  tecido::fuzz::decode_coordinates(in, c, 18);
  Triangle a, b;
  for (int k = 0; k < 3; ++k) {
    a[k] = Vec3(c[3 * k], c[3 * k + 1], c[3 * k + 2]);
    b[k] = Vec3(c[9 + 3 * k], c[9 + 3 * k + 1], c[9 + 3 * k + 2]);
  }
  apply_flags(flags, in, a, b);
  if (!finite(a) || !finite(b)) return 0;

  bool exact = false;
  try {
    exact = tecido::reference::exact_tri_tri(a, b);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exact_tri_tri threw on finite input: %s\n", e.what());
    report("the referee threw", a, b, false, false);
  }
  const bool core = tecido::tri_tri_intersect(a, b);
  if (core != exact) report("core(a, b) != exact(a, b)", a, b, exact, core);
  if (tecido::tri_tri_intersect(b, a) != exact) report("core(b, a) != exact(a, b)", a, b, exact, !core);
  // Rotate a's vertices and reverse b's orientation.
  const Triangle ra{a[1], a[2], a[0]}, rb{b[2], b[1], b[0]};
  if (tecido::tri_tri_intersect(ra, rb) != exact) report("core(rotated a, reversed b) != exact(a, b)", a, b, exact, !core);
  return 0;
}
