#include "core/geometry/ccd/kinetic_boxes.h"

#include "core/simd/scalar_lanes.h"

#include <cmath>

namespace tecido {

namespace {
// The test at width 1 of core's SIMD layer: the text the batched stages run at 2, 4 and 8.
namespace w1 {
using Lanes = simd::ScalarLanes;
#include "core/simd/lane_math.inl"
#include "core/geometry/ccd/kinetic_program.inl"
}  // namespace w1
}  // namespace

bool ccd_kinetic_boxes_disjoint(const CcdBox& a0, const CcdBox& a1, const CcdBox& b0, const CcdBox& b1) {
  using S = w1::Lanes;
  w1::PairBoxes<S> b;
  for (int c = 0; c < 3; ++c) {
    b.alo[0][c] = a0[c], b.ahi[0][c] = a0[c + 3], b.blo[0][c] = b0[c], b.bhi[0][c] = b0[c + 3];
    b.alo[1][c] = a1[c], b.ahi[1][c] = a1[c + 3], b.blo[1][c] = b1[c], b.bhi[1][c] = b1[c + 3];
  }
  // Overlapping at t = 0 or t = 1 (exactly): not disjoint, as the widened test would also
  // find; the common case for neighbours, decided without it.
  if (w1::overlap_at_a_frame<S>(b)) return false;
  return w1::kinetic_program_infeasible<S>(b);
}

}  // namespace tecido
