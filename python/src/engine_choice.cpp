#include "engine_choice.h"

#include "python_engine.h"

#include "comparisons/cli/commands.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/io/input_error.h"

#include <algorithm>

namespace tecido::python {

namespace {

/// A Python engine, whose name may not be a built-in engine's (the command line's rule).
std::shared_ptr<outside::OutsideEngine> python_engine(py::handle object) {
  auto e = std::make_shared<PythonEngine>(py::reinterpret_borrow<py::object>(object));
  const auto builtin = builtin_engine_names();
  if (std::find(builtin.begin(), builtin.end(), e->name()) != builtin.end())
    throw io::UsageError("engine " + e->name() + ": engine name \"" + e->name() + "\" is a built-in engine's; rename it");
  return e;
}

}  // namespace

EngineChoice choose_engine(py::handle engine, const std::vector<std::string>& builtin, const std::string& what,
                           bool outside::Capabilities::*capability) {
  EngineChoice c;
  c.outside = std::make_shared<outside::OutsideEngines>();
  if (py::isinstance<py::str>(engine)) {
    const std::string name = engine.cast<std::string>();
    const auto names = cli::parse_engine_list(name, builtin, what, "engine");
    if (names.size() != 1) throw io::UsageError("engine: one engine name, got \"" + name + "\"");
    c.name = names[0];
    return c;
  }
  const auto e = python_engine(engine);
  if (!(e->capabilities().*capability))
    throw io::UsageError("engine " + e->name() + ": " + e->door() + " does not answer " + what + " queries");
  c.name = e->name();
  c.outside->add(e);
  return c;
}

EngineList engine_list(py::handle engines) {
  EngineList l;
  l.outside = std::make_shared<outside::OutsideEngines>();
  if (engines.is_none()) return l;
  if (py::isinstance<py::str>(engines))
    throw io::UsageError("engines: expected a list of engine names and engine objects, got a string (use [\"" +
                         engines.cast<std::string>() + "\"])");
  for (const py::handle e : engines) {
    std::string name;
    if (py::isinstance<py::str>(e)) {
      name = e.cast<std::string>();
      if (name.empty() || name.find(',') != std::string::npos)
        throw io::UsageError("engines: \"" + name + "\" is not one engine name");
    } else {
      const auto engine = python_engine(e);
      name = engine->name();
      l.outside->add(engine);
    }
    l.names += (l.names.empty() ? "" : ",") + name;
  }
  if (l.names.empty()) throw io::UsageError("engines: no engine given (None runs every engine)");
  return l;
}

}  // namespace tecido::python
