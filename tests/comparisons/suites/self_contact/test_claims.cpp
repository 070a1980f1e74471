// comparisons/suites/self_contact/claims.h, ensemble.h, sensitivity.h on planted ensembles: shares
// built from a known none-share per cell and known effects per mode, with seeded noise, so that
// each claim's verdict is known in advance; and each rule on hand-made intervals.
#include "comparisons/suites/self_contact/claims.h"
#include "comparisons/suites/self_contact/sensitivity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido::suites::self_contact {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The seed's own tables (its effects: mode 3 -16.2%, mode 2 +7.1%, mode 1 -1.4%, the 0.1 N contrast +8.1%).
SeedTables seed_tables() { return read_seed_tables(std::string(TECIDO_SOURCE_DIR) + "/data/seed_tables/self_contact_share.json"); }

/// Shares y = base * factor(mode) * (1 + noise), base 0.2 + 0.02 * wind level, one detector.
Ensemble planted(int seeds, const double factor[4], double noise, std::uint64_t rng_seed) {
  Ensemble e(seeds, {ContactTest::Core});
  std::mt19937_64 g(rng_seed);
  for (int c = 0; c < CellGrid::kCells; ++c)
    for (int s = 0; s < seeds; ++s) {
      const double u = static_cast<double>(g() >> 11) * 0x1.0p-53 - 0.5;
      RunResult r;
      const double y = (0.2 + 0.02 * CellGrid::key(c).wind) * factor[CellGrid::key(c).mode] * (1.0 + noise * u);
      r.counts.push_back({10000, std::llround(10000 * y), 0, 0});
      e.add(c, s, &r, nullptr);
    }
  return e;
}

const Claim& find(const std::vector<Claim>& cs, const std::string& id) {
  for (const Claim& c : cs)
    if (c.id == id) return c;
  throw std::runtime_error("no claim " + id);
}

std::array<bool, CellGrid::kCells> no_fit() { return {}; }

TEST(ClaimRules, DirectionSizeNegligibleThreshold) {
  EXPECT_EQ(direction_verdict({-0.3, -0.1}, -0.2, -1), Verdict::Reproduced);
  EXPECT_EQ(direction_verdict({0.1, 0.3}, -0.2, -1), Verdict::NotReproduced);
  EXPECT_EQ(direction_verdict({-0.05, 0.05}, -0.2, -1), Verdict::NotReproduced);  // rules out the seed's -20%
  EXPECT_EQ(direction_verdict({-0.3, 0.05}, -0.2, -1), Verdict::Inconclusive);
  EXPECT_EQ(direction_verdict({0.01, 0.2}, 0.07, +1), Verdict::Reproduced);
  EXPECT_EQ(direction_verdict({kNaN, kNaN}, 0.07, +1), Verdict::Inconclusive);
  EXPECT_EQ(size_verdict({-0.05, 0.04}, -0.16), Verdict::Reproduced);
  EXPECT_EQ(size_verdict({0.02, 0.4}, -0.16), Verdict::NotReproduced);
  EXPECT_EQ(size_verdict({-0.1, 0.3}, -0.16), Verdict::Inconclusive);  // contains 0 and +16%
  EXPECT_EQ(negligible_verdict({-0.04, 0.06}, 0.1), Verdict::Reproduced);
  EXPECT_EQ(negligible_verdict({0.12, 0.3}, 0.1), Verdict::NotReproduced);
  EXPECT_EQ(negligible_verdict({0.05, 0.3}, 0.1), Verdict::Inconclusive);
  EXPECT_EQ(threshold_verdict({2.5, 3.0}, 2.0), Verdict::Reproduced);
  EXPECT_EQ(threshold_verdict({0.5, 1.5}, 2.0), Verdict::NotReproduced);
  EXPECT_EQ(threshold_verdict({1.5, 2.5}, 2.0), Verdict::Inconclusive);
  EXPECT_STREQ(verdict_name(Verdict::NotReproduced), "not reproduced");
}

TEST(Ensemble, RelativeEffectIsThePairedMeanOverSeeds) {
  // One pair (mode 3 cell 3, none cell 0), two seeds: none 0.2, 0.4 (mean 0.3); mode 3 0.1, 0.5.
  Ensemble e(2, {ContactTest::Core});
  auto add = [&](int cell, int seed, double y) {
    RunResult r;
    r.counts.push_back({1000, std::llround(1000 * y), 0, 0});
    e.add(cell, seed, &r, nullptr);
  };
  add(0, 0, 0.2), add(0, 1, 0.4), add(3, 0, 0.1), add(3, 1, 0.5);
  const Effect ef = relative_effect(e, 0, {{3, 0}});
  ASSERT_EQ(ef.per_seed.size(), 2u);
  EXPECT_NEAR(ef.per_seed[0], (0.1 - 0.2) / 0.3, 1e-15);
  EXPECT_NEAR(ef.per_seed[1], (0.5 - 0.4) / 0.3, 1e-15);
  EXPECT_NEAR(ef.s.mean, 0.3 / 0.3 - 1.0, 1e-15);  // mean over seeds = mean_a / mean_b - 1
  EXPECT_EQ(ef.pairs, 1);
  const Effect twice = contrast({&ef, &ef}, {2.0, -0.5});
  EXPECT_NEAR(twice.per_seed[1], 1.5 * ef.per_seed[1], 1e-15);
  // A failed or unstable run leaves its seed out of the pair.
  RunResult bad;
  bad.status = "unstable";
  e.add(3, 1, &bad, nullptr);
  EXPECT_EQ(e.unstable, 1);
  EXPECT_TRUE(std::isnan(relative_effect(e, 0, {{3, 0}}).per_seed[1]));
}

TEST(Claims, PlantedEffectsGiveTheirVerdicts) {
  // Mode 1 changes nothing, mode 2 raises by 15%, mode 3 lowers by 20%; 2% noise; 12 seeds.
  const double f[4] = {1.0, 1.0, 1.15, 0.8};
  const Ensemble e = planted(12, f, 0.02, 1);
  const Settings s;
  const auto cs = detector_claims(e, 0, seed_tables(), s, no_fit());
  EXPECT_EQ(find(cs, "mode3-better").verdict, Verdict::Reproduced);
  EXPECT_NEAR(find(cs, "mode3-better").observed, -0.2, 0.01);
  EXPECT_EQ(find(cs, "mode2-worse").verdict, Verdict::Reproduced);
  EXPECT_EQ(find(cs, "mode1-marginal").verdict, Verdict::Reproduced);
  EXPECT_EQ(find(cs, "mode3-every-step").verdict, Verdict::Reproduced);
  EXPECT_EQ(find(cs, "mode3-every-elasticity").verdict, Verdict::Reproduced);
  EXPECT_EQ(find(cs, "elasticity-level").verdict, Verdict::Reproduced);
  EXPECT_EQ(find(cs, "step-level").verdict, Verdict::Reproduced);
  // No wind dependence planted: the 0.1 N contrast is 0, its interval narrow, the seed's +8% ruled out.
  EXPECT_EQ(find(cs, "mode3-wind").verdict, Verdict::NotReproduced);
  // -20% planted against the seed's -16% +- its cells' spread: consistent, and told apart from none.
  EXPECT_EQ(find(cs, "mode3-size").verdict, Verdict::Reproduced);
  // -50% planted: the size is not the seed's.
  const double big[4] = {1.0, 1.0, 1.15, 0.5};
  EXPECT_EQ(find(detector_claims(planted(12, big, 0.02, 6), 0, seed_tables(), s, no_fit()), "mode3-size").verdict,
            Verdict::NotReproduced);
}

TEST(Claims, ReversedEffectsAreNotReproducedAndNoiseIsInconclusive) {
  const double reversed[4] = {1.0, 1.4, 0.7, 1.25};
  const auto cs = detector_claims(planted(12, reversed, 0.02, 2), 0, seed_tables(), Settings{}, no_fit());
  EXPECT_EQ(find(cs, "mode3-better").verdict, Verdict::NotReproduced);
  EXPECT_EQ(find(cs, "mode2-worse").verdict, Verdict::NotReproduced);
  EXPECT_EQ(find(cs, "mode1-marginal").verdict, Verdict::NotReproduced);
  // Three seeds and +-100% noise: nothing can be decided.
  const double f[4] = {1.0, 1.0, 1.0, 0.9};
  const auto noisy = detector_claims(planted(3, f, 2.0, 3), 0, seed_tables(), Settings{}, no_fit());
  EXPECT_EQ(find(noisy, "mode3-better").verdict, Verdict::Inconclusive);
  // One seed: no interval at all, and the reason says so.
  const Claim one = find(detector_claims(planted(1, f, 0.0, 4), 0, seed_tables(), Settings{}, no_fit()), "mode3-better");
  EXPECT_EQ(one.verdict, Verdict::Inconclusive);
  EXPECT_NE(one.reason.find("2 needed"), std::string::npos) << one.reason;
}

TEST(Claims, CellsMatchCountsSeedValuesOutsideThePredictionInterval) {
  const double f[4] = {1.0, 1.0, 1.0, 1.0};
  const Ensemble e = planted(10, f, 0.2, 5);
  SeedTables inside, outside;
  for (int c = 0; c < CellGrid::kCells; ++c) {
    inside.share[c] = 0.2 + 0.02 * CellGrid::key(c).wind;  // the planted centre
    outside.share[c] = 0.9;                                // far from every run
  }
  auto fit = no_fit();
  for (int c = 0; c < 6; ++c) fit[c] = true;  // left out of the judgement
  const Claim good = find(detector_claims(e, 0, inside, Settings{}, fit), "cells-match");
  EXPECT_EQ(good.verdict, Verdict::Reproduced);
  EXPECT_EQ(good.n, 66u);
  const Claim bad = find(detector_claims(e, 0, outside, Settings{}, fit), "cells-match");
  EXPECT_EQ(bad.verdict, Verdict::NotReproduced);
  EXPECT_DOUBLE_EQ(bad.observed, 1.0);
}

TEST(Claims, PremiseSharesArePooledPerSeed) {
  Ensemble e(3, {ContactTest::Core});
  for (int s = 0; s < 3; ++s)
    for (int c : {0, 4}) {  // two no-response cells
      RunResult r;
      r.counts.push_back({100, 10, 10, 1});
      r.premise = {10, 8 + s % 2, 2, 1};  // border 8 or 9 of 10; GIA fails in 2 of 10
      e.add(c, s, &r, nullptr);
    }
  const auto cs = premise_claims(e, Settings{});
  EXPECT_EQ(find(cs, "premise-border").verdict, Verdict::Reproduced);
  EXPECT_NEAR(find(cs, "premise-border").observed, (0.8 + 0.9 + 0.8) / 3.0, 1e-15);
  EXPECT_EQ(find(cs, "premise-gia-fails").verdict, Verdict::NotReproduced);  // 0.2 in every seed
}

TEST(Sensitivity, RobustFragileUnsettled) {
  auto claim = [](const char* id, Verdict v) {
    Claim c;
    c.id = id;
    c.verdict = v;
    return c;
  };
  const std::vector<SensitivityRow> rows{
      {"baseline", "core", {claim("a", Verdict::Reproduced), claim("b", Verdict::Reproduced), claim("c", Verdict::Inconclusive)}},
      {"v1", "core", {claim("a", Verdict::Reproduced), claim("b", Verdict::NotReproduced), claim("c", Verdict::Reproduced)}},
      {"v2", "core", {claim("a", Verdict::Reproduced), claim("b", Verdict::Inconclusive), claim("c", Verdict::Inconclusive)}}};
  const auto r = robustness(rows);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0].status, "robust");
  EXPECT_EQ(r[1].status, "fragile");
  EXPECT_EQ(r[2].status, "unsettled");
  EXPECT_EQ(r[1].not_reproduced, 1);
  Interpretation base;
  base.strength = 0.05;
  base.swirl_rate = 0.7;
  base.air_drag = 0.01;
  base.heading_diffusion = 0.1;
  ClothGridSpec cloth;
  cloth.rows = cloth.cols = 16;
  const auto vs = variants(base, cloth, true);
  EXPECT_EQ(vs.front().id, "baseline");
  EXPECT_EQ(variants(base, cloth, false).size(), 1u);
  for (const Variant& v : vs) {
    int changed = (v.in.elasticity_as != base.elasticity_as) + (v.in.wind_per != base.wind_per) +
                  (v.in.strength != base.strength) + (v.in.swirl_rate != base.swirl_rate) + (v.in.air_drag != base.air_drag) +
                  (v.in.heading_diffusion != base.heading_diffusion) + (v.in.pins != base.pins);
    EXPECT_EQ(changed, v.id == "baseline" ? 0 : 1) << v.id;  // one choice at a time
  }
}

}  // namespace
}  // namespace tecido::suites::self_contact
