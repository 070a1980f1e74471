#include "comparisons/suites/self_contact/findings.h"

#include "comparisons/suites/self_contact/timing.h"

#include <cmath>

namespace tecido::suites::self_contact {

namespace {

void gather(const Plan& plan, const std::vector<io::Json>& results, Findings& f) {
  for (std::size_t v = 0; v < plan.variants.size(); ++v) f.ensembles.emplace_back(plan.settings.seeds, plan.detectors);
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const CaseSpec& c = plan.cases[k];
    const std::string* err = case_error(results[k]);
    if (err) f.errors.push_back(*err);
    if (c.kind == CaseSpec::TriTriTiming && !err) f.tritri = results[k];
    if (c.kind == CaseSpec::PhaseTiming && !err) f.phases = results[k];
    if (c.kind != CaseSpec::Run) continue;
    const RunResult r = err ? RunResult{} : run_from_json(results[k]);
    for (std::size_t v = 0; v < plan.variants.size(); ++v) {
      const bool shared = c.variant == 0 && plan.variants[v].reuses_none && CellGrid::key(c.cell).mode == 0;
      if (static_cast<int>(v) == c.variant || shared) f.ensembles[v].add(c.cell, c.seed, err ? nullptr : &r, err);
    }
  }
}

/// Why the timing claims have no data: not run, or their case threw.
std::string timing_gap(const Plan& plan, const Findings& f) {
  if (!plan.all_cells) return "not measured: only some cells were run (--runs)";
  if (f.tritri.is_null() || f.phases.is_null()) return "a timing case threw (see the errors)";
  return "";
}

}  // namespace

Findings find(const Plan& plan, const std::vector<io::Json>& results) {
  Findings f;
  gather(plan, results, f);
  const std::string gap = timing_gap(plan, f);
  const CostHalf cost = detection_cost(f.phases.is_null() ? nullptr : &f.phases, plan.settings, gap);
  for (std::size_t d = 0; d < plan.detectors.size(); ++d) {
    const auto c = detector_claims(f.ensembles[0], d, plan.seed, plan.settings, plan.calibration.fit, cost);
    f.claims.insert(f.claims.end(), c.begin(), c.end());
  }
  for (const Claim& c : premise_claims(f.ensembles[0], plan.settings)) f.claims.push_back(c);
  for (const Claim& c : timing_claims(f.tritri.is_null() ? nullptr : &f.tritri, f.phases.is_null() ? nullptr : &f.phases,
                                      plan.settings, gap))
    f.claims.push_back(c);
  if (plan.variants.size() > 1) {
    for (std::size_t v = 0; v < plan.variants.size(); ++v)
      for (std::size_t d = 0; d < plan.detectors.size(); ++d) {
        SensitivityRow row{plan.variants[v].id, contact_test_name(plan.detectors[d]),
                           detector_claims(f.ensembles[v], d, plan.seed, plan.settings, plan.calibration.fit, cost)};
        if (d == 0)
          for (const Claim& c : premise_claims(f.ensembles[v], plan.settings)) row.claims.push_back(c);
        f.rows.push_back(std::move(row));
      }
    f.robustness = robustness(f.rows);
  }
  return f;
}

std::vector<CellStats> baseline_cells(const Plan& plan, const Findings& f, std::size_t d) {
  std::vector<CellStats> out;
  for (int c = 0; c < CellGrid::kCells; ++c) out.push_back(cell_stats(f.ensembles[0], d, c, plan.seed));
  return out;
}

Agreement agreement(const std::vector<CellStats>& cells, const std::array<bool, CellGrid::kCells>& fit, bool fitted) {
  Agreement a;
  std::vector<double> ours, theirs;
  double abs_sum = 0.0, sq_sum = 0.0;
  for (const CellStats& c : cells) {
    if (fit[c.cell] != fitted || std::isnan(c.s.mean) || std::isnan(c.seed_value)) continue;
    ++a.cells;
    a.inside_pi95 += c.s.pi95.contains(c.seed_value);
    const double d = c.s.mean - c.seed_value;
    abs_sum += std::abs(d);
    sq_sum += d * d;
    ours.push_back(c.s.mean);
    theirs.push_back(c.seed_value);
  }
  a.mean_abs_diff = a.cells ? abs_sum / a.cells : std::nan("");
  a.rms_diff = a.cells ? std::sqrt(sq_sum / a.cells) : std::nan("");
  a.correlation = pearson(ours, theirs);
  return a;
}

}  // namespace tecido::suites::self_contact
