#include "core/geometry/ccd/kinetic_boxes.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {
/// True when the closed boxes overlap (exact comparisons).
bool overlap(const CcdBox& a, const CcdBox& b) {
  return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] && b[2] <= a[5];
}
}  // namespace

// The branchy scalar form, kept for speed (early returns skip the divisions; a width-1
// instantiation of kinetic_program.inl, which computes every constraint's bound, made
// BM_CCD/core/*/random-small 20-25% slower). The batched stages run kinetic_program.inl, the
// same operations lane by lane; test_batch_stages compares them query by query.
bool ccd_kinetic_boxes_disjoint(const CcdBox& a0, const CcdBox& a1, const CcdBox& b0, const CcdBox& b1) {
  // Overlapping at t = 0 or t = 1 (exactly): not disjoint, as the widened test below would
  // also find; the common case for neighbours, decided without it.
  if (overlap(a0, b0) || overlap(a1, b1)) return false;
  // The six constraints, widened, at t = 0 (a) and t = 1 (b): k = 2c for hi_B - lo_A, 2c + 1
  // for hi_A - lo_B.
  double a[6], b[6];
  bool at0 = true, at1 = true;
  for (int c = 0; c < 3; ++c) {
    const double v0[2] = {b0[c + 3] - a0[c], a0[c + 3] - b0[c]};
    const double v1[2] = {b1[c + 3] - a1[c], a1[c + 3] - b1[c]};
    for (int k = 0; k < 2; ++k) {
      const double m = 0x1p-50 * std::max(std::fabs(v0[k]), std::fabs(v1[k]));
      a[2 * c + k] = v0[k] + m;
      b[2 * c + k] = v1[k] + m;
      if (a[2 * c + k] < 0.0 && b[2 * c + k] < 0.0) return true;  // violated at all t
      at0 = at0 && a[2 * c + k] >= 0.0;
      at1 = at1 && b[2 * c + k] >= 0.0;
    }
  }
  if (at0 || at1) return false;  // the boxes overlap at t = 0 or at t = 1
  double lower = 0.0, upper = 1.0;  // the feasible times
  for (int k = 0; k < 6; ++k) {
    if (a[k] < 0.0) {
      lower = std::max(lower, (-a[k] / (b[k] - a[k])) * (1.0 - 0x1p-50));  // satisfied from here on
    } else if (b[k] < 0.0) {
      upper = std::min(upper, (a[k] / (a[k] - b[k])) * (1.0 + 0x1p-50));  // satisfied until here
    }
  }
  return lower > upper;
}

}  // namespace tecido
