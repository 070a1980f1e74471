// tecido's suites run in-process on the caller's engines (include/tecido/harness.h: run_suites,
// Report): the context `tecido suite NAMES --engines ...` builds, the caller's tables registered
// as outside engines, the report as report.json and report.md would hold it.
#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/engines/outside/outside_engines.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/harness/registered_engines.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/output_dir.h"
#include "comparisons/suites/report.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/tolerances.h"

#include <tecido/harness.h>

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace tecido::harness {

namespace {

const suites::SuiteEntry& suite_named(const std::string& name) {
  for (const auto& s : suites::suite_registry())
    if (s.name == name) return s;
  throw std::invalid_argument("harness: no suite \"" + name + "\"");
}

/// The engines the suites run (--engines): the registered ones and the chosen built-in ones.
std::vector<std::string> engine_selection(const RegisteredEngines& registered, const SuiteOptions& options) {
  const std::vector<std::string> builtin = ::tecido::builtin_engine_names();
  std::vector<std::string> names;
  for (const auto& e : registered.engines()) {
    if (std::find(builtin.begin(), builtin.end(), e->name()) != builtin.end())
      throw std::invalid_argument("harness: engine name \"" + e->name() + "\" is a built-in engine's; rename it");
    names.push_back(e->name());
  }
  for (const std::string& name : options.builtin_engines) {
    if (std::find(builtin.begin(), builtin.end(), name) == builtin.end())
      throw std::invalid_argument("harness: no built-in engine \"" + name + "\"");
    names.push_back(name);
  }
  return names;
}

/// A directory of its own under the system's temporary directory, removed with the object.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "tecido-harness-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("harness: cannot create a temporary directory");
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

Check public_check(const std::string& suite, const suites::Check& c) {
  return Check{suite, c.name, !std::isnan(c.value), c.value, c.lo, c.hi, c.pass, c.note, c.reason};
}

Report run_in(const std::vector<std::string>& names, const RegisteredEngines& registered, const SuiteOptions& options,
              const std::string& out_dir) {
  std::vector<const suites::SuiteEntry*> chosen;
  for (const std::string& name : names) chosen.push_back(&suite_named(name));
  if (options.data_dir.empty())
    throw std::invalid_argument("harness: SuiteOptions::data_dir is empty (the package's share/tecido/data)");
  if (options.threads < 1) throw std::invalid_argument("harness: SuiteOptions::threads must be at least 1");
  const suites::Tolerances tolerances = suites::Tolerances::load(options.data_dir + "/tolerances.json");
  auto outside = std::make_shared<outside::OutsideEngines>();
  for (const auto& e : registered.engines()) outside->add(e);
  suites::SuiteContext ctx;
  ctx.out_dir = out_dir;
  ctx.data_dir = options.data_dir;
  ctx.quick = options.quick;
  ctx.seed = options.seed;
  ctx.threads = options.threads;
  ctx.tolerances = &tolerances;
  ctx.outside = outside;
  ctx.engines = engine_selection(registered, options);
  io::check_output_dir(out_dir);
  const io::OutputDirLock lock(out_dir);
  io::create_output_directories(out_dir);
  std::vector<suites::SuiteResult> results;
  for (const auto* s : chosen) results.push_back(suites::run_suite(*s, ctx));
  Report report;
  for (const auto& r : results)
    for (const auto& c : r.checks) report.checks.push_back(public_check(r.name, c));
  report.json = suites::report_json(results, ctx).dump(2);
  report.markdown = suites::report_markdown(results, ctx);
  if (!options.out_dir.empty()) suites::write_report(results, ctx);
  return report;
}

}  // namespace

std::size_t Report::failed() const {
  return static_cast<std::size_t>(std::count_if(checks.begin(), checks.end(), [](const Check& c) { return !c.pass; }));
}

std::vector<Check> Report::checks_with(const std::string& text) const {
  std::vector<Check> out;
  for (const Check& c : checks)
    if (c.name.find(text) != std::string::npos) out.push_back(c);
  return out;
}

Report run_suites(const std::vector<std::string>& suites, const std::vector<tecido_engine>& engines,
                  const SuiteOptions& options) {
  const RegisteredEngines registered(engines);
  try {
    if (!options.out_dir.empty()) return run_in(suites, registered, options, options.out_dir);
    const ScratchDir scratch;
    return run_in(suites, registered, options, scratch.path() + "/out");
  } catch (const io::UsageError& e) {
    throw std::invalid_argument(e.what());
  } catch (const io::InputError& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace tecido::harness
