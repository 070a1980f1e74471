#include "comparisons/io/source_dir.h"
#include "comparisons/cli/suite_session.h"

#include "comparisons/cli/commands.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/io/gnuplot.h"
#include "comparisons/io/input_error.h"

#include <algorithm>
#include <ostream>
#include <thread>
#include <unistd.h>

namespace tecido::cli {

namespace {

/// The suites named (`all` = every one; when sharded, every sweep, the others listed in `skipped`).
std::vector<const suites::SuiteEntry*> chosen_suites(const std::vector<std::string>& names, bool sharded,
                                                     std::string& skipped) {
  const auto& reg = suites::suite_registry();
  std::vector<const suites::SuiteEntry*> chosen;
  for (const auto& name : names) {
    if (name == "all") {
      for (const auto& s : reg) {
        if (sharded && !s.sweep) skipped += (skipped.empty() ? "" : ", ") + s.name;
        else chosen.push_back(&s);
      }
      continue;
    }
    auto it = std::find_if(reg.begin(), reg.end(), [&](const suites::SuiteEntry& e) { return e.name == name; });
    if (it == reg.end()) {
      std::string all;
      for (const auto& s : reg) all += (all.empty() ? "" : ", ") + s.name;
      throw io::UsageError("unknown suite \"" + name + "\" (known: " + all + ", all)");
    }
    if (sharded && !it->sweep) {
      std::string can;
      for (const auto& s : reg)
        if (s.sweep) can += (can.empty() ? "" : ", ") + s.name;
      throw io::UsageError("--shard: suite \"" + name + "\" cannot be sharded (only " + can + " can)");
    }
    chosen.push_back(&*it);
  }
  return chosen;
}

}  // namespace

SuiteSession::SuiteSession(const SuiteSettings& o, const LoadOutside& load_outside) {
  chosen_ = chosen_suites(o.names, o.sharded, skipped_);
  ctx_.data_dir = o.data.empty() ? std::string(TECIDO_SOURCE_DIR) + "/data" : o.data;
  tolerances_ = suites::Tolerances::load(o.tolerances.empty() ? ctx_.data_dir + "/tolerances.json" : o.tolerances);
  ctx_.out_dir = o.out;
  ctx_.quick = o.quick;
  ctx_.seed = o.seed;
  ctx_.threads = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  ctx_.tolerances = &tolerances_;
  ctx_.gnuplot = io::gnuplot_available();
  ctx_.progress = o.progress;
  io::check_output_dir(ctx_.out_dir);
  lock_ = std::make_unique<io::OutputDirLock>(ctx_.out_dir);  // a second run into this --out refuses
  const std::shared_ptr<outside::OutsideEngines> outside = load_outside();
  ctx_.outside = outside;
  if (!o.engines.empty()) {
    std::vector<std::string> known = builtin_engine_names();
    for (const auto& e : outside->all()) known.push_back(e->name());
    ctx_.engines = parse_engine_list(o.engines, known, "suite");
  }
}

std::vector<suites::SuiteResult> SuiteSession::run(std::ostream& log) const {
  io::create_output_directories(ctx_.out_dir);
  std::vector<suites::SuiteResult> results;
  for (const auto* s : chosen_) {
    log << "suite " << s->name << " ..." << std::flush;
    suites::SuiteResult r;
    try {
      r = suites::run_suite(*s, ctx_);
    } catch (...) {
      log << "\n";  // end the progress line: the error gets a line of its own
      throw;
    }
    int failed = 0;
    for (const auto& c : r.checks) failed += c.pass ? 0 : 1;
    // On a terminal a sweep's progress bar took the line: name the suite again.
    if (s->sweep && ctx_.progress && ::isatty(2) == 1) log << "suite " << s->name << ":";
    log << " " << r.checks.size() - failed << " passed, " << failed << " failed (" << r.seconds << " s)\n";
    for (const std::string& line : r.stderr_lines) log << "  " << line << "\n";
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace tecido::cli
