#pragma once
/// report.json and report.md from suite results. report.json:
/// {"tecido":{"version","commit","command_line"} (io/provenance.h),"seed":S,"quick":bool,"tolerances":"file","outside_engines":[{"name","door",...}] (when any),"suites":[{"name","checks":[{"name","value",
///  "expected":[lo,hi],"pass","note"?,"reason"?,"tolerance"?}],"data":{...},"seconds":s}]}. A check
///  without a value has "value": null, "pass": false and its "reason"; an unbounded end of a band is
///  null; "tolerance" names the tolerance-file entries the band came from. report.md opens with a one-screen
/// summary (under a line naming the version, the commit and the command line; per suite: checks passed/failed; the worst check and its margin), the outside engines
/// with their doors (when any), then each suite's section. Both are written atomically.
#include "comparisons/suites/suite.h"

#include <vector>

namespace tecido::suites {

io::Json report_json(const std::vector<SuiteResult>& results, const SuiteContext& ctx);
std::string report_markdown(const std::vector<SuiteResult>& results, const SuiteContext& ctx);
/// Relative margin of a check: min(value - lo, hi - value) / (hi - lo) (or absolute when the
/// band has zero width); negative when the check fails, -inf for NaN.
double check_margin(const Check& c);
/// Writes out_dir/report.json, out_dir/report.md and out_dir/report.html (report_html.h, with the
/// viewer's files beside it, view/viewer_assets.h). Returns the number of failed checks.
int write_report(const std::vector<SuiteResult>& results, const SuiteContext& ctx);

}  // namespace tecido::suites
