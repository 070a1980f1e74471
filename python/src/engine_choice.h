#pragma once
/// The `engine` argument of the module's calls: a built-in engine's name, exactly as on the command
/// line, or a Python object answering the question (python_engine.h), which joins an
/// OutsideEngines set of the call as the command line's --plugin and --engine-cmd engines do.
#include "comparisons/engines/outside/outside_engines.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

namespace tecido::python {

namespace py = pybind11;

struct EngineChoice {
  std::string name;
  std::shared_ptr<outside::OutsideEngines> outside;  ///< the Python engine's set (empty for a built-in)
};

/// `engine`: a name among `builtin` ("engine: unknown <what> engine ..." otherwise, the message of
/// --engines) or a Python object with capability `capability` (the GIL held).
EngineChoice choose_engine(py::handle engine, const std::vector<std::string>& builtin, const std::string& what,
                           bool outside::Capabilities::*capability);

/// The engines of suite(): names (built-in or of the objects given) and the objects as a set.
struct EngineList {
  std::string names;  ///< comma-separated, as --engines
  std::shared_ptr<outside::OutsideEngines> outside;
};
EngineList engine_list(py::handle engines);

}  // namespace tecido::python
