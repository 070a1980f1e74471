#pragma once
/// What the experiment's assembly computes from its case results, before anything is written:
/// the ensemble of each reading, the baseline's claims, the sensitivity rows and the timing cases'
/// raw results. The writers (document.h, report.h) only format these.
#include "comparisons/suites/self_contact/claims.h"
#include "comparisons/suites/self_contact/ensemble.h"
#include "comparisons/suites/self_contact/experiment.h"
#include "comparisons/suites/self_contact/sensitivity.h"

#include <string>
#include <vector>

namespace tecido::suites::self_contact {

struct Findings {
  std::vector<Ensemble> ensembles;       ///< per reading, Plan::variants' order (baseline first)
  std::vector<Claim> claims;             ///< the baseline's: per detector, then premise, then timing
  std::vector<SensitivityRow> rows;      ///< per (reading, detector); empty without variants
  std::vector<Robustness> robustness;    ///< per claim id over the rows
  io::Json tritri, phases;               ///< the timing cases' results (null when not run or failed)
  std::vector<std::string> errors;       ///< every case that threw, "case k threw: ..."
};

/// Computes the findings of a plan's case results (in case order).
Findings find(const Plan& plan, const std::vector<io::Json>& results);

/// The cells' summaries of the baseline for detector d (72, in index order).
std::vector<CellStats> baseline_cells(const Plan& plan, const Findings& f, std::size_t d);

/// How our cell means agree with the seed's values on one set of cells (the calibration's fit
/// cells, or the others: the predictions).
struct Agreement {
  int cells = 0;            ///< cells with a mean and a seed value
  int inside_pi95 = 0;      ///< ... whose seed value lies inside our 95% prediction interval
  double mean_abs_diff = 0.0, rms_diff = 0.0, correlation = 0.0;
};
Agreement agreement(const std::vector<CellStats>& cells, const std::array<bool, CellGrid::kCells>& fit, bool fitted);

}  // namespace tecido::suites::self_contact
