// libFuzzer target: the command line (comparisons/cli/app.h), parsed only, never run. The input
// is the arguments, one per line (the first names the subcommand). Parsing may fail only with a
// CLI11 error whose message names something (a validator's names the option); any other exception
// is a finding, and so is a value accepted outside its documented domain (comparisons/io/limits.h).
#include "fuzz_common.h"

#include "comparisons/cli/app.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr const char* kTarget = "fuzz_options";

std::vector<std::string> arguments(const std::string& text) {
  std::vector<std::string> args;
  std::size_t from = 0;
  while (from <= text.size() && args.size() < 64) {
    const std::size_t nl = std::min(text.find('\n', from), text.size());
    args.push_back(text.substr(from, nl - from));
    from = nl + 1;
  }
  return args;
}

/// The accepted value of `name` on `sub`, if given, lies in [lo, hi] (lo excluded when `open`).
void expect_within(CLI::App* sub, const char* name, double lo, bool open, double hi) {
  const CLI::Option* opt = sub->get_option_no_throw(name);
  if (!opt || opt->count() == 0) return;
  const double x = opt->as<double>();
  if (!std::isfinite(x) || (open ? !(x > lo) : !(x >= lo)) || !(x <= hi))
    tecido::fuzz::finding(kTarget, std::string("accepted ") + name + " " + opt->results().front());
}

void check_accepted(tecido::cli::CommandLine& cl) {
  namespace io = tecido::io;
  for (CLI::App* sub : cl.app.get_subcommands()) {
    const std::string n = sub->get_name();
    if (n == "run") {
      expect_within(sub, "--dt", 0.0, true, io::kMaxDt);
      expect_within(sub, "--steps", 0.0, false, static_cast<double>(io::kMaxSteps));
      expect_within(sub, "--frame-every", 1.0, false, static_cast<double>(io::kMaxSteps));
      expect_within(sub, "--max-work", 1.0, false, io::kMaxWorkCeiling);
    }
    if (n == "experiment" || n == "suite") expect_within(sub, "--threads", 0.0, false, io::kMaxThreads);
    if (n == "experiment") {
      expect_within(sub, "--strength", 0.0, false, 1e9);
      expect_within(sub, "--max-work", 1.0, false, io::kMaxWorkCeiling);
    }
    // Paths (and --runs): an empty one would silently mean "not given".
    for (const char* path : {"scene", "--out", "--cases", "--pairs", "--mesh", "--scene", "--seed-table", "--runs",
                             "--tolerances", "--data", "dirs"}) {
      const CLI::Option* opt = sub->get_option_no_throw(path);
      if (!opt) continue;
      for (const auto& value : opt->results())
        if (value.empty()) tecido::fuzz::finding(kTarget, std::string("accepted an empty ") + path);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = arguments(tecido::fuzz::as_text(data, size));
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  const auto cl = tecido::cli::make_command_line();
  try {
    cl->app.parse(args);
  } catch (const CLI::Success&) {
    return 0;  // --help
  } catch (const CLI::ValidationError& e) {
    const std::string what = e.what();
    if (what.empty() || what.find(": ") == std::string::npos) tecido::fuzz::finding(kTarget, "validation error naming nothing: " + what);
    return 0;
  } catch (const CLI::ParseError& e) {
    if (std::string(e.what()).empty()) tecido::fuzz::finding(kTarget, "parse error without a message");
    return 0;
  } catch (const std::exception& e) {
    tecido::fuzz::finding(kTarget, std::string("exception other than a CLI11 error: ") + typeid(e).name() + ": " + e.what());
  }
  check_accepted(*cl);
  return 0;
}
