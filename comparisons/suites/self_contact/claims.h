#pragma once
/// The seed's claims about its experiment (section 3.1.3, and 3.1.1 for the cost of detection),
/// each with the statistic that tests it, the seed's own value of that statistic (from its
/// tables where it has one), ours with a 95% interval, two p-values and a verdict decided by a
/// stated rule. Every claim is two tests (comparisons/stats/): one whose rejection supports the
/// claim (p_support) and one whose rejection refutes it (p_refute). Rule families (the rule string
/// of each claim says which, with its numbers):
///  - direction ("X lowers / raises the share"): support = one-sided t test over wind seeds that
///    our effect lies on the seed's side of 0; refute = two-sided t test that it equals the
///    seed's own value (so an effect on the other side, or none where the seed saw one, refutes);
///  - equivalence ("by about 20%", "helps little", "the rows are level"): two one-sided tests
///    (TOST) against a band of +-margin stated in advance (Settings; docs/design.md §10 gives each
///    margin's reason): support = the TOST p (the 90% interval inside the band), refute = the test
///    that the value lies wholly outside the band;
///  - threshold ("much slower", "often", "the costliest"): one-sided t tests above (support) and
///    below (refute) the threshold;
///  - coverage (cells-match): exact binomial tests of the count of seed values outside our 95%
///    prediction intervals: equivalence of the rate to [coverage_lo, coverage_hi] (support), the
///    two-sided test of the rate 5% (refute: coverage far from 95%, too high or too low);
///  - every level (mode3-every-*): the direction tests per level, joined as an intersection-union
///    test (support = the largest level p) and by Bonferroni (refute = levels x the smallest).
/// Multiplicity: within each family (a detector's ten claims, the premise's two, the cost's three)
/// both p-values are Holm-adjusted (stats/holm.h). Verdict: reproduced when the adjusted support
/// p < alpha, else not reproduced when the adjusted refute p < alpha, else inconclusive. A claim
/// with no test (fewer than 2 seeds, or data without variation: sd = 0 over n >= 2 values) is
/// inconclusive with the reason, and is not a member of its Holm family.
#include "comparisons/suites/self_contact/ensemble.h"
#include "comparisons/suites/self_contact/settings.h"

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace tecido::suites::self_contact {

enum class Verdict { Reproduced, NotReproduced, Inconclusive };
/// "reproduced", "not reproduced", "inconclusive".
const char* verdict_name(Verdict v);

/// A detector claim recomputed from the cell pairs that touch no calibration cell (calibration.h):
/// the fitted no-response cells are also the denominators of 6 of the 18 pairs of every mode claim
/// and of 3 of the 9 elasticity pairs, so their agreement with the seed is partly fitted.
struct HeldOut {
  bool computed = false;
  double observed = kNaN;
  Interval ci95{kNaN, kNaN};
  std::size_t n = 0;
  double p_support_holm = kNaN, p_refute_holm = kNaN;
  Verdict verdict = Verdict::Inconclusive;
  std::string reason;
  std::string observed_text;
};

struct Claim {
  std::string id;
  std::string detector;       ///< the counting detector; "" when the claim does not depend on it
  std::string statement;      ///< what the seed claims (or, for a check of ours, what we check)
  std::string seed_text;      ///< the seed's numbers as it states them or as its tables give them
  double seed = NAN;          ///< the seed's value of the statistic (NaN when it has none)
  double observed = NAN;      ///< ours
  Interval ci95{NAN, NAN};    ///< ours, 95%
  std::size_t n = 0;          ///< values the interval is computed from (seeds, cells or timing blocks)
  std::string observed_text;  ///< what else we found (counts, the parts of a composite)
  std::string unit;           ///< "relative change", "share of frames", "ratio", "difference of shares"
  Verdict verdict = Verdict::Inconclusive;
  std::string rule;           ///< how the verdict follows from the numbers
  std::string reason;         ///< why a claim could not be tested ("" otherwise)
  bool wall_clock = false;    ///< decided from timings (outside the determinism promise)
  bool seed_makes = true;     ///< the seed states it; false: a check of ours the seed never makes
  double margin = NAN;        ///< the equivalence margin stated in advance, in the claim's unit (NaN: none)
  std::string band;           ///< the equivalence band as stated ("+-10%", "[0.01, 0.14]"); "" when none
  std::string family;         ///< its Holm family: the detector's name, "premise" or "cost"
  double p_support = NAN, p_refute = NAN;            ///< raw p-values of the two tests
  double p_support_holm = NAN, p_refute_holm = NAN;  ///< Holm-adjusted within the family
  std::vector<std::pair<std::string, double>> figures;  ///< named numbers behind observed_text
  HeldOut held_out;           ///< detector claims: without the calibration's cells
};

/// Interval rules, for experiments that decide a claim on one 95% interval without a family (the
/// forced-contact experiment): direction (wholly on the claimed side of 0 -> reproduced; wholly on
/// the other side, or containing 0 but not the seed's value -> not reproduced), negligible (inside
/// +-margin: equivalence at 2.5% per side -> reproduced; wholly outside -> not reproduced) and
/// threshold (above -> reproduced; below -> not reproduced); inconclusive otherwise or undefined.
Verdict direction_verdict(const Interval& ci, double seed_value, int side);
Verdict negligible_verdict(const Interval& ci, double margin);
Verdict threshold_verdict(const Interval& ci, double threshold);

/// The verdict from Holm-adjusted p-values (see the file comment).
Verdict verdict_from(double p_support_holm, double p_refute_holm, double alpha);
/// Holm within each family of `claims`; sets the adjusted p-values and the verdicts.
void apply_holm(std::vector<Claim>& claims, double alpha);
/// Sets observed, ci95 and n from a summary; false (and the reason) when no test can use it:
/// fewer than 2 values, or values without variation.
bool take_summary(Claim& c, const Summary& s);

/// The cost half of mode1-marginal (the seed: "not worth it: no detection at all makes the
/// simulation much lighter"), measured by the phase timing (timing.h): per block of steps,
/// (step + the seed's detection + response) / step, against Settings::much_slower.
struct CostHalf {
  double observed = kNaN;
  Interval ci95{kNaN, kNaN};
  std::size_t n = 0;
  double p_support = kNaN, p_refute = kNaN;
  std::string reason;  ///< why it was not measured ("" when it was)
};

/// The claims that depend on the counting detector d of the ensemble, Holm-adjusted as one
/// family, each with its held-out recomputation. `fit` marks the cells the calibration was fitted
/// on; `cost` is mode1-marginal's cost half.
std::vector<Claim> detector_claims(const Ensemble& e, std::size_t d, const SeedTables& seed, const Settings& s,
                                   const std::array<bool, CellGrid::kCells>& fit, const CostHalf& cost);

/// The premise (GIA cannot separate the sides where a contact reaches the border; the scene
/// provokes contacts near the borders), measured on the no-response runs with the exact detector.
std::vector<Claim> premise_claims(const Ensemble& e, const Settings& s);

}  // namespace tecido::suites::self_contact
