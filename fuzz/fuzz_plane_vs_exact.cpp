// libFuzzer target: core's segment versus bounded plane decision (tecido::segment_plane,
// core/geometry/segment_plane.h) against the exact referee (exact_segment_plane, GMP rationals).
// Core claims its `hit` is exact for every finite input (the plane suite checks 1.0 agreement):
// a different hit from the referee's is a finding, so is a disagreement between core's filtered
// path and its unfiltered exact path (detail::segment_plane_exact), and a hit whose t lies
// outside [0, 1]. The stored plane is used as given: normal and forward need not be unit or
// orthogonal. A negative half extent (which the readers reject) is an empty rectangle for core and
// for the referee alike: both must say miss (regress_negative_half_extent: this target found the
// referee's clip() taking [-h, h] with h < 0 as the non-empty [h, -h]; fixed in exact_referee.cpp).
//
// Input layout: byte 0 structure flags (see apply_flags), then 17 coordinates as
// fuzz_coordinates.h reads them: position xyz, normal xyz, forward xyz, half extents x y,
// p1 xyz, p2 xyz; then up to 3 parameter bytes. Non-finite inputs are skipped (core answers
// miss by contract, the referee refuses them), and so are inputs whose nonzero coordinates span
// more than kMaxExponentSpread binary orders of magnitude (the referee's rationals grow with it).
#include "fuzz_coordinates.h"

#include "core/geometry/segment_plane.h"
#include "reference/exact_referee.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

namespace {

using tecido::BoundedPlane;
using tecido::Vec2;
using tecido::Vec3;
using tecido::fuzz::Bytes;

constexpr const char* kTarget = "fuzz_plane_vs_exact";
constexpr int kMaxExponentSpread = 1200;

void print_vec(const char* name, const double* v, int n) {
  std::fprintf(stderr, "  %s = [", name);
  for (int k = 0; k < n; ++k) std::fprintf(stderr, "%s%a", k ? ", " : "", v[k]);
  std::fprintf(stderr, "]\n");
}

[[noreturn]] void report(const std::string& what, const BoundedPlane& p, const Vec3& p1, const Vec3& p2) {
  std::fprintf(stderr, "\n%s: FINDING: %s\n", kTarget, what.c_str());
  print_vec("position", p.position.data(), 3);
  print_vec("normal", p.normal.data(), 3);
  print_vec("forward", p.forward.data(), 3);
  print_vec("half_extents", p.half_extents.data(), 2);
  print_vec("p1", p1.data(), 3);
  print_vec("p2", p2.data(), 3);
  std::fflush(stderr);
  __builtin_trap();
}

/// Structure flags: bit 0 axis-aligned plane (normal +-z, forward +-x); bit 1 p1 on the plane
/// (p1 = position + s forward + t right, s, t from a parameter, on the border for some); bit 2
/// p2 on the plane likewise; bit 3 p2 = p1 (a point); bit 4 p2 = 2 p1 - p2's mirror through the
/// plane (p2 = p1 - 2 s(p1) n: crossing); bit 5 half extents equal to |forward.(p1 - P)| (a
/// crossing on the border for planar p1); bit 6 position = 0; bit 7 scale every length by 2^e.
void apply_flags(std::uint8_t f, Bytes& in, BoundedPlane& pl, Vec3& p1, Vec3& p2) {
  const std::uint8_t a = in.u8(), b = in.u8(), e = in.u8();
  if (f & 1) {
    pl.normal = Vec3(0, 0, (a & 1) ? -1.0 : 1.0);
    pl.forward = Vec3((a & 2) ? -1.0 : 1.0, 0, 0);
  }
  if (f & 64) pl.position = Vec3::Zero();
  auto on_plane = [&](std::uint8_t p) {
    const double s = ((p & 15) - 8) / 8.0 * pl.half_extents.x(), t = ((p >> 4) - 8) / 8.0 * pl.half_extents.y();
    return Vec3(pl.position + s * pl.forward + t * pl.right());
  };
  if (f & 2) p1 = on_plane(a);
  if (f & 4) p2 = on_plane(b);
  if (f & 8) p2 = p1;
  if (f & 16) p2 = p1 - 2.0 * pl.side(p1) * pl.normal;
  if (f & 32) pl.half_extents.x() = std::abs(pl.forward.dot(p1 - pl.position));
  if (f & 128) {
    const int k = static_cast<int>(e % 200) * 6 - 600;
    pl.position = Vec3(std::ldexp(pl.position.x(), k), std::ldexp(pl.position.y(), k), std::ldexp(pl.position.z(), k));
    pl.half_extents = Vec2(std::ldexp(pl.half_extents.x(), k), std::ldexp(pl.half_extents.y(), k));
    for (Vec3* p : {&p1, &p2}) *p = Vec3(std::ldexp(p->x(), k), std::ldexp(p->y(), k), std::ldexp(p->z(), k));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::uint8_t flags = in.u8();
  double c[17];
  tecido::fuzz::decode_coordinates(in, c, 17);
  BoundedPlane pl;
  pl.position = Vec3(c[0], c[1], c[2]);
  pl.normal = Vec3(c[3], c[4], c[5]);
  pl.forward = Vec3(c[6], c[7], c[8]);
  pl.half_extents = Vec2(c[9], c[10]);
  Vec3 p1(c[11], c[12], c[13]), p2(c[14], c[15], c[16]);
  apply_flags(flags, in, pl, p1, p2);
  if (!pl.position.allFinite() || !pl.normal.allFinite() || !pl.forward.allFinite() || !pl.half_extents.allFinite() ||
      !p1.allFinite() || !p2.allFinite())
    return 0;
  const double all[17] = {pl.position.x(), pl.position.y(), pl.position.z(), pl.normal.x(), pl.normal.y(), pl.normal.z(),
                          pl.forward.x(), pl.forward.y(), pl.forward.z(), pl.half_extents.x(), pl.half_extents.y(),
                          p1.x(), p1.y(), p1.z(), p2.x(), p2.y(), p2.z()};
  if (tecido::fuzz::exponent_spread(all, 17) > kMaxExponentSpread) return 0;

  const tecido::SegmentPlaneHit core = tecido::segment_plane(pl, p1, p2);
  if ((pl.half_extents.x() < 0.0 || pl.half_extents.y() < 0.0) && core.hit)
    report("core hits a rectangle with a negative half extent (documented: no hit)", pl, p1, p2);
  const tecido::SegmentPlaneHit unfiltered = tecido::detail::segment_plane_exact(pl, p1, p2);
  tecido::reference::ExactSegmentPlane ex;
  try {
    ex = tecido::reference::exact_segment_plane(pl, p1, p2);
  } catch (const std::exception& e) {
    report(std::string("the referee threw on finite input: ") + e.what(), pl, p1, p2);
  }
  if (core.hit != ex.hit)
    report(std::string("core says ") + (core.hit ? "hit" : "miss") + ", the referee " + (ex.hit ? "hit" : "miss"), pl, p1, p2);
  if (unfiltered.hit != core.hit) report("core's filtered and unfiltered exact paths disagree", pl, p1, p2);
  if (core.hit && !(core.t >= 0.0 && core.t <= 1.0)) report("core's hit has t outside [0, 1]: " + std::to_string(core.t), pl, p1, p2);
  return 0;
}
