#pragma once
/// The runs of one reading of the experiment gathered by (detector, cell, seed), and what is
/// computed from them: each cell's summary with the seed's value placed against it, and effects
/// (a relative change between paired cells) per wind seed, so that their intervals treat the
/// wind realisation as the unit of replication (every cell of one seed index sees the same wind).
#include "comparisons/suites/self_contact/grid.h"
#include "comparisons/suites/self_contact/run.h"
#include "comparisons/suites/self_contact/seed_tables.h"
#include "comparisons/suites/self_contact/statistics.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace tecido::suites::self_contact {

struct Ensemble {
  int seeds = 0;
  std::vector<ContactTest> detectors;
  /// share[d][cell][seed]: the run's share of frames with contact; NaN when the run is missing
  /// (not selected), went unstable or failed.
  std::vector<std::array<std::vector<double>, CellGrid::kCells>> share;
  /// premise[cell][seed], no-response cells only (zero elsewhere).
  std::array<std::vector<PremiseCount>, CellGrid::kCells> premise;
  std::array<bool, CellGrid::kCells> ran{};  ///< the cell was selected
  int runs = 0, unstable = 0;
  std::vector<std::string> errors;           ///< cases that threw: "case k threw: ..."

  Ensemble(int seeds, std::vector<ContactTest> detectors);
  /// Records the run of (cell, seed), or its failure when `error` is not null.
  void add(int cell, int seed, const RunResult* r, const std::string* error);
};

/// One cell for one detector: the ensemble's summary and the seed's value placed against it.
struct CellStats {
  int cell = 0;
  Summary s;
  double seed_value = 0.0;       ///< NaN when the tables have none
  double seed_percentile = 0.0;  ///< mid-rank of the seed's value among the runs
};
CellStats cell_stats(const Ensemble& e, std::size_t d, int cell, const SeedTables& seed);

/// A relative effect over pairs (a, b) of cells: per seed s, the mean over the pairs of
/// (y_a,s - y_b,s) / mean_b, where mean_b is b's ensemble mean (pairs with mean_b = 0 or either run
/// missing are left out). Its mean over seeds is the mean over pairs of mean_a / mean_b - 1.
struct Effect {
  std::vector<double> per_seed;  ///< one value per seed; NaN where the seed has no usable pair
  Summary s;                     ///< over the seeds with a value
  int pairs = 0;                 ///< pairs with mean_b > 0
  int lower = 0, higher = 0;     ///< pairs whose paired 95% interval of y_a - y_b lies below / above 0
  int mean_lower = 0, mean_higher = 0;  ///< pairs with mean_a < mean_b / mean_a > mean_b (the seed's count)
};
Effect relative_effect(const Ensemble& e, std::size_t d, const std::vector<std::pair<int, int>>& pairs);

/// The per-seed combination sum_k w_k x_k,s of effects over the same seeds (a contrast); NaN for
/// a seed where any of them is; lower/higher are not set.
Effect contrast(const std::vector<const Effect*>& effects, const std::vector<double>& weights);

/// The seed's own effect over the same pairs: one value (seed_a - seed_b) / seed_b per pair with
/// both values; n = pairs; its spread over pairs is the only spread the seed offers.
struct SeedEffect {
  Summary s;
  int lower = 0, higher = 0;
};
SeedEffect seed_effect(const SeedTables& seed, const std::vector<std::pair<int, int>>& pairs);

/// Pairs (mode cell, its no-response cell) over every (wind, step, elasticity), optionally only
/// those with the given wind / step / elasticity level (-1 = any).
std::vector<std::pair<int, int>> mode_pairs(int mode, int wind = -1, int step = -1, int elasticity = -1);
/// Pairs (no-response cell at level a, the same at level b) of one factor: "elasticity" (levels
/// 0..1) or "step" (0..2), over the other factors.
std::vector<std::pair<int, int>> factor_pairs(const std::string& factor, int a, int b);

/// A share of frames pooled per seed over the no-response cells: sum of num / sum of den.
Summary premise_share(const Ensemble& e, long long PremiseCount::*num, long long PremiseCount::*den);

}  // namespace tecido::suites::self_contact
