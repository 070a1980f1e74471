#pragma once
/// The project's speed goals (settings.h Goals) against one run of the `bench` suite: one row per
/// goal, its value computed from the named benchmark rows (tecido-bench's and the timed
/// `selfcollide` processes', process_cost.h), the target, and whether it is met. A goal whose rows
/// are missing from the run is "not measured" (value NaN), never met.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/bench/benchmark_json.h"
#include "comparisons/suites/bench/settings.h"

#include <string>
#include <vector>

namespace tecido::suites::bench {

struct GoalRow {
  std::string id;     ///< stable key, e.g. "continuous_128_over_discrete" (report.json)
  std::string what;   ///< what is measured (the report's table)
  double value;       ///< NaN when not measured
  double target;
  bool at_least;      ///< met when value >= target; otherwise when value <= target
  std::string unit;   ///< "" (a ratio or a count), "ms", "ns"
  std::string from;   ///< the rows it is computed from, and how
  bool measured() const;
  bool met() const;
};

/// Every goal, in the order of the report.
std::vector<GoalRow> goal_rows(const std::vector<BenchRow>& rows, const Settings& s, const Goals& g);

/// report.json's "goals": [{"id", "what", "value" (null: not measured), "target", "comparison"
/// ("at_most" | "at_least"), "unit", "met" (null: not measured), "from"}, ...].
io::Json goals_json(const std::vector<GoalRow>& goals);

}  // namespace tecido::suites::bench
