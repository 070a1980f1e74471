#pragma once
/// experiment.md of the self-contact experiment, in this order: the claims table per counting
/// detector (statement, the seed's value, ours with its 95% interval, verdict), what reproduces
/// under which reading (sentences built from the verdicts), the rules, the calibration (fit and
/// prediction agreement), the sensitivity table, the 72 cells with intervals beside the seed's
/// values, plots (cell shares with intervals and the seed's values; effect sizes), the method.
/// Every number in it is computed from the findings; plots are written under plan.opt.out_dir
/// through gnuplot when it is available.
#include "comparisons/suites/self_contact/findings.h"

#include <string>

namespace tecido::suites::self_contact {

std::string experiment_markdown(const Plan& plan, const Findings& f);

/// "claims: R reproduced, N not reproduced, I inconclusive" over the baseline's claims.
std::string verdict_summary(const Findings& f);

}  // namespace tecido::suites::self_contact
