#include "python_simulation.h"

#include "python_engine.h"

#include "comparisons/engines/outside/process_protocol.h"

#include <pybind11/numpy.h>

#include <cmath>

namespace tecido::python {

namespace {

/// (n, 3) points of a step's reply, NaN where None; ProtocolError for another shape.
std::vector<Vec3> state_points(py::handle value, std::size_t n, const char* what) {
  py::array_t<double, py::array::c_style> a;
  try {
    a = py::module_::import("numpy").attr("asarray")(value, py::arg("dtype") = "float64");
  } catch (py::error_already_set& e) {
    throw outside::ProtocolError(std::string("\"") + what + "\" is not an array of numbers: " + std::string(py::str(e.value())));
  }
  if (a.ndim() != 2 || a.shape(1) != 3 || static_cast<std::size_t>(a.shape(0)) != n)
    throw outside::ProtocolError(std::string("\"") + what + "\" must hold " + std::to_string(n) + " points [x, y, z]");
  std::vector<Vec3> out(n);
  const auto r = a.unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) out[i] = Vec3(r(i, 0), r(i, 1), r(i, 2));
  return out;
}

}  // namespace

PythonSimulation::PythonSimulation(std::shared_ptr<PythonEngine> engine, const Scene& scene)
    : SteppedSimulation(scene.dt), engine_(std::move(engine)) {
  begin(scene.particles.x, scene.particles.v);
}

PythonSimulation::~PythonSimulation() { engine_->release_scene(); }

bool PythonSimulation::call_step(long long n) {
  {
    py::gil_scoped_acquire gil;
    const py::object r = engine_->call("step", "op step", py::make_tuple(dt(), n));
    try {
      py::object x, v;
      if (py::isinstance<py::dict>(r)) {
        const py::dict d = py::reinterpret_borrow<py::dict>(r);
        if (!d.contains("x") || !d.contains("v")) throw outside::ProtocolError("expected {\"x\": ..., \"v\": ...}");
        x = d["x"], v = d["v"];
      } else if ((py::isinstance<py::tuple>(r) || py::isinstance<py::list>(r)) && py::len(r) == 2) {
        x = r[py::int_(0)], v = r[py::int_(1)];
      } else {
        throw outside::ProtocolError("expected (x, v) or {\"x\": ..., \"v\": ...}");
      }
      x_ = state_points(x, x_.size(), "x");
      v_ = state_points(v, v_.size(), "v");
    } catch (const outside::ProtocolError& p) {
      engine_->fail("op step", p.what());
    }
  }
  return true;
}

}  // namespace tecido::python
