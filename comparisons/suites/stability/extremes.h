#pragma once
/// What a group of the `stability` suite's extremes returns (rows of the extremes table and the
/// values of the checks it feeds) and how it declares those checks. Each group is one function
/// (offset.h, mass_ratio.h, near_zero.h, resting.h, tunnelling.h), run as one case of the sweep;
/// its result travels as JSON.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/stability/value_range.h"
#include "comparisons/suites/tolerances.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::stability {

/// One row of the extremes table. Most verdicts are settled by the run ("broke: non-finite"); a
/// verdict that depends on a band of the tolerance file is left to the report (`judge`), so a case
/// never reads the tolerance file.
struct ExtremeRow {
  std::string group, label, measured, verdict;
  struct Judge {
    std::string band;            ///< a key of verdict_bands(): "ratio", "rest_jitter", "offset_degraded"
    std::vector<double> values;  ///< ok when every one is inside the band (and finite)
    std::string ok, out;         ///< the verdict either way
  };
  std::optional<Judge> judge;
};

/// The named bands that decide judged verdicts (ExtremeRow::judge), read before anything runs.
using VerdictBands = std::map<std::string, Band>;
VerdictBands verdict_bands(const Tolerances& tol);
/// The row's verdict: its own, or the judge's against `bands` (std::logic_error for an unknown band).
std::string verdict(const ExtremeRow& row, const VerdictBands& bands);

/// A check value a group produced, or the reason it could not ("unstable at step 12 ...").
struct Outcome {
  std::string check;
  double value = 0.0;
  std::string reason;  ///< non-empty: the check fails with it
};

struct ExtremeResult {
  std::vector<ExtremeRow> rows;
  std::vector<Outcome> outcomes;
  io::Json data = io::Json::object();  ///< machine-readable extras for report.json
  void set(const std::string& check, double value) { outcomes.push_back({check, value, {}}); }
  void fail(const std::string& check, const std::string& reason) { outcomes.push_back({check, 0.0, reason}); }
  /// set(check, value) when the range is complete, else fail(check, range.reason()).
  void from_range(const std::string& check, const ValueRange& range, double value);
};

io::Json result_json(const ExtremeResult& r);
ExtremeResult result_from_json(const io::Json& j);

/// A check, declared before anything runs: its name, band (read from the tolerance file) and note.
struct CheckSpec {
  std::string name;
  std::function<Band(const Tolerances&)> band;
  std::string note;
};

/// A group of extremes: its name, the checks it feeds and the function that runs it.
struct ExtremeGroup {
  std::string name;
  std::function<std::vector<CheckSpec>(const Settings&)> checks;
  std::function<ExtremeResult(const Settings&)> run;
};

/// "stability/extremes/<what>"
std::string extremes_check(const std::string& what);

/// "1.5e-08", "NaN", "inf": a measured value in a table cell.
std::string sci(double x);

}  // namespace tecido::suites::stability
