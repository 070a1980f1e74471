#include "comparisons/suites/self_contact/claims.h"

#include "comparisons/stats/stats.h"
#include "comparisons/suites/self_contact/statistics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace tecido::suites::self_contact {

namespace {

using Pairs = std::vector<std::pair<int, int>>;

std::string pct(double x) { return std::isnan(x) ? "n/a" : fmt::format("{:+.1f}%", 100.0 * x); }
std::string pct_interval(const Interval& ci) {
  return ci.defined() ? fmt::format("[{}, {}]", pct(ci.lo), pct(ci.hi)) : "n/a";
}

/// Bonferroni over the p-values that exist: the smallest times their count (NaN when none).
double bonferroni_min(const std::vector<double>& ps) {
  double m = kNaN;
  int k = 0;
  for (double p : ps)
    if (!std::isnan(p)) m = std::isnan(m) ? p : std::min(m, p), ++k;
  return std::isnan(m) ? kNaN : std::min(1.0, k * m);
}

const char* const kDecision =
    " Both p-values are Holm-adjusted within the claim's family (the detector's ten claims); reproduced if the "
    "adjusted support p < 0.05, else not reproduced if the adjusted refute p < 0.05, else inconclusive.";

/// What every detector claim reads: the ensemble, the seed's tables, and whether the pairs that
/// touch a calibration cell are left out (the held-out recomputation).
struct Context {
  const Ensemble& e;
  std::size_t d;
  const SeedTables& seed;
  const Settings& s;
  const std::array<bool, CellGrid::kCells>& fit;
  const CostHalf& cost;
  bool held_out;

  Pairs use(const Pairs& pairs) const {
    if (!held_out) return pairs;
    Pairs out;
    for (const auto& p : pairs)
      if (!fit[p.first] && !fit[p.second]) out.push_back(p);
    return out;
  }
};

/// The direction tests on an effect: our effect on the seed's side of 0 (support), equal to the
/// seed's own value (refute; without a seed value, on the other side of 0).
void direction_tests(Claim& c, const Summary& s, int side) {
  if (!take_summary(c, s)) return;
  const stats::Estimate e = stats::mean_estimate(s);
  c.p_support = side < 0 ? stats::p_below(e, 0.0) : stats::p_above(e, 0.0);
  c.p_refute = !std::isnan(c.seed) ? stats::p_two_sided(e, c.seed) : side < 0 ? stats::p_above(e, 0.0) : stats::p_below(e, 0.0);
}

/// The equivalence tests of an estimate against centre +- margin.
void equivalence_tests(Claim& c, const stats::Estimate& e, double centre, double margin) {
  c.band = fmt::format("+-{:.0f}%", 100.0 * margin);
  const stats::Tost t = stats::tost(e, centre - margin, centre + margin);
  c.p_support = t.p;
  c.p_refute = t.p_outside;
  c.figures.push_back({"tost_ci90_lo", t.ci90.lo});
  c.figures.push_back({"tost_ci90_hi", t.ci90.hi});
}

std::string direction_rule(int pairs, int side, double seed_value) {
  return fmt::format(
      "direction: per wind seed, the mean over the {} cell pairs of (share - reference share) / reference cell mean "
      "(the seed index is the unit of replication: all cells of one index see the same wind). Support: one-sided t "
      "test over seeds that the effect lies {} 0. Refute: two-sided t test that it equals the seed's own value {}.{}",
      pairs, side < 0 ? "below" : "above", pct(seed_value), kDecision);
}

std::string equivalence_rule(int pairs, const std::string& what, double margin, const std::string& why) {
  return fmt::format(
      "equivalence: {} over the {} cell pairs, per wind seed. Support: two one-sided t tests (TOST) that it lies inside "
      "+-{:.0f}% (the margin, set in advance: {}), i.e. its 90% interval inside the band. Refute: one-sided t test that "
      "it lies wholly outside the band.{}",
      what, pairs, 100.0 * margin, why, kDecision);
}

const char* const kMarginWhy = "the smallest gain the seed reports as a gain, mode 3's 10% at 0.1 N";

/// A claim on the relative effect of mode m against no response.
Claim mode_claim(const Context& x, int mode, const char* id, Effect& ef, SeedEffect& se) {
  Claim c;
  c.id = id;
  c.detector = contact_test_name(x.e.detectors[x.d]);
  c.family = c.detector;
  c.unit = "relative change";
  const Pairs pairs = x.use(mode_pairs(mode));
  ef = relative_effect(x.e, x.d, pairs);
  se = seed_effect(x.seed, pairs);
  c.seed = se.s.mean;
  c.seed_text = fmt::format("{}: {} lower and {} higher than no response in {} cells", pct(se.s.mean), se.lower, se.higher,
                            se.s.n);
  c.observed_text = fmt::format("cell means lower in {} of {} cells, higher in {}; paired 95% interval below 0 in {}, "
                                "above 0 in {}", ef.mean_lower, ef.pairs, ef.mean_higher, ef.lower, ef.higher);
  return c;
}

Claim mode3_better(const Context& x) {
  Effect ef;
  SeedEffect se;
  Claim c = mode_claim(x, 3, "mode3-better", ef, se);
  c.statement = fmt::format("Mode 3 lowers the share of frames with self-contact against no response (the seed: "
                            "lower in {} of {} cells).", se.lower, se.s.n);
  c.rule = direction_rule(ef.pairs, -1, c.seed);
  direction_tests(c, ef.s, -1);
  return c;
}

Claim mode3_size(const Context& x) {
  Effect ef;
  SeedEffect se;
  Claim c = mode_claim(x, 3, "mode3-size", ef, se);
  c.statement = "Mode 3 avoids about 20% of the frames with self-contact (the seed's abstract and conclusion: \"20%\", "
                "\"up to 20%\"; section 3.1.3: about 10% at 0.1 N and near 20% at the other winds).";
  c.margin = x.s.size_margin;
  c.band = fmt::format("+-{:.0f}%", 100.0 * c.margin);
  c.rule = equivalence_rule(ef.pairs, "(our mean relative change - the seed's mean over the same cells), Welch's standard "
                            "error from ours over seeds and the seed's over its cells (the only spread it offers: a "
                            "wider seed spread makes equivalence harder, never easier)", c.margin,
                            "the seed's own statements of this effect span 10% to 20%");
  if (!take_summary(c, ef.s)) return c;
  if (se.s.without_variation() || se.s.n < 2) {
    c.reason = "the seed's effect has no spread over its cells";
    return c;
  }
  const stats::Estimate diff = stats::welch_estimate(ef.s, se.s);
  equivalence_tests(c, diff, 0.0, c.margin);
  c.figures.push_back({"difference", diff.value});
  c.observed_text += fmt::format("; ours - the seed's: {} (90% interval {})", pct(diff.value),
                                 pct_interval(stats::t_interval(diff, 0.90)));
  return c;
}

Claim mode3_wind(const Context& x) {
  Claim c;
  c.id = "mode3-wind";
  c.detector = contact_test_name(x.e.detectors[x.d]);
  c.family = c.detector;
  c.unit = "difference of relative changes";
  Effect by_wind[3];
  double seed_by_wind[3];
  int pairs = 0;
  for (int w = 0; w < 3; ++w) {
    by_wind[w] = relative_effect(x.e, x.d, x.use(mode_pairs(3, w)));
    seed_by_wind[w] = seed_effect(x.seed, x.use(mode_pairs(3, w))).s.mean;
    pairs += by_wind[w].pairs;
  }
  const Effect g = contrast({&by_wind[1], &by_wind[0], &by_wind[2]}, {1.0, -0.5, -0.5});
  c.statement = "Mode 3's gain is smaller at 0.1 N (about 10%) than at 0.09 and 0.11 N (about 20%).";
  c.seed = seed_by_wind[1] - 0.5 * (seed_by_wind[0] + seed_by_wind[2]);
  c.seed_text = fmt::format("{}: {} at 0.09 N, {} at 0.1 N, {} at 0.11 N", pct(c.seed), pct(seed_by_wind[0]),
                            pct(seed_by_wind[1]), pct(seed_by_wind[2]));
  c.observed_text = fmt::format("{} at 0.09 N, {} at 0.1 N, {} at 0.11 N", pct(by_wind[0].s.mean), pct(by_wind[1].s.mean),
                                pct(by_wind[2].s.mean));
  c.rule = "contrast E(0.1 N) - (E(0.09 N) + E(0.11 N)) / 2 of mode 3's relative change, per wind seed; " +
           direction_rule(pairs, +1, c.seed);
  direction_tests(c, g.s, +1);
  return c;
}

/// Mode 3 lowers the share at every level of `factor` ("step" or "elasticity").
Claim mode3_every(const Context& x, const std::string& factor) {
  Claim c;
  c.id = "mode3-every-" + factor;
  c.detector = contact_test_name(x.e.detectors[x.d]);
  c.family = c.detector;
  c.seed_makes = false;
  c.unit = "relative change";
  const int levels = factor == "step" ? CellGrid::kSteps : CellGrid::kElasticities;
  std::vector<double> support, refute;
  std::string ours, theirs, gaps;
  c.observed = -std::numeric_limits<double>::infinity();
  for (int l = 0; l < levels; ++l) {
    const Pairs pairs = x.use(factor == "step" ? mode_pairs(3, -1, l) : mode_pairs(3, -1, -1, l));
    const std::string level = factor == "step" ? fmt::format("{} s", CellGrid::steps[l])
                                               : fmt::format("elasticity {}", CellGrid::elasticities[l]);
    if (pairs.empty()) {
      gaps += fmt::format("{}{}: every pair touches a calibration cell", gaps.empty() ? "" : "; ", level);
      continue;
    }
    const Effect ef = relative_effect(x.e, x.d, pairs);
    Claim part;
    part.seed = seed_effect(x.seed, pairs).s.mean;
    direction_tests(part, ef.s, -1);
    support.push_back(part.p_support);
    refute.push_back(part.p_refute);
    if (!part.reason.empty()) c.reason = level + ": " + part.reason;
    ours += fmt::format("{}{}: {} {} (support p {:.3g})", ours.empty() ? "" : "; ", level, pct(ef.s.mean),
                        pct_interval(ef.s.ci95), part.p_support);
    theirs += fmt::format("{}{}: {}", theirs.empty() ? "" : "; ", level, pct(part.seed));
    if (!(ef.s.mean <= c.observed)) c.observed = ef.s.mean, c.ci95 = ef.s.ci95, c.n = ef.s.n;  // the weakest (NaN wins)
  }
  c.statement = fmt::format("Mode 3's reduction holds at every {} the seed tried (a reading of ours: the seed states "
                            "the reduction over its tables, not per {}).", factor == "step" ? "step size" : "elasticity",
                            factor);
  c.seed_text = theirs;
  c.observed_text = ours + " (the value shown: the level with the weakest reduction)" + (gaps.empty() ? "" : "; left out: " + gaps);
  c.rule = fmt::format("every level: mode3-better's tests at each {} level separately. Support: the largest of the "
                       "levels' one-sided p (an intersection-union test: every level must reject). Refute: the smallest "
                       "of the levels' two-sided p times the number of levels (Bonferroni).{}", factor, kDecision);
  const bool all_tested = !support.empty() && std::none_of(support.begin(), support.end(), [](double p) { return std::isnan(p); });
  if (all_tested) c.p_support = *std::max_element(support.begin(), support.end());
  c.p_refute = bonferroni_min(refute);
  if (support.empty()) c.reason = "no level has a pair";
  return c;
}

Claim mode2_worse(const Context& x) {
  Effect ef;
  SeedEffect se;
  Claim c = mode_claim(x, 2, "mode2-worse", ef, se);
  c.statement = fmt::format("Mode 2 cannot improve on no response: it raises the share of frames with self-contact (the "
                            "seed: higher in {} of {} cells).", se.higher, se.s.n);
  c.rule = direction_rule(ef.pairs, +1, c.seed);
  direction_tests(c, ef.s, +1);
  return c;
}

Claim mode1_marginal(const Context& x) {
  Effect ef;
  SeedEffect se;
  Claim c = mode_claim(x, 1, "mode1-marginal", ef, se);
  c.statement = fmt::format("Mode 1 helps little (the seed: better in {}, worse in {} of {} cells) and is not worth its "
                            "cost: \"no detection at all makes the simulation much lighter\".", se.lower, se.higher, se.s.n);
  c.margin = x.s.margin;
  c.rule = fmt::format(
      "two halves. Effect: equivalence (TOST) of mode 1's relative change per wind seed over the {} cell pairs to 0 "
      "within +-{:.0f}% (the margin, set in advance: {}). Cost: per block of steps of the phase timing, (step + the "
      "seed's all-pairs detection + response) / step, one-sided t tests above (support) and below (refute) {}x "
      "(\"much lighter\"). Support: the larger of the halves' support p (both must hold). Refute: the smaller of the "
      "halves' refute p times 2 (Bonferroni; either half failing refutes).{}",
      ef.pairs, 100.0 * c.margin, kMarginWhy, x.s.much_slower, kDecision);
  if (!take_summary(c, ef.s)) return c;
  Claim effect_half;
  equivalence_tests(effect_half, stats::mean_estimate(ef.s), 0.0, c.margin);
  c.figures = effect_half.figures;
  c.band = effect_half.band + " (effect); >= " + fmt::format("{}x (cost)", x.s.much_slower);
  c.figures.push_back({"cost_ratio", x.cost.observed});
  c.figures.push_back({"cost_ratio_ci95_lo", x.cost.ci95.lo});
  c.figures.push_back({"cost_ratio_ci95_hi", x.cost.ci95.hi});
  c.observed_text += fmt::format("; effect half: support p {:.3g}, refute p {:.3g}; cost half: (step with detection) / "
                                 "(step without) {:.2f} [{:.2f}, {:.2f}], support p {:.3g}, refute p {:.3g}{}",
                                 effect_half.p_support, effect_half.p_refute, x.cost.observed, x.cost.ci95.lo,
                                 x.cost.ci95.hi, x.cost.p_support, x.cost.p_refute,
                                 x.cost.reason.empty() ? "" : " (" + x.cost.reason + ")");
  const bool both = !std::isnan(effect_half.p_support) && !std::isnan(x.cost.p_support);
  c.p_support = both ? std::max(effect_half.p_support, x.cost.p_support) : kNaN;
  c.p_refute = bonferroni_min({effect_half.p_refute, x.cost.p_refute});
  if (std::isnan(x.cost.p_support)) c.reason = "the cost half was not measured: " + x.cost.reason;
  return c;
}

/// The no-response share does not depend on `factor` (levels a against b): a check of ours.
Claim level_claim(const Context& x, const std::string& factor, int a, int b) {
  Claim c;
  c.id = factor + "-level";
  c.detector = contact_test_name(x.e.detectors[x.d]);
  c.family = c.detector;
  c.seed_makes = false;
  c.unit = "relative change";
  c.margin = x.s.margin;
  c.band = fmt::format("+-{:.0f}%", 100.0 * c.margin);
  const Pairs pairs = x.use(factor_pairs(factor, a, b));
  const Effect ef = relative_effect(x.e, x.d, pairs);
  const SeedEffect se = seed_effect(x.seed, pairs);
  const std::string from = factor == "step" ? fmt::format("{} s", CellGrid::steps[b]) : fmt::format("{}", CellGrid::elasticities[b]);
  const std::string to = factor == "step" ? fmt::format("{} s", CellGrid::steps[a]) : fmt::format("{}", CellGrid::elasticities[a]);
  c.statement = fmt::format("Without response, the share of frames with self-contact hardly depends on the {} (the "
                            "seed never says so; its tables are level: {} -> {} changes it by {} on average).", factor,
                            from, to, pct(se.s.mean));
  c.seed = se.s.mean;
  c.seed_text = fmt::format("{}: {} -> {} over {} cells ({} lower, {} higher)", pct(se.s.mean), from, to, se.s.n, se.lower,
                            se.higher);
  c.observed_text = fmt::format("paired 95% interval below 0 in {} of {} cells, above 0 in {}", ef.lower, ef.pairs, ef.higher);
  c.rule = equivalence_rule(ef.pairs, "the relative change " + from + " -> " + to, c.margin, kMarginWhy);
  if (take_summary(c, ef.s)) equivalence_tests(c, stats::mean_estimate(ef.s), 0.0, c.margin);
  return c;
}

/// The seed's own spread: the sd of its values over the three steps of each (wind, elasticity,
/// response), pooled over the 24 groups (the steps barely move our runs, so this is as near as its
/// tables come to repeated runs).
double seed_spread(const SeedTables& seed) {
  double sum = 0.0;
  int groups = 0;
  for (int w = 0; w < CellGrid::kWinds; ++w)
    for (int el = 0; el < CellGrid::kElasticities; ++el)
      for (int m = 0; m < CellGrid::kModes; ++m) {
        std::vector<double> xs;
        for (int st = 0; st < CellGrid::kSteps; ++st) xs.push_back(seed.share[CellGrid::index({w, st, el, m})]);
        const Summary s = summarize(xs);
        if (std::isfinite(s.sd)) sum += s.sd * s.sd, ++groups;
      }
  return groups ? std::sqrt(sum / groups) : kNaN;
}

Claim cells_match(const Context& x) {
  Claim c;
  c.id = "cells-match";
  c.detector = contact_test_name(x.e.detectors[x.d]);
  c.family = c.detector;
  c.seed_makes = false;
  c.unit = "share of cells";
  int n = 0, outside = 0;
  double var_sum = 0.0, width_sum = 0.0;
  std::vector<double> ours, theirs;
  for (int cell = 0; cell < CellGrid::kCells; ++cell) {
    const CellStats cs = cell_stats(x.e, x.d, cell, x.seed);
    if (x.fit[cell] || std::isnan(cs.seed_value) || !cs.s.pi95.defined()) continue;
    ++n;
    outside += !cs.s.pi95.contains(cs.seed_value);
    var_sum += cs.s.sd * cs.s.sd;
    width_sum += cs.s.pi95.hi - cs.s.pi95.lo;
    ours.push_back(cs.s.mean);
    theirs.push_back(cs.seed_value);
  }
  const stats::Correlation rho = stats::spearman(ours, theirs);
  const double run_sd = n ? std::sqrt(var_sum / n) : kNaN, spread = seed_spread(x.seed);
  c.statement = "The seed's cells are single runs of this scene: its values fall where single runs of the ensemble fall, "
                "about 5% of them outside our 95% prediction intervals (a check of ours, on the cells not used by the "
                "calibration).";
  c.seed = 0.05;
  c.seed_text = "0.050: a single run lies outside a 95% prediction interval 5% of the time";
  c.observed = n ? static_cast<double>(outside) / n : kNaN;
  c.ci95 = stats::wilson_interval(outside, n);
  c.n = static_cast<std::size_t>(n);
  c.band = fmt::format("[{}, {}]", x.s.coverage_lo, x.s.coverage_hi);
  c.figures = {{"outside", outside},
               {"cells", n},
               {"spearman", rho.r},
               {"spearman_ci95_lo", rho.ci95.lo},
               {"spearman_ci95_hi", rho.ci95.hi},
               {"pi95_mean_width", n ? width_sum / n : kNaN},
               {"run_sd", run_sd},
               {"seed_spread", spread},
               {"run_sd_over_seed_spread", run_sd / spread}};
  c.observed_text = fmt::format(
      "{} of {} seed values outside our 95% prediction interval of one run; Spearman rank correlation of our cell means "
      "with the seed's values {:.2f} (95% interval [{:.2f}, {:.2f}], Fisher z with variance 1.06 / (n - 3)); our "
      "single-run sd {:.4f} (pooled over the cells; prediction intervals {:.4f} wide on average) against the seed's own "
      "spread {:.4f} (the sd of its values over the three steps of each wind, elasticity and response, pooled): ratio {:.2f}",
      outside, n, rho.r, rho.ci95.lo, rho.ci95.hi, run_sd, n ? width_sum / n : kNaN, spread, run_sd / spread);
  c.rule = fmt::format(
      "coverage: the count k of predicted cells whose seed value lies outside our 95% prediction interval of a single "
      "run (mean +- t sd sqrt(1 + 1/n)), of n. Support: exact binomial equivalence (two one-sided tests) of the rate "
      "to [{}, {}] (set in advance: the rates of a 95% interval whose width is off by a factor of about 4/3 either "
      "way). Refute: the exact two-sided binomial test of the rate 5% (too many outside or too few both refute).{} "
      "Cells share wind realisations, so the p-values are indicative.",
      x.s.coverage_lo, x.s.coverage_hi, kDecision);
  if (n == 0) {
    c.reason = "no cell with a prediction interval (2 seeds needed)";
    return c;
  }
  c.p_support = stats::binomial_tost_p(outside, n, x.s.coverage_lo, x.s.coverage_hi);
  c.p_refute = stats::binomial_two_sided_p(outside, n, 0.05);
  return c;
}

std::vector<Claim> claims_of(const Context& x) {
  std::vector<Claim> out{mode3_better(x), mode3_size(x),  mode3_wind(x),           mode3_every(x, "step"),
                         mode3_every(x, "elasticity"),   mode2_worse(x), mode1_marginal(x),
                         level_claim(x, "elasticity", 1, 0), level_claim(x, "step", 2, 0), cells_match(x)};
  apply_holm(out, x.s.alpha);
  return out;
}

HeldOut held_out_of(const Claim& c) {
  HeldOut h;
  h.computed = true;
  h.observed = c.observed;
  h.ci95 = c.ci95;
  h.n = c.n;
  h.p_support_holm = c.p_support_holm;
  h.p_refute_holm = c.p_refute_holm;
  h.verdict = c.verdict;
  h.reason = c.reason;
  h.observed_text = c.observed_text;
  return h;
}

Claim premise_claim(const Ensemble& e, const Settings& s, const char* id, long long PremiseCount::*num,
                    const std::string& statement, const std::string& what) {
  Claim c;
  c.id = id;
  c.family = "premise";
  c.unit = "share of frames";
  const Summary sh = premise_share(e, num, &PremiseCount::contact_frames);
  c.statement = statement;
  c.seed_text = fmt::format("no number; read as: in at least {} of the frames with a contact", s.majority);
  c.observed_text = fmt::format("share of the frames with an exact contact {}, pooled per seed over the no-response runs", what);
  c.rule = fmt::format("threshold: per wind seed, frames with the property / frames with an exact contact, pooled over the "
                       "no-response cells. Support: one-sided t test over seeds that it lies above {}; refute: below. Both "
                       "Holm-adjusted over the premise's two claims; reproduced if the adjusted support p < 0.05, else not "
                       "reproduced if the adjusted refute p < 0.05, else inconclusive.", s.majority);
  if (take_summary(c, sh)) {
    c.p_support = stats::p_above(stats::mean_estimate(sh), s.majority);
    c.p_refute = stats::p_below(stats::mean_estimate(sh), s.majority);
  }
  return c;
}

}  // namespace

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::Reproduced: return "reproduced";
    case Verdict::NotReproduced: return "not reproduced";
    case Verdict::Inconclusive: return "inconclusive";
  }
  return "inconclusive";
}

Verdict direction_verdict(const Interval& ci, double seed_value, int side) {
  if (!ci.defined()) return Verdict::Inconclusive;
  if (side < 0 ? ci.below(0.0) : ci.above(0.0)) return Verdict::Reproduced;
  if (side < 0 ? ci.above(0.0) : ci.below(0.0)) return Verdict::NotReproduced;
  if (!std::isnan(seed_value) && !ci.contains(seed_value)) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

Verdict negligible_verdict(const Interval& ci, double margin) {
  if (!ci.defined()) return Verdict::Inconclusive;
  if (ci.lo > -margin && ci.hi < margin) return Verdict::Reproduced;
  if (ci.hi < -margin || ci.lo > margin) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

Verdict threshold_verdict(const Interval& ci, double threshold) {
  if (!ci.defined()) return Verdict::Inconclusive;
  if (ci.above(threshold)) return Verdict::Reproduced;
  if (ci.below(threshold)) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

Verdict verdict_from(double p_support_holm, double p_refute_holm, double alpha) {
  if (p_support_holm < alpha) return Verdict::Reproduced;
  if (p_refute_holm < alpha) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

void apply_holm(std::vector<Claim>& claims, double alpha) {
  std::map<std::string, std::vector<std::size_t>> families;
  for (std::size_t k = 0; k < claims.size(); ++k) families[claims[k].family].push_back(k);
  for (const auto& [name, members] : families) {
    std::vector<double> support, refute;
    for (std::size_t k : members) support.push_back(claims[k].p_support), refute.push_back(claims[k].p_refute);
    const auto s = stats::holm_adjust(support), r = stats::holm_adjust(refute);
    for (std::size_t i = 0; i < members.size(); ++i) {
      Claim& c = claims[members[i]];
      c.p_support_holm = s[i];
      c.p_refute_holm = r[i];
      c.verdict = verdict_from(s[i], r[i], alpha);
    }
  }
}

bool take_summary(Claim& c, const Summary& s) {
  c.observed = s.mean;
  c.ci95 = s.ci95;
  c.n = s.n;
  if (s.without_variation()) {
    c.reason = fmt::format("no variation: the {} compared values are identical (sd = 0), a zero-width interval that "
                           "says nothing about the runs", s.n);
    c.ci95 = {kNaN, kNaN};
    return false;
  }
  if (s.n < 2) {
    c.reason = fmt::format("no 95% interval: {} value(s) (2 needed)", s.n);
    return false;
  }
  return true;
}

std::vector<Claim> detector_claims(const Ensemble& e, std::size_t d, const SeedTables& seed, const Settings& s,
                                   const std::array<bool, CellGrid::kCells>& fit, const CostHalf& cost) {
  std::vector<Claim> out = claims_of({e, d, seed, s, fit, cost, false});
  if (std::none_of(fit.begin(), fit.end(), [](bool b) { return b; })) return out;
  const std::vector<Claim> held = claims_of({e, d, seed, s, fit, cost, true});
  for (std::size_t k = 0; k < out.size(); ++k) out[k].held_out = held_out_of(held[k]);
  return out;
}

std::vector<Claim> premise_claims(const Ensemble& e, const Settings& s) {
  std::vector<Claim> out{premise_claim(e, s, "premise-border", &PremiseCount::border_frames,
                                       "The scene provokes self-contacts near the cloth's borders constantly (fig. 21).",
                                       "that have an intersecting triangle on the border"),
                         premise_claim(e, s, "premise-gia-fails", &PremiseCount::unresolved_frames,
                                       "GIA often cannot separate the sides of such a contact: where the intersection "
                                       "reaches the border its flood covers the cloth and no reaction can be computed "
                                       "(section 3.1.3).",
                                       "in which GIA leaves an intersecting pair unresolved")};
  apply_holm(out, s.alpha);
  return out;
}

}  // namespace tecido::suites::self_contact
