#include "comparisons/suites/sweep.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/progress.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace tecido::suites {

io::Json num(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

double get_num(const io::Json& j) {
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
  }
  return j.get<double>();  // type_error unless a number
}

io::Json vec3s_json(const std::vector<Vec3>& xs) {
  io::Json a = io::Json::array();
  a.get_ref<io::Json::array_t&>().reserve(3 * xs.size());
  for (const Vec3& x : xs)
    for (int c = 0; c < 3; ++c) a.push_back(num(x[c]));
  return a;
}

std::vector<Vec3> vec3s_from_json(const io::Json& j) {
  if (!j.is_array() || j.size() % 3 != 0)
    throw std::invalid_argument("expected a flat array of 3n coordinates");
  std::vector<Vec3> xs(j.size() / 3);
  for (std::size_t i = 0; i < xs.size(); ++i)
    xs[i] = Vec3(get_num(j[3 * i]), get_num(j[3 * i + 1]), get_num(j[3 * i + 2]));
  return xs;
}

io::Json check_json(const Check& c) {
  return {{"name", c.name}, {"value", num(c.value)}, {"lo", num(c.lo)}, {"hi", num(c.hi)}, {"pass", c.pass},
          {"note", c.note}, {"reason", c.reason}, {"tolerance", c.tolerance}};
}

Check check_from_json(const io::Json& j) {
  Check c;
  c.name = j.at("name").get<std::string>();
  c.value = get_num(j.at("value"));
  c.lo = get_num(j.at("lo"));
  c.hi = get_num(j.at("hi"));
  c.pass = j.at("pass").get<bool>();
  c.note = j.at("note").get<std::string>();
  c.reason = j.at("reason").get<std::string>();
  c.tolerance = j.at("tolerance").get<std::string>();
  return c;
}

const std::string* case_error(const io::Json& result) {
  if (!result.is_object()) return nullptr;
  const auto it = result.find("error");
  return (it != result.end() && it->is_string() && result.size() == 1) ? &it->get_ref<const std::string&>() : nullptr;
}

std::vector<io::Json> run_sweep_cases(const Sweep& sweep, const std::vector<std::size_t>& indices, int threads,
                                      const std::string& label, bool progress) {
  std::unique_ptr<io::Progress> bar;
  if (progress) bar = std::make_unique<io::Progress>(indices.size(), label);
  std::vector<io::Json> results(indices.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr input_error;  // bad input (a data file the case reads) is exit 2, not a result
  std::mutex error_mutex;
  auto worker = [&]() {
    for (;;) {
      const std::size_t k = next.fetch_add(1);
      if (k >= indices.size()) return;
      try {
        // Through the text form, exactly as a shard file carries it to `tecido merge`.
        results[k] = io::Json::parse(sweep.run_case(indices[k]).dump());
      } catch (const io::InputError&) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!input_error) input_error = std::current_exception();
      } catch (const std::exception& e) {
        results[k] = io::Json{{"error", std::string("case ") + std::to_string(indices[k]) + " threw: " + e.what()}};
      }
      if (bar) bar->tick();
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(indices.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (bar) bar->finish();
  if (input_error) std::rethrow_exception(input_error);
  return results;
}

SuiteResult run_sweep(const SweepFn& make, const SuiteContext& ctx, const std::string& name) {
  const Sweep sweep = make(ctx);
  std::vector<std::size_t> all(sweep.cases);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  const std::vector<io::Json> results = run_sweep_cases(sweep, all, ctx.threads, "suite " + name, ctx.progress);
  SuiteResult r = sweep.assemble(results);
  r.name = name;
  return r;
}

}  // namespace tecido::suites
