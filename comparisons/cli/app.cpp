#include "comparisons/cli/app.h"

#include "comparisons/io/provenance.h"

#include <algorithm>

namespace tecido::cli {

std::vector<std::pair<std::string, CommandFactory>>& command_registry() {
  static std::vector<std::pair<std::string, CommandFactory>> registry;
  return registry;
}

std::unique_ptr<CommandLine> make_command_line() {
  auto cl = std::make_unique<CommandLine>();
  cl->app.require_subcommand(1);
  cl->app.set_help_all_flag("--help-all", "Show help for every subcommand");
  cl->app.set_version_flag("--version", io::version_line(), "Print the version and the commit it was built from");
  auto registry = command_registry();
  std::sort(registry.begin(), registry.end());
  for (const auto& entry : registry) {
    const std::size_t before = cl->app.get_subcommands({}).size();
    Command run = entry.second(cl->app);
    cl->commands[cl->app.get_subcommands({})[before]] = std::move(run);
  }
  return cl;
}

std::vector<std::string> command_names() {
  std::vector<std::string> names;
  for (const auto& entry : command_registry()) names.push_back(entry.first);
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace tecido::cli
