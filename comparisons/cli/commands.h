#pragma once
/// Each subcommand registers itself on the app and returns the callback that runs it; the
/// callback returns the process exit code (0 ok, 1 a tolerance check failed, 2 bad input).
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace tecido::cli {

using Command = std::function<int()>;

Command add_run(CLI::App& app);
Command add_plane(CLI::App& app);

/// Splits "a,b,c" and checks each name against `known`; throws io::UsageError on an unknown one.
std::vector<std::string> parse_engine_list(const std::string& list, const std::vector<std::string>& known,
                                           const std::string& what);

}  // namespace tecido::cli
