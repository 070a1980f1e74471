#pragma once
/// The `stability` suite's report: its settings, the method and theory paragraphs, one table per
/// measurement, the extremes table (its notes: extremes_notes.h). Every number in it is computed in the
/// run (from the settings, the theory or the tables); each stated conclusion is derived from the
/// table it summarises.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/stability/extremes.h"
#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/stability/tables.h"

#include <string>
#include <vector>

namespace tecido::suites::stability {

/// Where the settings live and what they were in this run.
std::string settings_markdown(const Settings& s);
/// The oscillator, the definition of "stable at h", the bisection and the linear-stability theory.
std::string method_markdown(const Settings& s);

/// The heading of the largest-stable-step tables, with each bounded integrator's limit.
std::string grid_heading(const Settings& s);
/// One bounded integrator's grid table and its summary (and, for symplectic Euler, how far the cells
/// lie from the bound-limited prediction).
std::string grid_markdown(const Settings& s, const GridTable& t);
/// The growers' growth per period against theory.
std::string growth_markdown(const Settings& s, const std::vector<GrowthTable>& tables);
/// The growers' horizon-limited step and whether it shrinks with the run length.
std::string horizon_markdown(const Settings& s, const std::vector<HorizonTable>& tables);

/// The extremes table, judged verdicts decided against `bands`.
std::string extremes_markdown(const std::vector<ExtremeRow>& rows, const VerdictBands& bands);

/// The tables as report.json data.
io::Json grid_data(const GridTable& t);
io::Json growth_data(const GrowthTable& t);
io::Json horizon_data(const HorizonTable& t);

}  // namespace tecido::suites::stability
