#pragma once
/// What the forced-contact experiment runs (`tecido experiment forced-contact`) and the constants
/// of its claim rules, with the --quick variant. Every number is fixed before any response was
/// compared (git history: this file and claims.h were committed before the first comparison run).
#include "core/cloth/self_collision_settings.h"

#include <vector>

namespace tecido::suites::forced_contact {

struct Settings {
  /// Hold times H [s]: a few steps, a fraction of a second, several seconds.
  std::vector<double> holds{0.03, 0.6, 3.0};
  /// Responses compared, in report order.
  std::vector<SelfCollisionResponse> responses{SelfCollisionResponse::None,  SelfCollisionResponse::Gia,
                                               SelfCollisionResponse::Edge1, SelfCollisionResponse::Edge2,
                                               SelfCollisionResponse::Edge3, SelfCollisionResponse::GiaEdge3,
                                               SelfCollisionResponse::Impulse};
  int seeds = 10;                ///< runs per (response, hold), each with its own initial offsets
  double after_release = 4.0;    ///< [s] simulated after the grips let go (the horizon)
  /// A run has recovered when every frame from some time on is free of intersection and that
  /// free stretch lasts at least `dwell` before the horizon: recovery is censored at
  /// after_release - dwell.
  double dwell = 0.5;
  double sample = 0.05;          ///< [s] between the samples of the pairs-over-time series
  int bootstrap = 2000;          ///< resamples of the bootstrap interval of a censored median

  /// Claim rules (claims.h):
  /// "GIA recovers": its recovery share's Wilson interval above this share.
  double recovers_share = 0.8;
  /// "GIA does not depend on H": the difference of restricted mean recovery times (longest hold
  /// minus shortest) inside +-margin [s] (a tenth of the censoring time).
  double hold_margin = 0.35;
};

inline Settings settings(bool quick) {
  Settings s;
  if (quick) {
    s.holds = {0.03, 0.3};
    s.seeds = 2;
    s.after_release = 1.0;
    s.dwell = 0.2;
    s.bootstrap = 200;
  }
  return s;
}

/// The censoring time of recovery [s after release].
inline double censor_time(const Settings& s) { return s.after_release - s.dwell; }

}  // namespace tecido::suites::forced_contact
