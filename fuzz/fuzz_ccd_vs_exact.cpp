// libFuzzer target: core's continuous collision test (tecido::ccd, core/geometry/ccd/ccd.h) against
// the exact referee (tecido::reference::exact_ccd, GMP), and core's batched first stages
// (core/geometry/ccd/batch/stages.h) against core's scalar test. What core claims, and so what
// is a finding (the target prints FINDING, the 24 coordinates in hex, and traps):
//  1. zero false negatives: the referee finds a contact, core answers miss;
//  2. toi never after the first contact: core's toi > the referee's upper bound toi_hi, or a
//     toi outside [0, 1];
//  1 and 2 are checked on the query and on each reordering of its points that describes the
//     same geometry (vertex-face: the triangle's corners rotated and reversed; edge-edge: the
//     two edges swapped, either edge reversed), whose exact answer is the referee's for the
//     original. Whether core says hit on a near miss (within its distance tolerance, relative
//     to a scale L that depends on the order of the points) may legitimately change with the
//     order, so a hit on one order and a miss on another is a finding only when the referee
//     says hit, which 1 already covers;
//  3. the batched stages decide as ccd does: a query they reject (boxes, cubic, root miss) is one
//     ccd misses, one their root says hit is one ccd hits; and their verdicts are the same bits at
//     every SIMD width this CPU runs (2, 4, 8).
//
// Input layout:
//   byte 0: bit 0 the kind (0 vertex-face, 1 edge-edge), bits 1..7 structure flags A
//   byte 1: structure flags B (see apply_flags)
//   then 24 coordinates (x0[0].xyz .. x0[3].xyz, then x1[0].xyz .. x1[3].xyz) as
//   fuzz_coordinates.h reads them, then up to 4 bytes of parameters for the flags.
// Skipped: non-finite inputs (core answers hit at 0 by contract; the referee refuses them), and,
// for the referee only (3 still runs), inputs whose nonzero coordinates span more than
// kMaxExponentSpread binary orders of magnitude: the referee scales the query to integers of
// about that many bits and its cost grows with them (GMP); past that, a few inputs take seconds.
#include "fuzz_coordinates.h"

#include "core/geometry/ccd/ccd.h"
#include "core/geometry/ccd/batch/stages.h"
#include "reference/exact_ccd.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using tecido::CcdAnswer;
using tecido::CcdKind;
using tecido::CcdQuery;
using tecido::Vec3;
using tecido::fuzz::Bytes;

constexpr const char* kTarget = "fuzz_ccd_vs_exact";
constexpr int kMaxExponentSpread = 400;

[[noreturn]] void report(const std::string& what, const CcdQuery& q) {
  std::fprintf(stderr, "\n%s: FINDING: %s\n  kind %s\n", kTarget, what.c_str(), tecido::ccd_kind_name(q.kind));
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 4; ++k) {
      const Vec3& v = t == 0 ? q.x0[k] : q.x1[k];
      std::fprintf(stderr, "  x%d[%d] = [%a, %a, %a]  (%.17g, %.17g, %.17g)\n", t, k, v.x(), v.y(), v.z(), v.x(), v.y(),
                   v.z());
    }
  std::fflush(stderr);
  __builtin_trap();
}

/// Point p of the query at both times gets a point on the segment or triangle spanned by
/// others, at parameters from the byte (exact for small integer and dyadic inputs).
Vec3 on_span(const std::array<Vec3, 4>& x, int a, int b, int c, std::uint8_t p) {
  const double s = (p & 15) / 16.0, t = (p >> 4) / 16.0;
  Vec3 r = x[a] + s * (x[b] - x[a]);
  if (c >= 0) r += t * (1.0 - s) * (x[c] - x[a]);
  return r;
}

/// Structure flags, so that the degenerate families are common:
///  A bit 1: coplanar throughout in a fixed plane (every z = x0[0].z at both times);
///  A bit 2: coplanar at each time in a moving plane (z at t0 = x0[0].z, z at t1 = x1[0].z);
///  A bit 3: zero-area face (vertex-face: x[3] = x[2], or collinear x[3] = 2 x[2] - x[1]) or
///           zero-length edge (edge-edge: x[1] = x[0]), at both times;
///  A bit 4: parallel edges (x[3] = x[2] + (x[1] - x[0])) / a rigidly translated face;
///  A bit 5: contact at t = 0 (the vertex on the face, or b0 on edge a, at parameters p0);
///  A bit 6: contact at t = 1 (the same at t = 1, parameters p1);
///  A bit 7: the points of mask p2 do not move (x1 = x0);
///  B bit 0: scale everything by 2^e, e from p3 in -600..594 (exact unless it under/overflows);
///  B bit 1: the second edge zero-length too / the whole face a point;
///  B bit 2: all four points coincide at t = 0 (or t = 1 with B bit 3);
///  B bit 4: reverse time (x0 and x1 swapped) after the rest.
void apply_flags(std::uint8_t a, std::uint8_t b, Bytes& in, CcdQuery& q) {
  const std::uint8_t p0 = in.u8(), p1 = in.u8(), p2 = in.u8(), p3 = in.u8();
  const bool ee = q.kind == CcdKind::EdgeEdge;
  for (auto* x : {&q.x0, &q.x1}) {
    if (a & 8) (*x)[ee ? 1 : 3] = ee ? (*x)[0] : ((p0 & 1) ? Vec3(2.0 * (*x)[2] - (*x)[1]) : (*x)[2]);
    if (b & 2) {
      if (ee) (*x)[3] = (*x)[2];
      else (*x)[2] = (*x)[3] = (*x)[1];
    }
  }
  if (a & 16) {
    if (ee) {
      q.x0[3] = q.x0[2] + (q.x0[1] - q.x0[0]);
      q.x1[3] = q.x1[2] + (q.x1[1] - q.x1[0]);
    } else {
      const Vec3 d = q.x1[1] - q.x0[1];
      q.x1[2] = q.x0[2] + d;
      q.x1[3] = q.x0[3] + d;
    }
  }
  if (a & 32) q.x0[ee ? 2 : 0] = ee ? on_span(q.x0, 0, 1, -1, p0) : on_span(q.x0, 1, 2, 3, p0);
  if (a & 64) q.x1[ee ? 2 : 0] = ee ? on_span(q.x1, 0, 1, -1, p1) : on_span(q.x1, 1, 2, 3, p1);
  if (b & 4) {
    auto& x = (b & 8) ? q.x1 : q.x0;
    x[1] = x[2] = x[3] = x[0];
  }
  if (a & 128)
    for (int k = 0; k < 4; ++k)
      if (p2 & (1 << k)) q.x1[k] = q.x0[k];
  if (a & 2)
    for (auto* x : {&q.x0, &q.x1})
      for (Vec3& v : *x) v.z() = q.x0[0].z();
  if (a & 4) {
    const double z0 = q.x0[0].z(), z1 = q.x1[0].z();
    for (Vec3& v : q.x0) v.z() = z0;
    for (Vec3& v : q.x1) v.z() = z1;
  }
  if (b & 1) {
    const int e = static_cast<int>(p3 % 200) * 6 - 600;
    for (auto* x : {&q.x0, &q.x1})
      for (Vec3& v : *x) v = Vec3(std::ldexp(v.x(), e), std::ldexp(v.y(), e), std::ldexp(v.z(), e));
  }
  if (b & 16) std::swap(q.x0, q.x1);
}

bool finite(const CcdQuery& q) {
  for (int k = 0; k < 4; ++k)
    if (!q.x0[k].allFinite() || !q.x1[k].allFinite()) return false;
  return true;
}

CcdQuery permuted(const CcdQuery& q, const std::array<int, 4>& order) {
  CcdQuery p = q;
  for (int k = 0; k < 4; ++k) {
    p.x0[k] = q.x0[order[k]];
    p.x1[k] = q.x1[order[k]];
  }
  return p;
}

/// The query and every reordering that describes the same geometry (the original first).
std::vector<CcdQuery> same_geometry(const CcdQuery& q) {
  static const std::array<std::array<int, 4>, 6> vf = {{{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {0, 1, 3, 2}, {0, 3, 2, 1}, {0, 2, 1, 3}}};
  static const std::array<std::array<int, 4>, 6> ee = {{{0, 1, 2, 3}, {2, 3, 0, 1}, {1, 0, 2, 3}, {0, 1, 3, 2}, {3, 2, 1, 0}, {1, 0, 3, 2}}};
  std::vector<CcdQuery> out;
  for (const auto& order : q.kind == CcdKind::EdgeEdge ? ee : vf) out.push_back(permuted(q, order));
  return out;
}

/// Claims 1 and 2 for every reordering; `q` is the original (what report prints).
void check_against_referee(const CcdQuery& q, const std::vector<CcdQuery>& variants,
                           const std::vector<CcdAnswer>& core) {
  tecido::reference::ExactCcd ex;
  try {
    ex = tecido::reference::exact_ccd(q);
  } catch (const std::exception& e) {
    report(std::string("the referee threw on finite input: ") + e.what(), q);
  }
  for (std::size_t k = 0; k < variants.size(); ++k) {
    const std::string which = "ordering " + std::to_string(k) + ": ";
    if (ex.hit && !core[k].hit)
      report(which + "core misses a contact the referee finds at t = " + std::to_string(ex.toi), q);
    if (ex.hit && core[k].toi > ex.toi_hi) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "core's toi %a is after the referee's first contact (toi_hi %a)", core[k].toi, ex.toi_hi);
      report(which + buf, q);
    }
  }
}

/// Claim 3: the batched first stages on all reorderings (repeated to fill two blocks of 8, so the
/// root replay, which runs on full blocks, sees them), at every available width.
void check_batch(const CcdQuery& q, const std::vector<CcdQuery>& variants, const std::vector<CcdAnswer>& core) {
  constexpr int kQueries = 16;
  std::vector<double> x0, x1;
  std::vector<std::array<int, 4>> points;
  for (int k = 0; k < kQueries; ++k) {
    const CcdQuery& v = variants[k % variants.size()];
    std::array<int, 4> idx;
    for (int i = 0; i < 4; ++i) {
      idx[i] = static_cast<int>(x0.size() / 3);
      for (int c = 0; c < 3; ++c) {
        x0.push_back(v.x0[i][c]);
        x1.push_back(v.x1[i][c]);
      }
    }
    points.push_back(idx);
  }
  std::vector<std::uint8_t> first;
  for (int width : {1, 2, 4, 8}) {
    if (!tecido::ccd_batch_width_available(width)) continue;
    std::vector<std::uint8_t> verdict(kQueries, 0xff);
    tecido::ccd_batch_first_stages(q.kind, x0.data(), x1.data(), 3, points.data(), kQueries, true, verdict.data(), width);
    if (first.empty()) first = verdict;
    for (int k = 0; k < kQueries; ++k) {
      const std::string which = "width " + std::to_string(width) + ", ordering " + std::to_string(k % variants.size());
      if (verdict[k] != first[k])
        report(which + ": batched verdict " + std::to_string(verdict[k]) + " differs from width 2's " +
                   std::to_string(first[k]), q);
      const bool says_miss = verdict[k] & (tecido::kCcdBoxesDisjoint | tecido::kCcdCubicMiss | tecido::kCcdRootMiss);
      const bool says_hit = verdict[k] & tecido::kCcdRootHit;
      const bool hit = core[k % variants.size()].hit;
      if ((says_miss && hit) || (says_hit && !hit) || (says_miss && says_hit))
        report(which + ": batched verdict " + std::to_string(verdict[k]) + " but scalar ccd says " + (hit ? "hit" : "miss"), q);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::uint8_t a = in.u8(), b = in.u8();
  double c[24];
  tecido::fuzz::decode_coordinates(in, c, 24);
  CcdQuery q;
  q.kind = (a & 1) ? CcdKind::EdgeEdge : CcdKind::VertexFace;
  for (int k = 0; k < 4; ++k) {
    q.x0[k] = Vec3(c[3 * k], c[3 * k + 1], c[3 * k + 2]);
    q.x1[k] = Vec3(c[12 + 3 * k], c[12 + 3 * k + 1], c[12 + 3 * k + 2]);
  }
  apply_flags(a, b, in, q);
  if (!finite(q)) return 0;

  const std::vector<CcdQuery> variants = same_geometry(q);
  std::vector<CcdAnswer> core;
  for (const CcdQuery& v : variants) {
    const CcdAnswer ans = tecido::ccd(v);
    if (ans.hit && !(ans.toi >= 0.0 && ans.toi <= 1.0)) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "core's toi %a is outside [0, 1]", ans.toi);
      report(buf, q);
    }
    core.push_back(ans);
  }
  double flat[24];
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) {
      flat[3 * k + i] = q.x0[k][i];
      flat[12 + 3 * k + i] = q.x1[k][i];
    }
  if (tecido::fuzz::exponent_spread(flat, 24) <= kMaxExponentSpread) check_against_referee(q, variants, core);
  check_batch(q, variants, core);
  return 0;
}
