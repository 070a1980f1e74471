#include "reference/exact_self_contacts.h"

#include "reference/exact_ccd.h"

namespace tecido::reference {

ContinuousContacts exact_self_contacts(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                                       const std::vector<std::array<int, 3>>& triangles, int threads) {
  ContinuousSelfCollisionDetector det(triangles, x0);
  det.set_threads(threads);
  const ContinuousContacts& candidates = det.detect(x0, x1);
  // The referee's filter decides nearly every candidate; exact arithmetic only where it cannot
  // (exact_ccd_hit: whether, not when).
  return filter_contacts(candidates, x0, x1, triangles, &exact_ccd_hit, threads);
}

}  // namespace tecido::reference
