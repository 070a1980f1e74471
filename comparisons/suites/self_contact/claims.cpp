#include "comparisons/suites/self_contact/claims.h"
#include "comparisons/suites/self_contact/statistics.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace tecido::suites::self_contact {

namespace {


bool defined(const Interval& ci) { return !std::isnan(ci.lo) && !std::isnan(ci.hi); }

std::string pct(double x) { return std::isnan(x) ? "n/a" : fmt::format("{:+.1f}%", 100.0 * x); }
std::string pct_interval(const Interval& ci) {
  return defined(ci) ? fmt::format("[{}, {}]", pct(ci.lo), pct(ci.hi)) : "n/a";
}

/// Sets the verdict, and the reason when the interval could not be computed.
void decide(Claim& c, Verdict v) {
  c.verdict = v;
  if (!defined(c.ci95)) c.reason = fmt::format("no 95% interval: {} value(s) (2 needed)", c.n);
}

std::string direction_rule(int pairs, int side, double seed_value) {
  const char* mine = side < 0 ? "below" : "above";
  const char* other = side < 0 ? "above" : "below";
  return fmt::format(
      "direction: per wind seed, the mean over the {} cell pairs of (share - reference share) / reference cell mean; "
      "95% t interval over seeds (the seed index is the unit of replication: all cells of one index see the same wind). "
      "Reproduced if the interval lies {} 0; not reproduced if it lies {} 0, or contains 0 but not the seed's own value "
      "{}; inconclusive otherwise.",
      pairs, mine, other, pct(seed_value));
}

std::string negligible_rule(int pairs, double margin) {
  return fmt::format(
      "negligible: the relative change per wind seed over the {} cell pairs, 95% t interval over seeds. Reproduced if "
      "the interval lies inside +-{:.0f}% (the smallest gain the seed reports as a gain); not reproduced if it lies "
      "wholly outside; inconclusive otherwise.",
      pairs, 100.0 * margin);
}

/// A claim on the relative effect of mode m against no response.
Claim mode_claim(const Ensemble& e, std::size_t d, const SeedTables& seed, int mode, const char* id) {
  Claim c;
  c.id = id;
  c.detector = contact_test_name(e.detectors[d]);
  c.unit = "relative change";
  const auto pairs = mode_pairs(mode);
  const Effect ef = relative_effect(e, d, pairs);
  const SeedEffect se = seed_effect(seed, pairs);
  c.seed = se.s.mean;
  c.seed_text = fmt::format("{}: {} lower and {} higher than no response in {} cells", pct(se.s.mean), se.lower, se.higher,
                            se.s.n);
  c.observed = ef.s.mean;
  c.ci95 = ef.s.ci95;
  c.n = ef.s.n;
  c.observed_text = fmt::format("cell means lower in {} of {} cells, higher in {}; paired 95% interval below 0 in {}, "
                                "above 0 in {}", ef.mean_lower, ef.pairs, ef.mean_higher, ef.lower, ef.higher);
  return c;
}

Claim mode3_better(const Ensemble& e, std::size_t d, const SeedTables& seed) {
  Claim c = mode_claim(e, d, seed, 3, "mode3-better");
  const SeedEffect se = seed_effect(seed, mode_pairs(3));
  c.statement = fmt::format("Mode 3 lowers the share of frames with self-contact against no response (the seed: "
                            "lower in {} of {} cells).", se.lower, se.s.n);
  c.rule = direction_rule(static_cast<int>(mode_pairs(3).size()), -1, c.seed);
  decide(c, direction_verdict(c.ci95, c.seed, -1));
  return c;
}

Claim mode3_size(const Ensemble& e, std::size_t d, const SeedTables& seed) {
  Claim c = mode_claim(e, d, seed, 3, "mode3-size");
  const SeedEffect se = seed_effect(seed, mode_pairs(3));
  c.statement = "Mode 3 avoids about 20% of the frames with self-contact (the seed's abstract and conclusion: \"20%\", "
                "\"up to 20%\"; section 3.1.3: about 10% at 0.1 N and near 20% at the other winds).";
  const Effect ef = relative_effect(e, d, mode_pairs(3));
  const Interval diff = welch_ci95(ef.s.mean, ef.s.se, ef.s.n, se.s.mean, se.s.se, se.s.n);
  c.observed_text += fmt::format("; ours - the seed's: 95% CI {}", pct_interval(diff));
  c.rule = fmt::format(
      "size: Welch's 95% interval of (our mean relative change - the seed's {}), our standard error over seeds, the "
      "seed's over its {} cells (the only spread it offers). Not reproduced if it excludes 0; reproduced if it contains "
      "0 but not {} (our effect told apart from none); inconclusive otherwise.",
      pct(se.s.mean), se.s.n, pct(-se.s.mean));
  decide(c, size_verdict(diff, se.s.mean));
  if (!defined(diff) && c.reason.empty()) c.reason = "no interval of the difference";
  return c;
}

Claim mode3_wind(const Ensemble& e, std::size_t d, const SeedTables& seed) {
  Claim c;
  c.id = "mode3-wind";
  c.detector = contact_test_name(e.detectors[d]);
  c.unit = "difference of relative changes";
  Effect by_wind[3];
  double seed_by_wind[3];
  for (int w = 0; w < 3; ++w) {
    by_wind[w] = relative_effect(e, d, mode_pairs(3, w));
    seed_by_wind[w] = seed_effect(seed, mode_pairs(3, w)).s.mean;
  }
  const Effect g = contrast({&by_wind[1], &by_wind[0], &by_wind[2]}, {1.0, -0.5, -0.5});
  c.statement = "Mode 3's gain is smaller at 0.1 N (about 10%) than at 0.09 and 0.11 N (about 20%).";
  c.seed = seed_by_wind[1] - 0.5 * (seed_by_wind[0] + seed_by_wind[2]);
  c.seed_text = fmt::format("{}: {} at 0.09 N, {} at 0.1 N, {} at 0.11 N", pct(c.seed), pct(seed_by_wind[0]),
                            pct(seed_by_wind[1]), pct(seed_by_wind[2]));
  c.observed = g.s.mean;
  c.ci95 = g.s.ci95;
  c.n = g.s.n;
  c.observed_text = fmt::format("{} at 0.09 N, {} at 0.1 N, {} at 0.11 N", pct(by_wind[0].s.mean), pct(by_wind[1].s.mean),
                                pct(by_wind[2].s.mean));
  c.rule = "contrast E(0.1 N) - (E(0.09 N) + E(0.11 N)) / 2 of mode 3's relative change, per wind seed; " +
           direction_rule(static_cast<int>(mode_pairs(3).size()), +1, c.seed);
  decide(c, direction_verdict(c.ci95, c.seed, +1));
  return c;
}

/// Mode 3 lowers the share at every level of `factor` ("step" or "elasticity").
Claim mode3_every(const Ensemble& e, std::size_t d, const SeedTables& seed, const std::string& factor) {
  Claim c;
  c.id = "mode3-every-" + factor;
  c.detector = contact_test_name(e.detectors[d]);
  c.unit = "relative change";
  const int levels = factor == "step" ? CellGrid::kSteps : CellGrid::kElasticities;
  int repro = 0, not_repro = 0;
  std::string ours, theirs;
  c.observed = -std::numeric_limits<double>::infinity();
  for (int l = 0; l < levels; ++l) {
    const auto pairs = factor == "step" ? mode_pairs(3, -1, l) : mode_pairs(3, -1, -1, l);
    const Effect ef = relative_effect(e, d, pairs);
    const SeedEffect se = seed_effect(seed, pairs);
    const Verdict v = direction_verdict(ef.s.ci95, se.s.mean, -1);
    repro += v == Verdict::Reproduced;
    not_repro += v == Verdict::NotReproduced;
    const std::string level = factor == "step" ? fmt::format("{} steps/s", CellGrid::cell(CellGrid::index({0, l, 0, 0})).steps_per_second())
                                               : fmt::format("elasticity {}", CellGrid::elasticities[l]);
    ours += fmt::format("{}{}: {} {} ({})", l ? "; " : "", level, pct(ef.s.mean), pct_interval(ef.s.ci95), verdict_name(v));
    theirs += fmt::format("{}{}: {}", l ? "; " : "", level, pct(se.s.mean));
    if (!(ef.s.mean <= c.observed)) c.observed = ef.s.mean, c.ci95 = ef.s.ci95, c.n = ef.s.n;  // the weakest (NaN wins)
  }
  c.statement = fmt::format("Mode 3's reduction holds at every {} the seed tried.", factor == "step" ? "step size" : "elasticity");
  c.seed_text = theirs;
  c.observed_text = ours + " (the value shown: the level with the weakest reduction)";
  c.rule = fmt::format("the direction rule (mode3-better) at each {} level separately; reproduced if every level is, not "
                       "reproduced if any level is not, inconclusive otherwise.", factor);
  c.verdict = repro == levels ? Verdict::Reproduced : not_repro > 0 ? Verdict::NotReproduced : Verdict::Inconclusive;
  if (!defined(c.ci95) && c.verdict == Verdict::Inconclusive) c.reason = "no 95% interval at some level";
  return c;
}

Claim mode2_worse(const Ensemble& e, std::size_t d, const SeedTables& seed) {
  Claim c = mode_claim(e, d, seed, 2, "mode2-worse");
  const SeedEffect se = seed_effect(seed, mode_pairs(2));
  c.statement = fmt::format("Mode 2 cannot improve on no response: it raises the share of frames with self-contact (the "
                            "seed: higher in {} of {} cells).", se.higher, se.s.n);
  c.rule = direction_rule(static_cast<int>(mode_pairs(2).size()), +1, c.seed);
  decide(c, direction_verdict(c.ci95, c.seed, +1));
  return c;
}

Claim mode1_marginal(const Ensemble& e, std::size_t d, const SeedTables& seed, double margin) {
  Claim c = mode_claim(e, d, seed, 1, "mode1-marginal");
  const SeedEffect se = seed_effect(seed, mode_pairs(1));
  c.statement = fmt::format("Mode 1 helps little (the seed: better in {}, worse in {} of {} cells) and is not worth its "
                            "cost, since no detection at all makes the simulation much lighter.", se.lower, se.higher, se.s.n);
  c.rule = negligible_rule(static_cast<int>(mode_pairs(1).size()), margin) +
           " The cost half is measured by detection-dominates-step (the share of a step spent detecting).";
  decide(c, negligible_verdict(c.ci95, margin));
  return c;
}

/// The no-response share does not depend on `factor` (levels a against b).
Claim level_claim(const Ensemble& e, std::size_t d, const SeedTables& seed, const std::string& factor, int a, int b,
                  double margin) {
  Claim c;
  c.id = factor + "-level";
  c.detector = contact_test_name(e.detectors[d]);
  c.unit = "relative change";
  const auto pairs = factor_pairs(factor, a, b);
  const Effect ef = relative_effect(e, d, pairs);
  const SeedEffect se = seed_effect(seed, pairs);
  const std::string from = factor == "step" ? fmt::format("{} s", CellGrid::steps[b]) : fmt::format("{}", CellGrid::elasticities[b]);
  const std::string to = factor == "step" ? fmt::format("{} s", CellGrid::steps[a]) : fmt::format("{}", CellGrid::elasticities[a]);
  c.statement = fmt::format("Without response, the share of frames with self-contact hardly depends on the {} (the "
                            "seed's tables are level: {} -> {} changes it by {} on average).", factor, from, to, pct(se.s.mean));
  c.seed = se.s.mean;
  c.seed_text = fmt::format("{}: {} -> {} over {} cells ({} lower, {} higher)", pct(se.s.mean), from, to, se.s.n, se.lower,
                            se.higher);
  c.observed = ef.s.mean;
  c.ci95 = ef.s.ci95;
  c.n = ef.s.n;
  c.observed_text = fmt::format("paired 95% interval below 0 in {} of {} cells, above 0 in {}", ef.lower, ef.pairs, ef.higher);
  c.rule = negligible_rule(static_cast<int>(pairs.size()), margin);
  decide(c, negligible_verdict(c.ci95, margin));
  return c;
}

Claim cells_match(const Ensemble& e, std::size_t d, const SeedTables& seed, const std::array<bool, CellGrid::kCells>& fit) {
  Claim c;
  c.id = "cells-match";
  c.detector = contact_test_name(e.detectors[d]);
  c.unit = "share of cells";
  int n = 0, outside = 0;
  std::vector<double> ours, theirs;
  for (int cell = 0; cell < CellGrid::kCells; ++cell) {
    const CellStats cs = cell_stats(e, d, cell, seed);
    if (fit[cell] || std::isnan(cs.seed_value) || !defined(cs.s.pi95)) continue;
    ++n;
    outside += !cs.s.pi95.contains(cs.seed_value);
    ours.push_back(cs.s.mean);
    theirs.push_back(cs.seed_value);
  }
  const double p = binomial_upper_tail(outside, n, 0.05);
  c.statement = "The seed's cells are single runs of this scene: its values fall where single runs of the ensemble fall "
                "(cells not used by the calibration).";
  c.seed = 0.05;
  c.seed_text = "0.050: a single run lies outside a 95% prediction interval 5% of the time";
  c.observed = n ? static_cast<double>(outside) / n : kNaN;
  c.ci95 = wilson_ci95(outside, n);
  c.n = static_cast<std::size_t>(n);
  c.observed_text = fmt::format("{} of {} seed values outside our 95% prediction interval of one run (binomial p = {:.3g}); "
                                "correlation of cell means with the seed's values {:.2f}", outside, n, p, pearson(ours, theirs));
  c.rule = "the seed's value of each predicted cell against our 95% prediction interval of a single run (mean +- t sd "
           "sqrt(1 + 1/n)); reproduced if the count outside is what chance allows (one-sided binomial p >= 0.05 at "
           "rate 5%), not reproduced otherwise. Cells share wind realisations, so p is indicative.";
  c.verdict = n == 0 ? Verdict::Inconclusive : p >= 0.05 ? Verdict::Reproduced : Verdict::NotReproduced;
  if (n == 0) c.reason = "no cell with a prediction interval (2 seeds needed)";
  return c;
}

Claim premise_claim(const Ensemble& e, const Settings& s, const char* id, long long PremiseCount::*num,
                    const std::string& statement, const std::string& what) {
  Claim c;
  c.id = id;
  c.unit = "share of frames";
  const Summary sh = premise_share(e, num, &PremiseCount::contact_frames);
  c.statement = statement;
  c.seed_text = fmt::format("no number; read as: in at least {} of the frames with a contact", s.majority);
  c.observed = sh.mean;
  c.ci95 = sh.ci95;
  c.n = sh.n;
  c.observed_text = fmt::format("share of the frames with an exact contact {}, pooled per seed over the no-response runs", what);
  c.rule = fmt::format("threshold: per wind seed, frames with the property / frames with an exact contact, pooled over the "
                       "no-response cells; 95% t interval over seeds. Reproduced if it lies above {}; not reproduced if below; "
                       "inconclusive otherwise.", s.majority);
  decide(c, threshold_verdict(c.ci95, s.majority));
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
  if (!defined(ci)) return Verdict::Inconclusive;
  if (side < 0 ? ci.below(0.0) : ci.above(0.0)) return Verdict::Reproduced;
  if (side < 0 ? ci.above(0.0) : ci.below(0.0)) return Verdict::NotReproduced;
  if (!std::isnan(seed_value) && !ci.contains(seed_value)) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

Verdict size_verdict(const Interval& difference, double seed_value) {
  if (!defined(difference)) return Verdict::Inconclusive;
  if (!difference.contains(0.0)) return Verdict::NotReproduced;
  return difference.contains(-seed_value) ? Verdict::Inconclusive : Verdict::Reproduced;
}

Verdict negligible_verdict(const Interval& ci, double margin) {
  if (!defined(ci)) return Verdict::Inconclusive;
  if (ci.lo > -margin && ci.hi < margin) return Verdict::Reproduced;
  if (ci.hi < -margin || ci.lo > margin) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

Verdict threshold_verdict(const Interval& ci, double threshold) {
  if (!defined(ci)) return Verdict::Inconclusive;
  if (ci.above(threshold)) return Verdict::Reproduced;
  if (ci.below(threshold)) return Verdict::NotReproduced;
  return Verdict::Inconclusive;
}

std::vector<Claim> detector_claims(const Ensemble& e, std::size_t d, const SeedTables& seed, const Settings& s,
                                   const std::array<bool, CellGrid::kCells>& fit) {
  return {mode3_better(e, d, seed),
          mode3_size(e, d, seed),
          mode3_wind(e, d, seed),
          mode3_every(e, d, seed, "step"),
          mode3_every(e, d, seed, "elasticity"),
          mode2_worse(e, d, seed),
          mode1_marginal(e, d, seed, s.margin),
          level_claim(e, d, seed, "elasticity", 1, 0, s.margin),
          level_claim(e, d, seed, "step", 2, 0, s.margin),
          cells_match(e, d, seed, fit)};
}

std::vector<Claim> premise_claims(const Ensemble& e, const Settings& s) {
  return {premise_claim(e, s, "premise-border", &PremiseCount::border_frames,
                        "The scene provokes self-contacts near the cloth's borders constantly (fig. 21).",
                        "that have an intersecting triangle on the border"),
          premise_claim(e, s, "premise-gia-fails", &PremiseCount::unresolved_frames,
                        "GIA often cannot separate the sides of such a contact: where the intersection reaches the border "
                        "its flood covers the cloth and no reaction can be computed (section 3.1.3).",
                        "in which GIA leaves an intersecting pair unresolved")};
}

}  // namespace tecido::suites::self_contact
