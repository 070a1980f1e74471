#include "comparisons/suites/order/convergence.h"

#include "comparisons/suites/sweep.h"

#include <chrono>
#include <cmath>
#include <limits>

namespace tecido::suites::order {

Sample run_once(const Problem& p, const OrderEngine& engine, double h) {
  Scene s = p.scene;
  s.dt = h;
  const long long n = std::llround(p.T / h);
  const auto t0 = std::chrono::steady_clock::now();
  auto e = engine.make(s);
  const bool ok = e->advance(n);  // an outside engine takes the n steps in one call of its door
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!ok) return {h, std::numeric_limits<double>::infinity(), secs};
  const std::vector<Vec3> x = e->positions();
  const std::vector<Vec3> exact = p.exact(e->time());
  double err = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) err = std::max(err, (x[i] - exact[i]).norm());
  return {h, std::isfinite(err) ? err : std::numeric_limits<double>::infinity(), secs};
}

std::vector<Sample> convergence_runs(const Problem& p, const OrderEngine& engine, double h0, int halvings) {
  std::vector<Sample> out;
  for (int j = 0; j <= halvings; ++j) out.push_back(run_once(p, engine, h0 / std::pow(2.0, j)));
  return out;
}

io::Json samples_json(const std::vector<Sample>& s) {
  io::Json a = io::Json::array();
  for (const Sample& x : s) a.push_back({num(x.h), num(x.error), num(x.seconds)});
  return a;
}

std::vector<Sample> samples_from_json(const io::Json& j) {
  std::vector<Sample> out;
  for (const io::Json& x : j) out.push_back({get_num(x.at(0)), get_num(x.at(1)), get_num(x.at(2))});
  return out;
}

}  // namespace tecido::suites::order
