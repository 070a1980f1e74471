#include "core/geometry/ccd/pipeline.h"

#include "core/geometry/ccd/kinetic_boxes.h"
#include "core/geometry/ccd/stats.h"
#include "core/geometry/ccd/system.h"
#include "core/geometry/ccd/time_search.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace tecido {

namespace {

/// The box of points [first, last) of x (lo xyz, hi xyz); adds their coordinates to sum.
void box_of(const std::array<Vec3, 4>& x, int first, int last, CcdBox& b, double& sum) {
  for (int c = 0; c < 3; ++c) {
    double lo = x[first][c], hi = lo;
    sum += lo;
    for (int i = first + 1; i < last; ++i) {
      lo = std::min(lo, x[i][c]);
      hi = std::max(hi, x[i][c]);
      sum += x[i][c];
    }
    b[c] = lo;
    b[c + 3] = hi;
  }
}

bool inputs_finite(const CcdQuery& q) {
  for (const auto* x : {&q.x0, &q.x1})
    for (const Vec3& p : *x)
      if (!p.allFinite()) return false;
  return true;
}

enum class Boxes { Finite, NonFinite, Disjoint };

/// Stages 1 and 2 in one pass over the 24 coordinates: the primitives' boxes at t = 0 and 1,
/// and the sum of the coordinates (finite whenever they all are, unless it overflows: only
/// then are they checked one by one). The union of a primitive's two boxes is its swept box:
/// it contains the primitive at every t (each point moves on the segment between its
/// positions, and a box is convex), so disjoint swept boxes (exact comparisons) mean no
/// contact. Then the kinetic boxes (ccd/kinetic_boxes.h), which also see through shared motion.
Boxes box_stages(const CcdQuery& q) {
  const int split = q.kind == CcdKind::VertexFace ? 1 : 2;
  CcdBox a0, a1, b0, b1;
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  box_of(q.x0, 0, split, a0, sum[0]);
  box_of(q.x1, 0, split, a1, sum[1]);
  box_of(q.x0, split, 4, b0, sum[2]);
  box_of(q.x1, split, 4, b1, sum[3]);
  if (!(std::fabs((sum[0] + sum[1]) + (sum[2] + sum[3])) <= DBL_MAX) && !inputs_finite(q)) return Boxes::NonFinite;
  for (int c = 0; c < 3; ++c) {
    const double alo = std::min(a0[c], a1[c]), ahi = std::max(a0[c + 3], a1[c + 3]);
    const double blo = std::min(b0[c], b1[c]), bhi = std::max(b0[c + 3], b1[c + 3]);
    if (ahi < blo || bhi < alo) return Boxes::Disjoint;
  }
  return ccd_kinetic_boxes_disjoint(a0, a1, b0, b1) ? Boxes::Disjoint : Boxes::Finite;
}

CcdAnswer after_boxes(const CcdQuery& q, const CcdSettings& clamped, CcdStats& st) {
  CcdSystem s;
  switch (prepare_ccd_system(q, s)) {
    case CcdPrepared::NonFinite:
      st.non_finite++;
      return {true, 0.0};
    case CcdPrepared::AllCoincide:
      return {true, 0.0};
    case CcdPrepared::Ok:
      break;
  }
  return ccd_time_search(s, clamped, st);
}

}  // namespace

CcdSettings ccd_clamped(const CcdSettings& s) {
  const CcdSettings def;
  CcdSettings c = s;
  const double d = std::isnan(s.distance_tolerance) ? def.distance_tolerance : s.distance_tolerance;
  c.distance_tolerance = std::fmin(std::fmax(d, 0x1p-36), 0x1p-4);
  const double t = std::isnan(s.time_tolerance) ? def.time_tolerance : std::fmin(std::fmax(s.time_tolerance, 0x1p-40), 0x1p-2);
  int e = 0;
  std::frexp(t, &e);  // t = m 2^e, m in [0.5, 1): the power of two at or below t is 2^(e-1)
  c.time_tolerance = std::ldexp(1.0, e - 1);
  c.max_boxes = s.max_boxes < 1 ? 1 : s.max_boxes;
  return c;
}

CcdAnswer ccd_pipeline(const CcdQuery& q, const CcdSettings& clamped) {
  CcdStats& st = ccd_stats();
  st.queries++;
  switch (box_stages(q)) {
    case Boxes::NonFinite:
      st.non_finite++;
      return {true, 0.0};
    case Boxes::Disjoint:
      st.box_rejections++;
      return {};
    case Boxes::Finite:
      break;
  }
  return after_boxes(q, clamped, st);
}

CcdAnswer ccd_after_boxes(const CcdQuery& q) {
  static const CcdSettings defaults = ccd_clamped(CcdSettings{});
  CcdStats& st = ccd_stats();
  st.queries++;
  return after_boxes(q, defaults, st);
}

}  // namespace tecido
