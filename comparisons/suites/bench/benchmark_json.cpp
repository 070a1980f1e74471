#include "comparisons/suites/bench/benchmark_json.h"

#include <cmath>
#include <set>

namespace tecido::suites::bench {

namespace {
double ns_scale(const std::string& unit) {
  return unit == "ns" ? 1.0 : unit == "us" ? 1e3 : unit == "ms" ? 1e6 : 1e9;
}

/// Google Benchmark's own keys; any other number in a row is a user counter.
bool is_own_key(const std::string& key) {
  static const std::set<std::string> own = {
      "name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations", "real_time",
      "cpu_time", "time_unit", "items_per_second", "family_index", "per_family_instance_index", "aggregate_name",
      "bytes_per_second", "label", "error_occurred", "error_message"};
  return own.count(key) != 0;
}
}  // namespace

std::string benchmark_base_name(const std::string& name) {
  static const char* const attributes[] = {"real_time", "process_time", "manual_time", "iterations:", "min_time:", "repeats:"};
  std::string base = name;
  for (bool cut = true; cut;) {
    cut = false;
    const std::size_t slash = base.rfind('/');
    if (slash == std::string::npos) break;
    const std::string last = base.substr(slash + 1);
    for (const char* a : attributes) {
      const std::string attr = a;
      if (attr.back() == ':' ? last.compare(0, attr.size(), attr) == 0 : last == attr) {
        base.resize(slash);
        cut = true;
        break;
      }
    }
  }
  return base;
}

namespace {
bool is_median(const io::Json& b) { return b.value("run_type", "iteration") == "aggregate" && b.value("aggregate_name", "") == "median"; }
std::string run_name(const io::Json& b) { return b.value("run_name", b.value("name", "")); }
}  // namespace

std::vector<BenchRow> parse_benchmark_json(const io::Json& doc) {
  std::vector<BenchRow> rows;
  if (!doc.is_object() || !doc.contains("benchmarks")) return rows;
  std::set<std::string> repeated;  // benchmarks with a median of repetitions: it stands for them
  for (const auto& b : doc["benchmarks"])
    if (is_median(b)) repeated.insert(run_name(b));
  for (const auto& b : doc["benchmarks"]) {
    const bool iteration = b.value("run_type", "iteration") == "iteration";
    if (!(is_median(b) || (iteration && !repeated.count(run_name(b)))) || b.value("error_occurred", false)) continue;
    BenchRow r;
    r.name = run_name(b);
    r.label = b.value("label", "");
    // CPU time: on a machine shared with other work, wall time also counts the time others take
    // (every benchmark here is one thread without I/O, so on an idle machine the two agree).
    r.ns_per_iter = b.value("cpu_time", 0.0) * ns_scale(b.value("time_unit", "ns"));
    r.real_ns_per_iter = b.value("real_time", 0.0) * ns_scale(b.value("time_unit", "ns"));
    if (b.contains("items_per_second") && b["items_per_second"].get<double>() > 0)
      r.ns_per_item = 1e9 / b["items_per_second"].get<double>();
    for (auto it = b.begin(); it != b.end(); ++it)
      if (!is_own_key(it.key()) && it.value().is_number()) r.counters[it.key()] = it.value();
    rows.push_back(std::move(r));
  }
  return rows;
}

const BenchRow* find_row(const std::vector<BenchRow>& rows, const std::string& name) {
  for (const auto& r : rows)
    if (r.name == name || benchmark_base_name(r.name) == name) return &r;
  return nullptr;
}

double ns_per_item(const std::vector<BenchRow>& rows, const std::string& name) {
  const BenchRow* r = find_row(rows, name);
  if (!r) return std::nan("");
  return r->ns_per_item > 0 ? r->ns_per_item : r->ns_per_iter;
}

double ns_per_spring(const BenchRow* row) {
  if (!row || !row->counters.contains("springs")) return std::nan("");
  const double springs = row->counters["springs"].get<double>();
  return springs > 0 ? row->ns_per_iter / springs : std::nan("");
}

}  // namespace tecido::suites::bench
