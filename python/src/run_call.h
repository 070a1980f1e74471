#pragma once
/// tecido.run (docs/python.md): `tecido run` on a scene given as a dict or a path, with the same
/// reader, overrides, limits and result document, and the state as arrays.
#include <pybind11/pybind11.h>

namespace tecido::python {

namespace py = pybind11;

struct RunArgs {
  py::object scene;           ///< dict, or str / os.PathLike naming a scene file
  py::object steps, dt, integrator;  ///< None: the scene's
  py::object frames;          ///< None, or K: every K-th step's state (and the last)
  double max_work;
};

/// {"status", "steps", "time", "positions", "velocities", "result", "frames"?}.
py::dict run_call(const RunArgs& args);

}  // namespace tecido::python
