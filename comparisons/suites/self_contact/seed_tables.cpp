#include "comparisons/suites/self_contact/seed_tables.h"

#include "comparisons/io/json_reader.h"

#include <cmath>
#include <limits>

namespace tecido::suites::self_contact {

namespace {

/// The level index of `value` among `levels`, or -1.
template <std::size_t N>
int level(const std::array<double, N>& levels, double value) {
  for (std::size_t i = 0; i < N; ++i)
    if (std::abs(levels[i] - value) <= 1e-9 * std::abs(levels[i])) return static_cast<int>(i);
  return -1;
}

void read_row(const io::JsonReader& rd, const io::Json& row, const std::string& where, int wind, SeedTables& out) {
  rd.require_object(row, where);
  const double sps = rd.number(rd.require(row, where, "steps_per_second"), io::child(where, "steps_per_second"));
  const int step = level(CellGrid::steps, 1.0 / sps);
  if (step < 0) rd.fail(io::child(where, "steps_per_second"), "not one of the experiment's 50, 100, 200");
  const int e = level(CellGrid::elasticities, rd.number(rd.require(row, where, "elasticity"), io::child(where, "elasticity")));
  if (e < 0) rd.fail(io::child(where, "elasticity"), "not one of the experiment's 0.9, 0.5");
  static const char* const columns[4] = {"none", "mode1", "mode2", "mode3"};
  for (int m = 0; m < 4; ++m)
    if (row.contains(columns[m]))
      out.share[CellGrid::index({wind, step, e, m})] = rd.number_in(row[columns[m]], io::child(where, columns[m]), 0.0, 1.0);
}

}  // namespace

SeedTables read_seed_tables(const std::string& path) {
  SeedTables out;
  out.file = path;
  out.share.fill(std::numeric_limits<double>::quiet_NaN());
  const io::Json doc = io::read_json_file(path);
  const io::JsonReader rd(path);
  rd.require_object(doc, "");
  const io::Json& tables = rd.require_array(rd.require(doc, "", "tables"), "/tables");
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const std::string wt = io::child("/tables", t);
    rd.require_object(tables[t], wt);
    const int wind = level(CellGrid::winds, rd.number(rd.require(tables[t], wt, "wind"), io::child(wt, "wind")));
    if (wind < 0) rd.fail(io::child(wt, "wind"), "not one of the experiment's 0.09, 0.1, 0.11");
    const io::Json& rows = rd.require_array(rd.require(tables[t], wt, "rows"), io::child(wt, "rows"));
    for (std::size_t r = 0; r < rows.size(); ++r) read_row(rd, rows[r], io::child(io::child(wt, "rows"), r), wind, out);
  }
  return out;
}

}  // namespace tecido::suites::self_contact
