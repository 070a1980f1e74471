#include "comparisons/suites/tradeoff/points.h"

#include "comparisons/suites/sweep.h"
#include "comparisons/suites/tradeoff/distances.h"
#include "comparisons/suites/tradeoff/pareto.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::tradeoff {

namespace {

/// One point from its case result.
Point measured(const TradeoffEngine& e, std::size_t ei, std::size_t j, double h, const io::Json& result,
               const std::optional<std::vector<Vec3>>& ref, const Settings& s) {
  Point p;
  p.engine = ei;
  p.step = j;
  p.h = h;
  if (const std::string* err = case_error(result)) {
    p.status = *err;
    return p;
  }
  p.rerun_diff = get_num(result.at("rerun_diff"));
  std::optional<std::vector<Vec3>> x = positions_of(result);
  if (!x) {
    const std::string reason = result.at("reason").get<std::string>();
    const std::string not_built = "not built: ";  // the engine refused the scene or could not be built
    if (reason.rfind(not_built, 0) == 0) p.status = reason.substr(not_built.size());
    else p.status = "unstable (" + (reason.empty() ? std::string("failed") : reason) + ")";
    return p;
  }
  p.x = std::move(*x);
  p.cost = get_num(result.at("seconds")) / s.seconds;
  p.evals = e.evaluations_per_step > 0 ? e.evaluations_per_step / h : NAN;
  p.error = ref ? rms_distance(p.x, *ref) : NAN;
  p.counted = std::isfinite(p.error) && p.error <= s.max_error;
  if (p.counted) p.status = "counted";
  else if (!ref) p.status = "not measured (no reference)";
  else p.status = fmt::format("unstable (error > {:g} m)", s.max_error);
  return p;
}

}  // namespace

std::vector<Point> size_points(const CaseLayout& layout, std::size_t si, const std::vector<double>& swept,
                               const std::vector<TradeoffEngine>& engines, const std::vector<io::Json>& results,
                               const std::optional<std::vector<Vec3>>& ref, const Settings& s) {
  std::vector<Point> pts;
  for (std::size_t e = 0; e < engines.size(); ++e) {
    for (std::size_t j = 0; j < swept.size(); ++j) {
      const io::Json& r = results.at(layout.point_case(si, e, j));
      if (r.is_object() && r.contains("skipped")) continue;  // outside the engine's range
      pts.push_back(measured(engines[e], e, j, swept[j], r, ref, s));
    }
  }
  return pts;
}

std::vector<int> front_of(const std::vector<Point>& points) {
  std::vector<CostError> ce;
  std::vector<int> idx;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    if (!points[i].counted) continue;
    ce.push_back({points[i].cost, points[i].error});
    idx.push_back(i);
  }
  std::vector<int> front;
  for (int f : pareto_front(ce)) front.push_back(idx[f]);
  return front;
}

std::string h_label(double h) {
  const double e = std::log2(h);
  if (e == std::round(e)) return fmt::format("2^{}", static_cast<int>(e));
  return fmt::format("{:.3g}", h);
}

}  // namespace tecido::suites::tradeoff
