// tecido suite NAME... | all [--out DIR] [--quick] [--seed N] [--threads N] [--tolerances FILE]
#include "comparisons/cli/commands.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/io/input_error.h"
#include "comparisons/suites/report.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

namespace tecido::cli {

namespace {

Command add_suite(CLI::App& app) {
  struct Opts {
    std::vector<std::string> names;
    std::string out = "out";
    std::string tolerances;
    std::string data;
    bool quick = false;
    std::uint64_t seed = 20141;
    int threads = 0;
  };
  auto o = std::make_shared<Opts>();
  std::string list;
  for (const auto& s : suites::suite_registry()) list += "\n  " + s.name + ": " + s.summary;
  CLI::App* sub = app.add_subcommand("suite", "Run comparison suites and write report.json and report.md. Suites:" + list);
  sub->add_option("names", o->names, "Suite names, or all")->required();
  sub->add_option("--out", o->out, "Output directory")->capture_default_str();
  sub->add_flag("--quick", o->quick, "Smaller counts, same checks (under 2 minutes for all)");
  sub->add_option("--seed", o->seed, "Seed of every random input (written into the report)")->capture_default_str();
  sub->add_option("--threads", o->threads, "Worker threads (0 = all cores); results do not depend on it");
  sub->add_option("--tolerances", o->tolerances, "Tolerance file (default data/tolerances.json)");
  sub->add_option("--data", o->data, "Data directory (default: the source tree's data/)");
  return [o]() {
    std::vector<const suites::SuiteEntry*> chosen;
    for (const auto& name : o->names) {
      if (name == "all") {
        for (const auto& s : suites::suite_registry()) chosen.push_back(&s);
        continue;
      }
      const auto& reg = suites::suite_registry();
      auto it = std::find_if(reg.begin(), reg.end(), [&](const suites::SuiteEntry& e) { return e.name == name; });
      if (it == reg.end()) {
        std::string all;
        for (const auto& s : reg) all += (all.empty() ? "" : ", ") + s.name;
        throw io::UsageError("unknown suite \"" + name + "\" (known: " + all + ", all)");
      }
      chosen.push_back(&*it);
    }
    suites::SuiteContext ctx;
    ctx.data_dir = o->data.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data" : o->data;
    const suites::Tolerances tol =
        suites::Tolerances::load(o->tolerances.empty() ? ctx.data_dir + "/tolerances.json" : o->tolerances);
    ctx.out_dir = o->out;
    ctx.quick = o->quick;
    ctx.seed = o->seed;
    ctx.threads = o->threads > 0 ? o->threads : std::max(1u, std::thread::hardware_concurrency());
    ctx.tolerances = &tol;
    ctx.gnuplot = io::gnuplot_available();
    std::filesystem::create_directories(ctx.out_dir);
    std::vector<suites::SuiteResult> results;
    for (const auto* s : chosen) {
      std::cerr << "suite " << s->name << " ..." << std::flush;
      const auto t0 = std::chrono::steady_clock::now();
      suites::SuiteResult r = s->run(ctx);
      r.name = s->name;
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      int failed = 0;
      for (const auto& c : r.checks) failed += c.pass ? 0 : 1;
      std::cerr << " " << r.checks.size() - failed << " passed, " << failed << " failed (" << r.seconds << " s)\n";
      results.push_back(std::move(r));
    }
    const int failed = suites::write_report(results, ctx);
    std::cout << "report: " << ctx.out_dir << "/report.md (" << failed << " failed checks)\n";
    return failed == 0 ? 0 : 1;
  };
}

}  // namespace

TECIDO_REGISTER_COMMAND(suite, add_suite);

}  // namespace tecido::cli
