#pragma once
/// tecido.suite (docs/python.md): `tecido suite` (cli/suite_session.h), its report as a dict,
/// and its files when `out` is given.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

namespace tecido::python {

namespace py = pybind11;

struct SuiteArgs {
  py::object names;    ///< a suite name or a list of them ("all")
  py::object engines;  ///< None, or names and Python engine objects
  py::object out;      ///< None: a temporary directory, removed afterwards
  bool quick = false;
  std::uint64_t seed = 20141;
  int threads = 0;
  py::object tolerances, data;  ///< None: the defaults
  bool verbose = false;
};

/// The report (report.json's document).
py::object suite_call(const SuiteArgs& args);

}  // namespace tecido::python
