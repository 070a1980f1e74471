#pragma once
/// The seed's claims about its experiment (section 3.1.3, and 3.1.1 for the cost of detection),
/// each with the statistic that tests it, the seed's own value of that statistic (from its
/// tables where it has one), ours with a 95% interval, and a verdict decided by a stated rule.
/// Four rule families (the rule string of each claim says which, with its numbers):
///  - direction ("X lowers / raises the share"): our effect's interval wholly on the seed's side
///    of 0 -> reproduced; wholly on the other side, or containing 0 but not the seed's own value
///    (the seed's effect is ruled out) -> not reproduced; otherwise inconclusive;
///  - size ("by about 20%"): Welch's interval of (ours - the seed's), the seed's standard error
///    from its cells' spread: excludes 0 -> not reproduced; contains 0 and not -seed (so our
///    effect is told apart from none) -> reproduced; otherwise inconclusive;
///  - negligible ("helps little", "the rows are level"): interval inside +-margin -> reproduced;
///    wholly outside -> not reproduced; otherwise inconclusive;
///  - threshold ("much slower", "often", "the costliest"): interval above the threshold ->
///    reproduced; below -> not reproduced; otherwise inconclusive.
/// Too few values for an interval (fewer than 2 seeds) -> inconclusive, with the reason.
#include "comparisons/suites/self_contact/ensemble.h"
#include "comparisons/suites/self_contact/settings.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace tecido::suites::self_contact {

enum class Verdict { Reproduced, NotReproduced, Inconclusive };
/// "reproduced", "not reproduced", "inconclusive".
const char* verdict_name(Verdict v);

struct Claim {
  std::string id;
  std::string detector;       ///< the counting detector; "" when the claim does not depend on it
  std::string statement;      ///< what the seed claims
  std::string seed_text;      ///< the seed's numbers as it states them or as its tables give them
  double seed = NAN;          ///< the seed's value of the statistic (NaN when it has none)
  double observed = NAN;      ///< ours
  Interval ci95{NAN, NAN};    ///< ours, 95%
  std::size_t n = 0;          ///< values the interval is computed from (seeds, cells or timing blocks)
  std::string observed_text;  ///< what else we found (counts, the parts of a composite)
  std::string unit;           ///< "relative change", "share of frames", "ratio", "difference of shares"
  Verdict verdict = Verdict::Inconclusive;
  std::string rule;           ///< how the verdict follows from the numbers
  std::string reason;         ///< why a claim is inconclusive for lack of data ("" otherwise)
  bool wall_clock = false;    ///< decided from timings (outside the determinism promise)
};

Verdict direction_verdict(const Interval& ci, double seed_value, int side);
Verdict size_verdict(const Interval& difference, double seed_value);
Verdict negligible_verdict(const Interval& ci, double margin);
Verdict threshold_verdict(const Interval& ci, double threshold);

/// The claims that depend on the counting detector d of the ensemble. `fit` marks the cells the
/// calibration was fitted on (left out of the cells-match claim, which judges predictions).
std::vector<Claim> detector_claims(const Ensemble& e, std::size_t d, const SeedTables& seed, const Settings& s,
                                   const std::array<bool, CellGrid::kCells>& fit);

/// The premise (GIA cannot separate the sides where a contact reaches the border; the scene
/// provokes contacts near the borders), measured on the no-response runs with the exact detector.
std::vector<Claim> premise_claims(const Ensemble& e, const Settings& s);

}  // namespace tecido::suites::self_contact
