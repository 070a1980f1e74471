#include "core/geometry/ccd_pipeline.h"

#include "core/geometry/ccd_kinetic_boxes.h"
#include "core/geometry/ccd_stats.h"
#include "core/geometry/ccd_swept_boxes.h"
#include "core/geometry/ccd_system.h"
#include "core/geometry/ccd_time_search.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace tecido {

namespace {

/// True when every coordinate is finite. The sum of all 24 (four partial sums) is finite
/// whenever they are, unless it overflows: only then are they checked one by one.
bool finite_inputs(const CcdQuery& q) {
  double acc[4] = {0.0, 0.0, 0.0, 0.0};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) {
      acc[i] += q.x0[i][c];
      acc[i] += q.x1[i][c];
    }
  const double sum = (acc[0] + acc[1]) + (acc[2] + acc[3]);
  if (std::fabs(sum) <= DBL_MAX) return true;
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(q.x0[i][c]) || !std::isfinite(q.x1[i][c])) return false;
  return true;
}

/// The boxes of points [first, last) of x.
void box_of(const std::array<Vec3, 4>& x, int first, int last, CcdBox& b) {
  for (int c = 0; c < 3; ++c) {
    double lo = x[first][c], hi = lo;
    for (int i = first + 1; i < last; ++i) {
      lo = std::min(lo, x[i][c]);
      hi = std::max(hi, x[i][c]);
    }
    b[c] = lo;
    b[c + 3] = hi;
  }
}

/// ccd_kinetic_boxes_disjoint on the query's two primitives.
bool kinetic_boxes_disjoint(const CcdQuery& q) {
  const int split = q.kind == CcdKind::VertexFace ? 1 : 2;
  CcdBox a0, a1, b0, b1;
  box_of(q.x0, 0, split, a0);
  box_of(q.x1, 0, split, a1);
  box_of(q.x0, split, 4, b0);
  box_of(q.x1, split, 4, b1);
  return ccd_kinetic_boxes_disjoint(a0, a1, b0, b1);
}

}  // namespace

CcdAnswer ccd_after_boxes(const CcdQuery& q, const CcdSettings& clamped);

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
  if (!finite_inputs(q)) {
    st.non_finite++;
    return {true, 0.0};
  }
  if (ccd_swept_boxes_disjoint(q) || kinetic_boxes_disjoint(q)) {
    st.box_rejections++;
    return {};
  }
  return ccd_after_boxes(q, clamped);
}

CcdAnswer ccd_after_boxes(const CcdQuery& q) {
  static const CcdSettings defaults = ccd_clamped(CcdSettings{});
  ccd_stats().queries++;
  return ccd_after_boxes(q, defaults);
}

CcdAnswer ccd_after_boxes(const CcdQuery& q, const CcdSettings& clamped) {
  CcdStats& st = ccd_stats();
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
  return ccd_time_search(s, clamped);
}

}  // namespace tecido
