#include "comparisons/suites/self_contact/experiment.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/scene_json.h"
#include "comparisons/suites/random.h"
#include "comparisons/suites/self_contact/document.h"
#include "comparisons/suites/self_contact/findings.h"
#include "comparisons/suites/self_contact/report.h"
#include "comparisons/suites/self_contact/run.h"
#include "comparisons/suites/self_contact/scene_applier.h"
#include "comparisons/suites/self_contact/statistics.h"
#include "comparisons/suites/self_contact/timing.h"

#include <fmt/format.h>

#include <algorithm>
#include <memory>

namespace tecido::suites::self_contact {

namespace {

std::vector<ContactTest> parse_detectors(const Options& o) {
  std::vector<std::string> names = o.detectors;
  if (names.empty()) names = o.quick || o.calibrate ? std::vector<std::string>{"core-mt"} : std::vector<std::string>{"core-mt", "core"};
  std::vector<ContactTest> out;
  for (const auto& n : names) {
    const auto t = parse_contact_test(n);
    if (!t) throw io::UsageError("--detector: unknown detector \"" + n + "\" (core, core-mt, core-rotation)");
    if (std::find(out.begin(), out.end(), *t) != out.end()) throw io::UsageError("--detector: \"" + n + "\" named twice");
    out.push_back(*t);
  }
  return out;
}

std::vector<int> selected_cells(const Options& o) {
  std::vector<int> out = o.cells;
  if (out.empty())
    for (int c = 0; c < CellGrid::kCells; ++c) out.push_back(c);
  std::vector<bool> seen(CellGrid::kCells, false);
  for (int c : out) {
    if (c < 0 || c >= CellGrid::kCells) throw io::UsageError(fmt::format("--runs: cell index {} is outside 0..71", c));
    if (seen[c]) throw io::UsageError(fmt::format("--runs: cell {} is named twice", c));
    seen[c] = true;
  }
  return out;
}

Interpretation baseline_reading(const Options& o, const Scene& base) {
  Interpretation in = scene_interpretation(base);
  if (!o.elasticity_as.empty()) {
    if (o.elasticity_as != "stiffness" && o.elasticity_as != "restitution")
      throw io::UsageError("--elasticity-as must be stiffness or restitution");
    in.elasticity_as = o.elasticity_as;
  }
  if (o.strength >= 0.0) in.strength = o.strength;
  return in;
}

void list_cases(Plan& p) {
  const int seeds = p.settings.seeds;
  if (p.opt.calibrate) {
    const int points = static_cast<int>(p.settings.drag_grid.size() * p.settings.rate_grid.size());
    for (int g = 0; g < points; ++g)
      for (int c : calibration_cells(p.settings))
        for (int s = 0; s < seeds; ++s) p.cases.push_back({CaseSpec::Calibration, 0, c, s, g});
    return;
  }
  if (p.all_cells) {
    p.cases.push_back({CaseSpec::TriTriTiming, 0, 0, 0, 0});
    p.cases.push_back({CaseSpec::PhaseTiming, 0, 0, 0, 0});
  }
  for (int v = 0; v < static_cast<int>(p.variants.size()); ++v)
    for (int c : p.cells) {
      if (p.variants[v].reuses_none && CellGrid::key(c).mode == 0) continue;  // the baseline's runs
      for (int s = 0; s < seeds; ++s) p.cases.push_back({CaseSpec::Run, v, c, s, 0});
    }
}

std::uint64_t wind_seed(const Plan& p, const CaseSpec& c) {
  const std::uint64_t stream = c.kind == CaseSpec::Calibration ? kCalibrationStream : 0;
  return substream(p.base.seed, stream + static_cast<std::uint64_t>(c.seed));
}

/// The cell the timing cases run: wind 0.1 N, 100 steps per second, elasticity 0.9.
int timing_cell(int mode) { return CellGrid::index({1, 1, 0, mode}); }

}  // namespace

Plan make_plan(const Options& o) {
  if (o.seeds < 0) throw io::UsageError("--seeds must be >= 1");
  Plan p;
  p.opt = o;
  p.settings = settings(o.quick);
  if (o.seeds > 0) p.settings.seeds = o.seeds;
  p.detectors = parse_detectors(o);
  p.cells = selected_cells(o);
  p.all_cells = o.cells.empty() || p.cells.size() == static_cast<std::size_t>(CellGrid::kCells);
  p.base = io::load_scene(o.scene_path);
  check_base_scene(p.base, o.scene_path);
  p.seed = read_seed_tables(o.seed_table_path);
  p.baseline = baseline_reading(o, p.base);
  if (!o.calibrate) {
    p.calibration = read_calibration(o.calibration_path);
    p.baseline.air_drag = p.calibration.air_drag;
    p.baseline.swirl_rate = p.calibration.swirl_rate;
  }
  if (!is_sensitivity_set(o.sensitivity)) throw io::UsageError("--sensitivity must be none, strength or all");
  p.variants = variants(p.baseline, *p.base.cloth, o.quick || o.calibrate ? "none" : o.sensitivity);
  list_cases(p);
  return p;
}

Scene run_case_scene(const Plan& p, const CaseSpec& c) {
  return apply_cell(p.base, CellGrid::cell(c.cell), p.variants.at(static_cast<std::size_t>(c.variant)).in, wind_seed(p, c),
                    p.settings.simulated_time);
}

namespace {

io::Json run_one(const Plan& p, const CaseSpec& c) {
  const double T = p.settings.simulated_time;
  const Cell cell = CellGrid::cell(c.cell);
  io::Json j;
  if (c.kind == CaseSpec::Calibration) {
    Interpretation in = p.baseline;
    const GridPoint g = grid_point(p.settings, c.grid);
    in.air_drag = g.air_drag;
    in.swirl_rate = g.swirl_rate;
    j = run_json(run_scene(apply_cell(p.base, cell, in, wind_seed(p, c), T), {ContactTest::CoreMt}, false), false);
  } else {
    const bool premise = cell.mode == 0;
    const Scene s = run_case_scene(p, c);
    j = run_json(run_scene(s, p.detectors, premise), premise);
  }
  j["case"] = {static_cast<int>(c.kind), c.variant, c.cell, c.seed, c.grid};
  return j;
}

io::Json run_timing(const Plan& p, const CaseSpec& c) {
  const bool tritri = c.kind == CaseSpec::TriTriTiming;
  const Cell cell = CellGrid::cell(timing_cell(tritri ? 0 : 3));
  const Scene s = apply_cell(p.base, cell, p.baseline, wind_seed(p, c), p.settings.simulated_time);
  io::Json j = tritri ? time_tri_tri(s, p.settings) : time_phases(s, p.settings);
  j["case"] = {static_cast<int>(c.kind), c.variant, c.cell, c.seed, c.grid};
  return j;
}

std::vector<GridPoint> calibration_points(const Plan& plan, const std::vector<io::Json>& results) {
  const auto cells = calibration_cells(plan.settings);
  const std::size_t points = plan.settings.drag_grid.size() * plan.settings.rate_grid.size();
  std::vector<std::vector<std::vector<double>>> shares(points, std::vector<std::vector<double>>(cells.size()));
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const CaseSpec& c = plan.cases[k];
    if (c.kind != CaseSpec::Calibration || case_error(results[k])) continue;
    const RunResult r = run_from_json(results[k]);
    const auto at = std::find(cells.begin(), cells.end(), c.cell) - cells.begin();
    if (r.status == "ok") shares[c.grid][at].push_back(share(r, 0));
  }
  std::vector<GridPoint> out;
  for (std::size_t g = 0; g < points; ++g) {
    GridPoint p = grid_point(plan.settings, static_cast<int>(g));
    for (const auto& xs : shares[g]) p.means.push_back(summarize(xs).mean);
    p.sse = objective(p, cells, plan.seed);
    out.push_back(p);
  }
  return out;
}

}  // namespace

Sweep make_sweep(const std::shared_ptr<const Plan>& plan) {
  Sweep s;
  s.cases = plan->cases.size();
  s.run_case = [plan](std::size_t k) {
    const CaseSpec& c = plan->cases[k];
    if (c.kind == CaseSpec::TriTriTiming || c.kind == CaseSpec::PhaseTiming) return run_timing(*plan, c);
    return run_one(*plan, c);
  };
  return s;
}

Outputs assemble(const Plan& plan, const std::vector<io::Json>& results) {
  Outputs out;
  if (plan.opt.calibrate) {
    std::vector<GridPoint> points = calibration_points(plan, results);
    const std::string cmd = command_line(plan.opt);
    out.files.push_back({"calibration.json", calibration_json(points, plan.settings, plan.baseline, cmd, plan.opt.quick)});
    out.files.push_back({"calibration.md", calibration_markdown(points, plan.settings, plan.seed, cmd)});
    const int b = best_point(points);
    out.summary = b < 0 ? "no fit" : fmt::format("fit: air drag {} kg/s, swirl rate {} rad/s", points[b].air_drag, points[b].swirl_rate);
    return out;
  }
  const Findings f = find(plan, results);
  out.files.push_back({"experiment.json", experiment_json(plan, f, results)});
  out.files.push_back({"experiment.md", experiment_markdown(plan, f)});
  out.summary = verdict_summary(f);
  return out;
}

std::string command_line(const Options& o) {
  std::string cmd = "tecido experiment self-contact";
  if (o.calibrate) cmd += " --calibrate";
  if (o.quick) cmd += " --quick";
  if (o.seeds > 0) cmd += fmt::format(" --seeds {}", o.seeds);
  if (!o.detectors.empty()) {
    cmd += " --detector ";
    for (std::size_t k = 0; k < o.detectors.size(); ++k) cmd += (k ? "," : "") + o.detectors[k];
  }
  if (!o.cells.empty()) {
    cmd += " --runs ";
    for (std::size_t k = 0; k < o.cells.size(); ++k) cmd += fmt::format("{}{}", k ? "," : "", o.cells[k]);
  }
  if (o.sensitivity != "strength" && !o.quick && !o.calibrate) cmd += " --sensitivity " + o.sensitivity;
  if (!o.elasticity_as.empty()) cmd += " --elasticity-as " + o.elasticity_as;
  if (o.strength >= 0.0) cmd += fmt::format(" --strength {}", o.strength);
  return cmd;
}

}  // namespace tecido::suites::self_contact
