#pragma once
/// report.json and report.md from suite results. report.json:
/// {"seed":S,"quick":bool,"tolerances":"file","suites":[{"name","checks":[{"name","value",
///  "expected":[lo,hi],"pass"}],"data":{...},"seconds":s}]}. report.md opens with a one-screen
/// summary (per suite: checks passed/failed; the worst check and its margin), then each suite's
/// section. Both are written atomically.
#include "comparisons/suites/suite.h"

#include <vector>

namespace tecido::suites {

io::Json report_json(const std::vector<SuiteResult>& results, const SuiteContext& ctx);
std::string report_markdown(const std::vector<SuiteResult>& results, const SuiteContext& ctx);
/// Relative margin of a check: min(value - lo, hi - value) / (hi - lo) (or absolute when the
/// band has zero width); negative when the check fails, -inf for NaN.
double check_margin(const Check& c);
/// Writes out_dir/report.json and out_dir/report.md. Returns the number of failed checks.
int write_report(const std::vector<SuiteResult>& results, const SuiteContext& ctx);

}  // namespace tecido::suites
