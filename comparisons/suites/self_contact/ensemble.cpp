#include "comparisons/suites/self_contact/ensemble.h"
#include "comparisons/suites/self_contact/statistics.h"

#include <cmath>
#include <limits>

namespace tecido::suites::self_contact {

namespace {


std::vector<double> finite(const std::vector<double>& xs) {
  std::vector<double> out;
  for (double x : xs)
    if (!std::isnan(x)) out.push_back(x);
  return out;
}

double cell_mean(const Ensemble& e, std::size_t d, int cell) { return summarize(finite(e.share[d][cell])).mean; }

}  // namespace

Ensemble::Ensemble(int n, std::vector<ContactTest> tests) : seeds(n), detectors(std::move(tests)) {
  share.resize(detectors.size());
  for (auto& by_cell : share)
    for (auto& v : by_cell) v.assign(static_cast<std::size_t>(seeds), kNaN);
  for (auto& v : premise) v.assign(static_cast<std::size_t>(seeds), PremiseCount{});
}

void Ensemble::add(int cell, int seed, const RunResult* r, const std::string* error) {
  ran[cell] = true;
  ++runs;
  for (auto& by_cell : share) by_cell[cell][seed] = kNaN;
  premise[cell][seed] = PremiseCount{};
  if (error) {
    errors.push_back(*error);
    return;
  }
  if (r->status != "ok") {
    ++unstable;
    return;
  }
  for (std::size_t d = 0; d < detectors.size(); ++d) share[d][cell][seed] = self_contact::share(*r, d);
  premise[cell][seed] = r->premise;
}

CellStats cell_stats(const Ensemble& e, std::size_t d, int cell, const SeedTables& seed) {
  CellStats c;
  c.cell = cell;
  const std::vector<double> xs = finite(e.share[d][cell]);
  c.s = summarize(xs);
  c.seed_value = seed.share[cell];
  c.seed_percentile = std::isnan(c.seed_value) ? kNaN : mid_percentile(xs, c.seed_value);
  return c;
}

Effect relative_effect(const Ensemble& e, std::size_t d, const std::vector<std::pair<int, int>>& pairs) {
  Effect out;
  std::vector<double> ref(pairs.size());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    ref[p] = cell_mean(e, d, pairs[p].second);
    if (!(ref[p] > 0.0)) continue;
    ++out.pairs;
    const double mean_a = cell_mean(e, d, pairs[p].first);
    out.mean_lower += mean_a < ref[p];
    out.mean_higher += mean_a > ref[p];
    std::vector<double> diff;
    for (int s = 0; s < e.seeds; ++s) diff.push_back(e.share[d][pairs[p].first][s] - e.share[d][pairs[p].second][s]);
    const Summary ds = summarize(finite(diff));
    out.lower += ds.ci95.below(0.0);
    out.higher += ds.ci95.above(0.0);
  }
  for (int s = 0; s < e.seeds; ++s) {
    double sum = 0.0;
    int used = 0;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const double a = e.share[d][pairs[p].first][s], b = e.share[d][pairs[p].second][s];
      if (!(ref[p] > 0.0) || std::isnan(a) || std::isnan(b)) continue;
      sum += (a - b) / ref[p];
      ++used;
    }
    out.per_seed.push_back(used ? sum / used : kNaN);
  }
  out.s = summarize(finite(out.per_seed));
  return out;
}

Effect contrast(const std::vector<const Effect*>& effects, const std::vector<double>& weights) {
  Effect out;
  const std::size_t n = effects.empty() ? 0 : effects.front()->per_seed.size();
  for (std::size_t s = 0; s < n; ++s) {
    double v = 0.0;
    for (std::size_t k = 0; k < effects.size(); ++k) v += weights[k] * effects[k]->per_seed[s];
    out.per_seed.push_back(v);
  }
  for (const Effect* e : effects) out.pairs += e->pairs;
  out.s = summarize(finite(out.per_seed));
  return out;
}

SeedEffect seed_effect(const SeedTables& seed, const std::vector<std::pair<int, int>>& pairs) {
  SeedEffect out;
  std::vector<double> rel;
  for (const auto& [a, b] : pairs) {
    const double ya = seed.share[a], yb = seed.share[b];
    if (std::isnan(ya) || !(yb > 0.0)) continue;
    rel.push_back((ya - yb) / yb);
    out.lower += ya < yb;
    out.higher += ya > yb;
  }
  out.s = summarize(rel);
  return out;
}

std::vector<std::pair<int, int>> mode_pairs(int mode, int wind, int step, int elasticity) {
  std::vector<std::pair<int, int>> out;
  for (int w = 0; w < CellGrid::kWinds; ++w)
    for (int st = 0; st < CellGrid::kSteps; ++st)
      for (int el = 0; el < CellGrid::kElasticities; ++el) {
        if ((wind >= 0 && w != wind) || (step >= 0 && st != step) || (elasticity >= 0 && el != elasticity)) continue;
        out.emplace_back(CellGrid::index({w, st, el, mode}), CellGrid::index({w, st, el, 0}));
      }
  return out;
}

std::vector<std::pair<int, int>> factor_pairs(const std::string& factor, int a, int b) {
  std::vector<std::pair<int, int>> out;
  for (int w = 0; w < CellGrid::kWinds; ++w)
    for (int st = 0; st < CellGrid::kSteps; ++st)
      for (int el = 0; el < CellGrid::kElasticities; ++el) {
        if (factor == "elasticity" && el == 0) out.emplace_back(CellGrid::index({w, st, a, 0}), CellGrid::index({w, st, b, 0}));
        if (factor == "step" && st == 0) out.emplace_back(CellGrid::index({w, a, el, 0}), CellGrid::index({w, b, el, 0}));
      }
  return out;
}

Summary premise_share(const Ensemble& e, long long PremiseCount::*num, long long PremiseCount::*den) {
  std::vector<double> per_seed;
  for (int s = 0; s < e.seeds; ++s) {
    long long n = 0, d = 0;
    for (int c = 0; c < CellGrid::kCells; ++c) {
      if (CellGrid::key(c).mode != 0) continue;
      n += e.premise[c][s].*num;
      d += e.premise[c][s].*den;
    }
    if (d > 0) per_seed.push_back(static_cast<double>(n) / static_cast<double>(d));
  }
  return summarize(per_seed);
}

}  // namespace tecido::suites::self_contact
