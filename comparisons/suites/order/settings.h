#pragma once
/// What the `order` suite runs (its own settings; the tolerance file holds only the band of the
/// fitted order, /order/band). Changing these changes the work done and the fit, so they live
/// here, next to the code, and are printed in the report.
namespace tecido::suites::order {

struct Settings {
  double h0 = 0.25;   ///< first step [s]; each run halves it
  int halvings = 12;  ///< steps h0 / 2^0 .. h0 / 2^halvings (9 with --quick)
  /// Errors at or below roundoff_floor x the problem's scale are round-off and are left out of the
  /// fit; errors at or above too_big x scale are unstable or pre-asymptotic and are left out too.
  double roundoff_floor = 1e-11;
  double too_big = 0.02;
  double agree = 0.1;     ///< observed orders of neighbouring halvings in the fitted range differ by at most this
  int min_halvings = 3;   ///< a fit needs at least this many consecutive agreeing halvings
  int head_to_head = 4;   ///< Euler vs midpoint compared at h0 / 2^head_to_head (1/64 s)
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) s.halvings = 9;
  return s;
}

}  // namespace tecido::suites::order
