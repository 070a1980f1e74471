#pragma once
/// Tolerances of core's continuous collision test (core/geometry/ccd/ccd.h). They decide how near
/// a near miss may be and still be reported as a hit, and how close the reported time of
/// impact is to the true one; they never decide whether a true contact is found (zero false
/// negatives hold for every setting, see ccd/ccd.h).

namespace tecido {

struct CcdSettings {
  /// Relative distance tolerance. The query's scale L is the largest absolute coordinate of
  /// its difference vectors at t = 0 and t = 1 (vertex-face: b - a, c - a, p - a; edge-edge:
  /// a1 - a0, b0 - b1, b0 - a0), about the size of the primitives plus their relative motion.
  /// A hit is reported only when the primitives come within distance_tolerance * L (plus a
  /// rounding term below 1e-13 L) of each other during the step; primitives that stay farther
  /// apart are always a miss. Clamped to [2^-36, 2^-4].
  double distance_tolerance = 1e-9;
  /// Time tolerance: every hit comes with a time in [toi, toi + time_tolerance] at which the
  /// primitives are that close (for a transversal contact: the true time of impact lies in
  /// that window), and toi is never later than the true time of impact. Rounded down to a
  /// power of two and clamped to [2^-40, 2^-2].
  double time_tolerance = 0x1p-20;
  /// Cap on the boxes the inclusion search (the fallback for degenerate motion) examines in
  /// one query. When reached, the answer is a conservative hit at the earliest time not yet
  /// excluded (toi still <= true toi, but the distance guarantee above is void).
  int max_boxes = 20000;
};

}  // namespace tecido
