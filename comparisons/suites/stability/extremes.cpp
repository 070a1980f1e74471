#include "comparisons/suites/stability/extremes.h"

#include "comparisons/suites/sweep.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace tecido::suites::stability {

VerdictBands verdict_bands(const Tolerances& tol) {
  return {{"ratio", tol.between("/stability/ratio_lo", "/stability/ratio_hi")},
          {"rest_jitter", tol.at_most("/stability/rest_max_jitter")},
          {"offset_degraded", tol.at_most("/stability/offset_degraded_fraction")}};
}

std::string verdict(const ExtremeRow& row, const VerdictBands& bands) {
  if (!row.judge) return row.verdict;
  const auto it = bands.find(row.judge->band);
  if (it == bands.end()) throw std::logic_error("unknown verdict band: " + row.judge->band);
  for (double v : row.judge->values)
    if (!(std::isfinite(v) && v >= it->second.lo && v <= it->second.hi)) return row.judge->out;
  return row.judge->ok;
}

void ExtremeResult::from_range(const std::string& check, const ValueRange& range, double value) {
  if (range.complete()) {
    set(check, value);
  } else {
    fail(check, range.reason());
  }
}

namespace {
io::Json row_json(const ExtremeRow& r) {
  io::Json j{{"group", r.group}, {"case", r.label}, {"measured", r.measured}, {"verdict", r.verdict}};
  if (r.judge) {
    io::Json values = io::Json::array();
    for (double v : r.judge->values) values.push_back(num(v));
    j["judge"] = {{"band", r.judge->band}, {"values", values}, {"ok", r.judge->ok}, {"out", r.judge->out}};
  }
  return j;
}

ExtremeRow row_from_json(const io::Json& j) {
  ExtremeRow r{j.at("group").get<std::string>(), j.at("case").get<std::string>(), j.at("measured").get<std::string>(),
               j.at("verdict").get<std::string>(), std::nullopt};
  if (j.contains("judge")) {
    const io::Json& g = j.at("judge");
    ExtremeRow::Judge judge{g.at("band").get<std::string>(), {}, g.at("ok").get<std::string>(), g.at("out").get<std::string>()};
    for (const io::Json& v : g.at("values")) judge.values.push_back(get_num(v));
    r.judge = judge;
  }
  return r;
}
}  // namespace

io::Json result_json(const ExtremeResult& r) {
  io::Json rows = io::Json::array(), outcomes = io::Json::array();
  for (const ExtremeRow& row : r.rows) rows.push_back(row_json(row));
  for (const Outcome& o : r.outcomes) outcomes.push_back({{"check", o.check}, {"value", num(o.value)}, {"reason", o.reason}});
  return {{"rows", rows}, {"outcomes", outcomes}, {"data", r.data}};
}

ExtremeResult result_from_json(const io::Json& j) {
  ExtremeResult r;
  for (const io::Json& row : j.at("rows")) r.rows.push_back(row_from_json(row));
  for (const io::Json& o : j.at("outcomes"))
    r.outcomes.push_back({o.at("check").get<std::string>(), get_num(o.at("value")), o.at("reason").get<std::string>()});
  r.data = j.at("data");
  return r;
}

std::string extremes_check(const std::string& what) { return "stability/extremes/" + what; }

std::string sci(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "NaN" : "inf";
  return fmt::format("{:.3g}", x);
}

}  // namespace tecido::suites::stability
