#include "comparisons/suites/self_contact/calibration.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace tecido::suites::self_contact {

std::vector<int> calibration_cells(const Settings& s) {
  std::vector<int> out;
  for (int c = 0; c < CellGrid::kCells; ++c) {
    const CellKey k = CellGrid::key(c);
    if (k.mode == 0 && k.step == s.calibration_step) out.push_back(c);
  }
  return out;
}

CalibrationRecord read_calibration(const std::string& path) {
  CalibrationRecord r;
  r.file = path;
  r.doc = io::read_json_file(path);
  const io::JsonReader rd(path);
  rd.require_object(r.doc, "");
  const io::Json& fitted = rd.require_object(rd.require(r.doc, "", "fitted"), "/fitted");
  r.air_drag = rd.number_in(rd.require(fitted, "/fitted", "air_drag"), "/fitted/air_drag", 0.0, 1e12);
  r.swirl_rate = rd.number(rd.require(fitted, "/fitted", "swirl_rate"), "/fitted/swirl_rate", 1e6);
  const io::Json& cells = rd.require_array(rd.require(r.doc, "", "fit_cells"), "/fit_cells");
  for (std::size_t k = 0; k < cells.size(); ++k)
    r.fit[rd.integer(cells[k], io::child("/fit_cells", k), 0, CellGrid::kCells - 1)] = true;
  return r;
}

GridPoint grid_point(const Settings& s, int g) {
  GridPoint p;
  const int rates = static_cast<int>(s.rate_grid.size());
  p.air_drag = s.drag_grid[g / rates];
  p.swirl_rate = s.rate_grid[g % rates];
  return p;
}

double objective(const GridPoint& p, const std::vector<int>& cells, const SeedTables& seed) {
  double sse = 0.0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double d = p.means[k] - seed.share[cells[k]];
    sse += d * d;
  }
  return sse;
}

int best_point(const std::vector<GridPoint>& points) {
  int best = -1;
  for (int g = 0; g < static_cast<int>(points.size()); ++g)
    if (std::isfinite(points[g].sse) && (best < 0 || points[g].sse < points[best].sse)) best = g;
  return best;
}

std::string calibration_json(const std::vector<GridPoint>& points, const Settings& s, const Interpretation& base,
                             const std::string& command, bool quick) {
  nlohmann::ordered_json table = nlohmann::ordered_json::array();
  for (const GridPoint& p : points)
    table.push_back({{"air_drag", p.air_drag}, {"swirl_rate", p.swirl_rate},
                     {"sse", std::isfinite(p.sse) ? nlohmann::ordered_json(p.sse) : nlohmann::ordered_json(nullptr)},
                     {"means", p.means}});
  const int b = best_point(points);
  nlohmann::ordered_json doc;
  doc["experiment"] = "self-contact";
  doc["kind"] = "calibration";
  doc["command"] = command;
  doc["quick"] = quick;
  doc["detector"] = "core-mt";
  doc["simulated_time"] = s.simulated_time;
  doc["seeds"] = s.seeds;
  doc["seed_stream"] = kCalibrationStream;
  doc["fit_cells"] = calibration_cells(s);
  doc["objective"] = "sum over the fit cells of (mean share over the seeds - the seed's share)^2";
  doc["grid"] = {{"air_drag", s.drag_grid}, {"swirl_rate", s.rate_grid}};
  doc["interpretation"] = nlohmann::ordered_json::parse(interpretation_json(base).dump());
  doc["table"] = table;
  if (b >= 0) {
    doc["fitted"] = {{"air_drag", points[b].air_drag}, {"swirl_rate", points[b].swirl_rate}, {"sse", points[b].sse}};
  } else {
    doc["fitted"] = nullptr;
  }
  return doc.dump(2) + "\n";
}

std::string calibration_markdown(const std::vector<GridPoint>& points, const Settings& s, const SeedTables& seed,
                                 const std::string& command) {
  const auto cells = calibration_cells(s);
  std::string md = fmt::format(
      "# Calibration of the self-contact experiment\n\n`{}`: air drag x swirl rate over a {} x {} grid, {} wind seeds "
      "per cell (their own stream), {} s per run, counted with core-mt; fitted on the {} no-response cells at {} steps "
      "per second. Objective: sum over those cells of (our mean share - the seed's)^2.\n\n",
      command, s.drag_grid.size(), s.rate_grid.size(), s.seeds, s.simulated_time, cells.size(),
      CellGrid::cell(cells.front()).steps_per_second());
  md += "| air drag | swirl rate | objective |";
  for (int c : cells) md += fmt::format(" {} N, e {} |", CellGrid::cell(c).wind, CellGrid::cell(c).elasticity);
  md += "\n|---:|---:|---:|";
  for (std::size_t k = 0; k < cells.size(); ++k) md += "---:|";
  md += "\n| seed's | | |";
  for (int c : cells) md += fmt::format(" {:.4f} |", seed.share[c]);
  md += "\n";
  for (const GridPoint& p : points) {
    md += fmt::format("| {} | {} | {:.5f} |", p.air_drag, p.swirl_rate, p.sse);
    for (double m : p.means) md += fmt::format(" {:.4f} |", m);
    md += "\n";
  }
  const int b = best_point(points);
  md += b >= 0 ? fmt::format("\n**Fit:** air drag {} kg/s, swirl rate {} rad/s (objective {:.5f}).\n", points[b].air_drag,
                             points[b].swirl_rate, points[b].sse)
               : "\n**No fit:** no grid point has a finite objective.\n";
  return md;
}

}  // namespace tecido::suites::self_contact
