// tecido: the command line. Exit codes: 0 ok, 1 a tolerance check failed, 2 bad usage or bad
// input (one line on stderr naming file, JSON path and problem).
#include "comparisons/cli/commands.h"
#include "comparisons/io/input_error.h"

#include <iostream>
#include <algorithm>
#include <map>

namespace tecido::cli {
std::vector<std::pair<std::string, CommandFactory>>& command_registry() {
  static std::vector<std::pair<std::string, CommandFactory>> registry;
  return registry;
}
}  // namespace tecido::cli

int main(int argc, char** argv) {
  CLI::App app{"tecido: a validation harness for cloth and particle physics"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Show help for every subcommand");
  std::map<CLI::App*, tecido::cli::Command> commands;
  auto add = [&](tecido::cli::Command (*f)(CLI::App&)) {
    const std::size_t before = app.get_subcommands({}).size();
    tecido::cli::Command c = f(app);
    commands[app.get_subcommands({})[before]] = std::move(c);
  };
  auto registry = tecido::cli::command_registry();
  std::sort(registry.begin(), registry.end());
  for (const auto& entry : registry) add(entry.second);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "tecido: " << e.what() << " (see --help)\n";
    return 2;
  }
  try {
    for (auto& [sub, run] : commands)
      if (sub->parsed()) return run();
  } catch (const tecido::io::InputError& e) {
    std::cerr << "tecido: " << e.what() << "\n";
    return 2;
  } catch (const tecido::io::UsageError& e) {
    std::cerr << "tecido: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tecido: error: " << e.what() << "\n";
    return 3;
  }
  return 2;
}
