#pragma once
/// What every output file says about how it was made, so that a report read later can be traced
/// and redone: tecido's version (the CMake project version), the git commit it was built from
/// ("unknown" when the source was not a git checkout at configure time, or git was missing), and
/// the command line that wrote it. In report.json, result.json and experiment.json as
/// "tecido": {"version", "commit", "command_line"}; in report.md as one line under the title;
/// `tecido --version` prints version_line().
#include "comparisons/io/json_reader.h"

#include <string>
#include <vector>

namespace tecido::io {

const char* tecido_version();
const char* tecido_commit();

/// "tecido 0.1.0 (commit 1a2b3c4)".
std::string version_line();

/// Recorded once by main(): argv as one line a shell would run again (an argument with anything
/// but [A-Za-z0-9_./:=,+@%-] in single quotes).
void set_command_line(int argc, const char* const* argv);
/// The recorded line; "" when nothing recorded it (the suites called from a test).
const std::string& command_line();
/// `args` joined as set_command_line joins them.
std::string shell_line(const std::vector<std::string>& args);

/// {"version", "commit", "command_line"}.
Json provenance_json();
/// "tecido 0.1.0, commit 1a2b3c4: `tecido suite order --quick`" (one markdown line, no newline).
std::string provenance_markdown();

}  // namespace tecido::io
