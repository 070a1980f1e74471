#include "comparisons/suites/bench_suite.h"

#include "comparisons/io/atomic_file.h"
#include "comparisons/io/gnuplot.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace tecido::suites {

std::vector<BenchRow> parse_benchmark_json(const io::Json& doc) {
  std::vector<BenchRow> rows;
  if (!doc.contains("benchmarks")) return rows;
  for (const auto& b : doc["benchmarks"]) {
    if (b.value("run_type", "iteration") != "iteration") continue;
    BenchRow r;
    r.name = b.value("run_name", b.value("name", ""));
    const std::string unit = b.value("time_unit", "ns");
    const double scale = unit == "ns" ? 1.0 : unit == "us" ? 1e3 : unit == "ms" ? 1e6 : 1e9;
    r.ns_per_iter = b.value("real_time", 0.0) * scale;
    if (b.contains("items_per_second") && b["items_per_second"].get<double>() > 0)
      r.ns_per_item = 1e9 / b["items_per_second"].get<double>();
    static const char* known[] = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads",
                                  "iterations", "real_time", "cpu_time", "time_unit", "items_per_second",
                                  "family_index", "per_family_instance_index", "aggregate_name", "bytes_per_second",
                                  "label", "error_occurred", "error_message"};
    for (auto it = b.begin(); it != b.end(); ++it) {
      bool k = false;
      for (const char* n : known) k = k || it.key() == n;
      if (!k && it.value().is_number()) r.counters[it.key()] = it.value();
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

namespace {

std::string self_dir() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  buf[n] = 0;
  return std::filesystem::path(buf).parent_path().string();
}

const BenchRow* find(const std::vector<BenchRow>& rows, const std::string& name) {
  for (const auto& r : rows)
    if (r.name == name) return &r;
  return nullptr;
}

std::string goal_row(const std::string& what, double value, double goal, const std::string& unit, bool lower_is_better = true) {
  const bool met = lower_is_better ? value <= goal : value >= goal;
  return fmt::format("| {} | {:.3g}{} | {} {:.3g}{} | {} |\n", what, value, unit, lower_is_better ? "≤" : "≥", goal, unit,
                     met ? "met" : "not met");
}

}  // namespace

SuiteResult run_bench_suite(const SuiteContext& ctx) {
  SuiteResult res;
  res.name = "bench";
  const std::string bin = self_dir() + "/tecido-bench";
  const std::string dir = ctx.out_dir + "/bench";
  std::filesystem::create_directories(dir);
  if (!std::filesystem::exists(bin)) {
    res.markdown = "`tecido-bench` was not found next to `tecido` (built with TECIDO_BENCH=OFF?): no timings.\n";
    return res;
  }
  const std::string json_path = dir + "/bench.json";
  const std::string min_time = ctx.quick ? "0.01" : "0.2";
  const std::string cmd = fmt::format("'{}' --benchmark_format=json --benchmark_out='{}.tmp' --benchmark_min_time={} >/dev/null 2>'{}/bench.stderr'",
                                      bin, json_path, min_time, dir);
  if (std::system(cmd.c_str()) != 0 || !std::filesystem::exists(json_path + ".tmp")) {
    res.markdown = "`tecido-bench` failed; see `bench/bench.stderr`.\n";
    return res;
  }
  std::filesystem::rename(json_path + ".tmp", json_path);
  const io::Json doc = io::read_json_file(json_path);
  const auto rows = parse_benchmark_json(doc);
  std::string md = fmt::format(
      "Google Benchmark, min time {} s per benchmark, one thread, this machine, this run (`bench/bench.json`). Ratios compare "
      "engines measured in the same run. These are measurements, not checks.\n\n",
      min_time);
  if (doc.contains("context")) {
    const auto& c = doc["context"];
    md += fmt::format("Machine: {} CPUs at {} MHz; library build type {}.\n\n", c.value("num_cpus", 0), c.value("mhz_per_cpu", 0),
                      c.value("library_build_type", "?"));
  }
  // Goals of the project (issue: speed versus accuracy).
  md += "### Goals\n\n| goal | measured | target | |\n|---|---:|---:|---|\n";
  auto per_item = [&](const std::string& n) {
    const BenchRow* r = find(rows, n);
    return r ? (r->ns_per_item > 0 ? r->ns_per_item : r->ns_per_iter) : std::nan("");
  };
  const double core_tt = per_item("BM_TriTri/core"), fcl_tt = per_item("BM_TriTri/fcl"), exact_tt = per_item("BM_TriTri/exact");
  if (std::isfinite(core_tt) && std::isfinite(fcl_tt)) md += goal_row("core tri-tri time / FCL's", core_tt / fcl_tt, 0.5, "");
  if (std::isfinite(core_tt) && std::isfinite(exact_tt)) md += goal_row("core tri-tri time / CGAL exact's", core_tt / exact_tt, 1.0, "");
  if (const BenchRow* r = find(rows, "BM_SelfCollision/core/256")) md += goal_row("self-collision 256x256 frame, core, one thread", r->ns_per_iter / 1e6, 10.0, " ms");
  for (int n : {16, 32, 64, 128}) {
    const BenchRow* c = find(rows, fmt::format("BM_ClothStep/core-symplectic/{}", n));
    const BenchRow* b = find(rows, fmt::format("BM_ClothStep/bullet-classic/{}", n));
    if (c && b) md += goal_row(fmt::format("cloth step {}x{}: core symplectic / Bullet classic", n, n), c->ns_per_iter / b->ns_per_iter, 0.25, "");
    if (c && c->counters.contains("springs"))
      md += goal_row(fmt::format("cloth step {}x{}: core ns per spring", n, n), c->ns_per_iter / c->counters["springs"].get<double>(), 3.0, " ns");
    if (b && b->counters.contains("springs"))
      md += fmt::format("| cloth step {}x{}: Bullet classic ns per link | {:.3g} ns | (reference) | |\n", n, n,
                        b->ns_per_iter / b->counters["springs"].get<double>());
  }
  md += "\n### All benchmarks\n\n| benchmark | time per iteration | ns per item |\n|---|---:|---:|\n";
  io::Json data = io::Json::array();
  std::map<std::string, std::string> series;  // "BM_SelfCollision/core" -> "n t\n..."
  for (const auto& r : rows) {
    md += fmt::format("| `{}` | {:.4g} µs | {} |\n", r.name, r.ns_per_iter / 1e3, r.ns_per_item > 0 ? fmt::format("{:.1f}", r.ns_per_item) : "");
    data.push_back({{"name", r.name}, {"ns_per_iteration", r.ns_per_iter}, {"ns_per_item", r.ns_per_item}, {"counters", r.counters}});
    const auto slash = r.name.rfind('/');
    if (slash != std::string::npos && (r.name.rfind("BM_SelfCollision/", 0) == 0 || r.name.rfind("BM_ClothStep/", 0) == 0)) {
      const std::string tail = r.name.substr(slash + 1);
      if (!tail.empty() && std::isdigit(static_cast<unsigned char>(tail[0])))
        series[r.name.substr(0, slash)] += fmt::format("{} {:.9g}\n", tail, r.ns_per_iter / 1e6);
    }
  }
  if (ctx.gnuplot && !series.empty()) {
    std::string dat, plot = "plot ";
    int i = 0;
    for (const auto& [name, pts] : series) {
      dat += "# " + name + "\n" + pts + "\n\n";
      plot += fmt::format("{}'scaling.dat' index {} using 1:2 with linespoints title '{}'", i ? ", " : "", i, name.substr(3));
      ++i;
    }
    io::write_file_atomic(dir + "/scaling.dat", dat);
    const std::string script = fmt::format(
        "set terminal svg size 800,420 dynamic font 'sans,11'\nset output 'scaling.svg'\nset title 'cost vs cloth size n (n x n nodes)'\n"
        "set logscale xy\nset grid\nset key outside right\nset xlabel 'n'\nset ylabel 'ms per frame / step'\n{}\n",
        plot);
    if (io::run_gnuplot(dir, "scaling", script)) {
      res.plots.push_back("bench/scaling.svg");
      md += "\n![scaling](bench/scaling.svg)\n";
    }
  }
  res.markdown = md;
  res.data = {{"benchmarks", data}};
  return res;
}

}  // namespace tecido::suites
