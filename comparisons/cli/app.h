#pragma once
/// The command line as one CLI11 app: every registered subcommand (commands.h), in name order,
/// with the runner of each. main() parses and runs it; the options fuzzer (fuzz/fuzz_options.cpp)
/// only parses it.
#include "comparisons/cli/commands.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tecido::cli {

struct CommandLine {
  CLI::App app{"tecido: a validation harness for cloth and particle physics"};
  std::map<CLI::App*, Command> commands;  ///< subcommand -> its runner
};

/// A fresh app with every registered subcommand.
std::unique_ptr<CommandLine> make_command_line();

/// The registered subcommands' names, in order.
std::vector<std::string> command_names();

}  // namespace tecido::cli
