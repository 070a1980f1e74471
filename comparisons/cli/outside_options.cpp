#include "comparisons/cli/outside_options.h"

#include "comparisons/engines/run_engines.h"

namespace tecido::cli {

void add_outside_options(CLI::App* sub, outside::OutsideOptions& o) {
  sub->add_option("--plugin", o.plugins,
                  "A C plug-in (shared library exporting tecido_plugin_entry, include/tecido/plugin.h); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub->add_option("--engine-cmd", o.engine_cmds,
                  "NAME=COMMAND: an engine in a process speaking JSON lines on stdin/stdout; repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  sub->add_option("--engine-timeout", o.timeout_seconds, "Longest wait for one reply of a process engine [s]")
      ->capture_default_str();
}

std::shared_ptr<outside::OutsideEngines> load_outside_engines(const outside::OutsideOptions& options) {
  if (!options.any()) return std::make_shared<outside::OutsideEngines>();
  return outside::OutsideEngines::load(options, builtin_engine_names());
}

}  // namespace tecido::cli
