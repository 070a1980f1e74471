#pragma once
/// The `stability` suite's tables, computed from the case results: the largest stable step of each
/// bounded integrator over the grid, the growers' growth per period and their horizon-limited step.
/// Each table carries the ranges its checks take their values from (value_range.h): a case that
/// threw, a cell with no stable step, an unstable run or a NaN leaves its range incomplete, with a
/// reason naming the cell.
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/stability/cases.h"
#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/stability/value_range.h"

#include <cmath>
#include <string>
#include <vector>

namespace tecido::suites::stability {

/// "ks = 10 N/m, m = 1 kg"
std::string cell_name(double ks, double m);

struct GridCell {
  double ks = 0.0, m = 0.0;
  double h = NAN;        ///< largest stable step [s]
  double h_omega = NAN;  ///< h omega
  int runs = 0;
  std::string missing;   ///< why there is no value ("" when there is)
};
struct GridTable {
  IntegratorKind kind = IntegratorKind::Symplectic;
  double limit = 0.0;            ///< theory: stable_limit(kind)
  std::vector<GridCell> cells;   ///< stiffness-major
  ValueRange ratio;              ///< h omega / limit over the cells
  ValueRange h_omega;            ///< h omega over the cells
  int runs = 0;                  ///< simulation runs of every bisection
};
/// The table of settings.bounded[kind] from every case's result (indexed by `l`).
GridTable grid_table(const Settings& s, const Layout& l, std::size_t kind, const std::vector<io::Json>& results);

struct GrowthRow {
  double c = 0.0;
  double theory = 0.0;  ///< growth_per_period(kind, c)
  ValueRange growth;    ///< measured growth per period over the grid
  ValueRange error;     ///< |ln measured / ln theory - 1| over the grid
};
struct GrowthTable {
  IntegratorKind kind = IntegratorKind::Euler;
  std::vector<GrowthRow> rows;  ///< one per c
  ValueRange worst;             ///< error over every row
};
GrowthTable growth_table(const Settings& s, const Layout& l, std::size_t grower, const std::vector<io::Json>& results);

struct HorizonRow {
  double periods = 0.0;
  double measured = NAN;  ///< largest "stable" h omega over `periods` periods (omega = 1)
  double predicted = 0.0; ///< horizon_prediction
  double ratio = NAN;
  std::string missing;
};
struct HorizonTable {
  IntegratorKind kind = IntegratorKind::Euler;
  std::vector<HorizonRow> rows;  ///< one per horizon, in the settings' order
  ValueRange ratio;
};
HorizonTable horizon_table(const Settings& s, const Layout& l, std::size_t grower, const std::vector<io::Json>& results);

}  // namespace tecido::suites::stability
