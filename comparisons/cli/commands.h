#pragma once
/// Each subcommand registers itself on the app and returns the callback that runs it; the
/// callback returns the process exit code (0 ok, 1 a tolerance check failed, 2 bad input).
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tecido::cli {

using Command = std::function<int()>;

/// A subcommand's registration: adds itself to the app, returns its runner.
using CommandFactory = Command (*)(CLI::App& app);

/// Every registered subcommand, in name order (filled by TECIDO_REGISTER_COMMAND).
std::vector<std::pair<std::string, CommandFactory>>& command_registry();

struct CommandRegistrar {
  CommandRegistrar(const char* name, CommandFactory f) { command_registry().emplace_back(name, f); }
};

/// In one cmd_*.cpp of the CLI executable: TECIDO_REGISTER_COMMAND(run, add_run);
#define TECIDO_REGISTER_COMMAND(name, factory) \
  static const ::tecido::cli::CommandRegistrar tecido_registrar_##name(#name, &factory)

/// Splits "a,b,c" and checks each name against `known`; throws io::UsageError naming --engines on
/// an unknown one or an empty list.
std::vector<std::string> parse_engine_list(const std::string& list, const std::vector<std::string>& known,
                                           const std::string& what);

}  // namespace tecido::cli
