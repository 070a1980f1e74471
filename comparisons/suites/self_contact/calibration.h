#pragma once
/// The declared calibration of the experiment's two free parameters that are set to match the
/// seed: air drag and the wind's swirl rate (`tecido experiment self-contact --calibrate`).
/// Fitted on the no-response cells at one step (Settings::calibration_step: 100 steps per
/// second, 6 cells), with wind seeds of their own (Settings' kCalibrationStream), counted with
/// the seed's detector (core-mt, what its tables counted): for every (drag, rate) of the grid,
/// each fit cell's mean share over the seeds; the objective is the sum over the fit cells of
/// (mean - the seed's value)^2; the fit is the grid point with the least objective (the first in
/// grid order on a tie). Every other cell of the experiment is then a prediction.
/// The record (calibration.json) is what the experiment reads (--calibration, by default
/// data/seed_tables/self_contact_calibration.json, a copy of the command's output).
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/self_contact/grid.h"
#include "comparisons/suites/self_contact/interpretation.h"
#include "comparisons/suites/self_contact/seed_tables.h"
#include "comparisons/suites/self_contact/settings.h"

#include <array>
#include <string>
#include <vector>

namespace tecido::suites::self_contact {

/// The cells the calibration fits: no response at the calibration step, in index order.
std::vector<int> calibration_cells(const Settings& s);

/// What the experiment needs from a calibration record.
struct CalibrationRecord {
  std::string file;
  double air_drag = 0.0, swirl_rate = 0.0;
  std::array<bool, CellGrid::kCells> fit{};  ///< the cells it was fitted on
  io::Json doc;                              ///< the whole record, echoed into experiment.json
};

/// Reads a record written by --calibrate; throws io::InputError naming the file and pointer.
CalibrationRecord read_calibration(const std::string& path);

/// One grid point's result.
struct GridPoint {
  double air_drag = 0.0, swirl_rate = 0.0;
  std::vector<double> means;  ///< per fit cell (NaN when no run of it finished)
  double sse = 0.0;           ///< the objective (NaN when a mean is missing)
};

/// Grid point g of the settings' grid (drag-major).
GridPoint grid_point(const Settings& s, int g);
/// The objective of `p` against the seed's values of `cells`.
double objective(const GridPoint& p, const std::vector<int>& cells, const SeedTables& seed);
/// The index of the best point (least finite sse; first on ties); -1 when none is finite.
int best_point(const std::vector<GridPoint>& points);

/// calibration.json: the record (see the file comment); `base` is the reading the fit varied.
std::string calibration_json(const std::vector<GridPoint>& points, const Settings& s, const Interpretation& base,
                             const std::string& command, bool quick);
/// calibration.md: the grid's objective table and the fit.
std::string calibration_markdown(const std::vector<GridPoint>& points, const Settings& s, const SeedTables& seed,
                                 const std::string& command);

}  // namespace tecido::suites::self_contact
