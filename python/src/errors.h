#pragma once
/// How tecido's C++ errors reach Python (docs/python.md, "Errors"): the message is the one line the
/// command line prints after "tecido: " (cli/error_line.h), the type says what failed:
///   io::FileError (an input file missing, unreadable, too large), io::OutputError, a
///   std::filesystem error                                           -> OSError
///   io::InputError (a bad value: file or argument, JSON pointer, problem), io::UsageError -> ValueError
///   outside::EngineError (an outside engine failed; a Python engine raised)  -> tecido.EngineError
/// A Python engine's own exception is the __cause__ of its tecido.EngineError.
#include "comparisons/engines/outside/engine_error.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace tecido::python {

namespace py = pybind11;

/// An exception raised inside a Python engine, as the EngineError the harness handles (it crosses
/// the C++ suites and threads like any engine failure), carrying the Python exception itself.
class PythonEngineError : public outside::EngineError {
 public:
  /// Takes the error indicator of the calling thread's Python state (the GIL held).
  PythonEngineError(const std::string& door, const std::string& where, py::error_already_set& error);
  /// The original exception (a new reference, the GIL held), or nullptr.
  PyObject* cause() const;

 private:
  std::shared_ptr<PyObject> cause_;  ///< released with the GIL held, whichever thread drops it
};

/// Adds tecido.EngineError to `m` and registers the translators.
void register_errors(py::module_& m);

}  // namespace tecido::python
