#include "suite_call.h"

#include "engine_choice.h"
#include "json_bridge.h"

#include "comparisons/cli/suite_session.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/suites/report.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <streambuf>

namespace tecido::python {

namespace {

/// Where the progress lines go without verbose.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

std::string path_arg(const py::object& p) { return py::str(py::module_::import("os").attr("fspath")(p)); }

std::vector<std::string> suite_names(const py::object& names) {
  std::vector<std::string> out;
  if (py::isinstance<py::str>(names)) return {names.cast<std::string>()};
  for (const py::handle n : names) {
    if (!py::isinstance<py::str>(n)) throw io::UsageError("names: a suite name is a string");
    out.push_back(n.cast<std::string>());
  }
  if (out.empty()) throw io::UsageError("names: no suite given (a name, a list of names, or \"all\")");
  return out;
}

/// A fresh directory under the system's temporary folder, removed when this goes.
struct TemporaryDirectory {
  std::string path;
  TemporaryDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "tecido-suite-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::filesystem::filesystem_error("mkdtemp", pattern, std::error_code(errno, std::generic_category()));
    path = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace

py::object suite_call(const SuiteArgs& a) {
  if (a.threads < 0 || a.threads > io::kMaxThreads)
    throw io::UsageError("threads: must be in [0, " + std::to_string(io::kMaxThreads) + "] (0 = all cores)");
  cli::SuiteSettings s;
  s.names = suite_names(a.names);
  s.quick = a.quick;
  s.seed = a.seed;
  s.threads = a.threads;
  s.progress = false;
  if (!a.tolerances.is_none()) s.tolerances = path_arg(a.tolerances);
  if (!a.data.is_none()) s.data = path_arg(a.data);
  const EngineList engines = engine_list(a.engines);
  s.engines = engines.names;
  std::unique_ptr<TemporaryDirectory> scratch;
  if (a.out.is_none()) {
    scratch = std::make_unique<TemporaryDirectory>();
    s.out = scratch->path;
  } else {
    s.out = path_arg(a.out);
  }
  io::Json report;
  {
    py::gil_scoped_release release;
    const cli::SuiteSession session(s, [&] { return engines.outside; });
    NullBuffer null_buffer;
    std::ostream null_log(&null_buffer);
    const auto results = session.run(a.verbose ? std::cerr : null_log);
    report = suites::report_json(results, session.context());
    if (!a.out.is_none()) suites::write_report(results, session.context());
  }
  return to_python(report);
}

}  // namespace tecido::python
