// tecido: the command line. Exit codes: 0 ok, 1 a tolerance check failed, 2 bad usage, bad input
// or an output that cannot be written (one line on stderr naming the option, the file and JSON
// pointer, or the path, and the problem), 3 an internal error.
#include "comparisons/cli/app.h"
#include "comparisons/cli/error_line.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/output_error.h"
#include "comparisons/io/provenance.h"
#include "core/platform/simd_level.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <new>

namespace tecido::cli {
namespace {

/// Runs the parsed subcommand, turning every error into its one line and exit code.
int run_parsed(const std::map<CLI::App*, Command>& commands) {
  try {
    for (const auto& [sub, run] : commands)
      if (sub->parsed()) return run();
  } catch (const io::InputError& e) {
    report_error(std::cerr, e.what());
    return 2;
  } catch (const io::UsageError& e) {
    report_error(std::cerr, e.what());
    return 2;
  } catch (const io::OutputError& e) {
    report_error(std::cerr, e.what());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A writer that reached the file system directly: still a path that cannot be written.
    report_error(std::cerr, e.path1().string() + ": " + e.code().message());
    return 2;
  } catch (const std::bad_alloc&) {
    report_error(std::cerr, "error: out of memory");
    return 3;
  } catch (const std::exception& e) {
    report_error(std::cerr, std::string("error: ") + e.what());
    return 3;
  }
  return 2;
}

/// stdout is an output like any file: a failed write (a full disk, a closed pipe) is exit 2.
int check_stdout(int code) {
  errno = 0;
  std::cout.flush();
  if (std::cout.good()) return code;
  const int e = errno;
  report_error(std::cerr, std::string("stdout: cannot write") + (e ? std::string(": ") + std::strerror(e) : ""));
  return 2;
}

}  // namespace
}  // namespace tecido::cli

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) then shows as a failed write, reported like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  if (const auto& simd = tecido::simd_choice(); !simd.error.empty()) {
    tecido::cli::report_error(std::cerr, simd.error);
    return 2;
  }
  const auto names = tecido::cli::command_names();
  if (argc > 1 && argv[1][0] != '-' && std::find(names.begin(), names.end(), argv[1]) == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    tecido::cli::report_error(std::cerr, "unknown command \"" + std::string(argv[1]) + "\" (known: " + known + "; see --help)");
    return 2;
  }
  tecido::io::set_command_line(argc, argv);  // for the reports the command writes
  const auto cl = tecido::cli::make_command_line();
  try {
    cl->app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return tecido::cli::check_stdout(cl->app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return tecido::cli::check_stdout(cl->app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return tecido::cli::check_stdout(cl->app.exit(e));
  } catch (const CLI::ValidationError& e) {
    tecido::cli::report_error(std::cerr, e.what());  // already "--option: problem"
    return 2;
  } catch (const CLI::ParseError& e) {
    tecido::cli::report_error(std::cerr, std::string(e.what()) + " (see --help)");
    return 2;
  }
  return tecido::cli::check_stdout(tecido::cli::run_parsed(cl->commands));
}
