#include "run_call.h"

#include "arrays.h"
#include "json_bridge.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/run_result.h"
#include "comparisons/io/scene_json.h"
#include "comparisons/io/work_limit.h"
#include "core/simulation/self_collision_response.h"
#include "core/simulation/simulation.h"

#include <pybind11/numpy.h>

namespace tecido::python {

namespace {

/// An integer argument in [lo, hi] (bool refused: True is not a step count).
long long integer_arg(const py::object& v, const std::string& name, long long lo, long long hi) {
  if (!PyLong_Check(v.ptr()) || PyBool_Check(v.ptr()))
    throw io::UsageError(name + ": expected an integer, got " + std::string(py::str(py::type::handle_of(v).attr("__name__"))));
  const long long x = v.cast<long long>();
  if (x < lo || x > hi)
    throw io::UsageError(name + ": " + std::to_string(x) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

Scene read_scene(const py::object& scene, std::string& file) {
  const py::object os_path = py::module_::import("os").attr("PathLike");
  if (py::isinstance<py::str>(scene) || py::isinstance(scene, os_path)) {
    file = py::str(py::module_::import("os").attr("fspath")(scene));
    return io::load_scene(file);
  }
  if (!py::isinstance<py::dict>(scene))
    throw io::UsageError("scene: expected a dict (tecido's scene JSON) or a path, got " +
                         std::string(py::str(py::type::handle_of(scene).attr("__name__"))));
  file = "scene";
  return io::scene_from_json(from_python(scene, file), file);
}

/// The scene with the overrides, once the work limit is known to hold (cmd_run.cpp's rules).
Scene prepared_scene(const RunArgs& a) {
  std::string file;
  Scene scene = read_scene(a.scene, file);
  if (!a.integrator.is_none()) {
    const std::string name = py::str(a.integrator);
    const auto kind = parse_integrator(name);
    if (!kind) throw io::UsageError("integrator: expected euler, symplectic, midpoint or rk4, got \"" + name + "\"");
    scene.integrator = *kind;
  }
  if (!a.dt.is_none()) {
    if (!(PyFloat_Check(a.dt.ptr()) || PyLong_Check(a.dt.ptr())) || PyBool_Check(a.dt.ptr()))
      throw io::UsageError("dt: expected a number of seconds, got " +
                           std::string(py::str(py::type::handle_of(a.dt).attr("__name__"))));
    const double dt = py::float_(a.dt).cast<double>();
    if (!(dt > 0.0 && dt <= io::kMaxDt))
      throw io::UsageError("dt: " + std::to_string(dt) + " is outside (0, " + std::to_string(io::kMaxDt) + "]");
    scene.dt = dt;
  }
  if (!a.steps.is_none()) scene.steps = integer_arg(a.steps, "steps", 0, io::kMaxSteps);
  if (!(a.max_work >= 1.0 && a.max_work <= io::kMaxWorkCeiling))
    throw io::UsageError("max_work: must be in [1, " + std::to_string(io::kMaxWorkCeiling) + "]");
  const std::string too_much = io::work_limit_problem(scene, scene.steps, a.max_work);
  if (!too_much.empty()) {
    if (!a.steps.is_none()) throw io::UsageError("steps: " + too_much);
    throw io::InputError(file, "/steps", too_much);
  }
  return scene;
}

/// Every K-th step once the frames fit the limits of `tecido run --frame-every`.
long long frame_interval(const py::object& frames, const Scene& scene) {
  const long long every = integer_arg(frames, "frames", 1, io::kMaxSteps);
  const long long count = scene.steps / every + 2;
  const double elements = static_cast<double>(count) * static_cast<double>(scene.particles.size());
  if (count > io::kMaxFrames || elements > io::kMaxFrameElements)
    throw io::UsageError("frames: " + std::to_string(every) + " gives " + std::to_string(count) + " frames of " +
                         std::to_string(scene.particles.size()) + " particles, more than the limits of " +
                         std::to_string(io::kMaxFrames) + " frames and 1e9 points in all (choose a larger K)");
  return every;
}

struct Frames {
  std::vector<long long> steps;
  std::vector<double> times;
  std::vector<Vec3> x, v;
};

}  // namespace

py::dict run_call(const RunArgs& a) {
  const Scene scene = prepared_scene(a);
  const long long every = a.frames.is_none() ? 0 : frame_interval(a.frames, scene);
  Simulation sim(scene);
  const auto self_collision = install_self_collision(sim);
  Frames frames;
  io::Json result;
  {
    py::gil_scoped_release release;
    if (every == 0) {
      sim.run(scene.steps);
    } else {
      auto capture = [&](const Simulation& s) {
        const long long k = s.steps_done();
        if (k % every != 0 && k != scene.steps) return;
        frames.steps.push_back(k);
        frames.times.push_back(s.time());
        frames.x.insert(frames.x.end(), s.particles().x.begin(), s.particles().x.end());
        frames.v.insert(frames.v.end(), s.particles().v.begin(), s.particles().v.end());
      };
      capture(sim);
      sim.run(scene.steps, capture);
    }
    result = io::run_result_json(sim);
    if (self_collision) result["self_collision"] = io::self_collision_json(*self_collision);
  }
  py::dict out;
  out["status"] = result["status"].get<std::string>();
  out["steps"] = sim.steps_done();
  out["time"] = sim.time();
  out["positions"] = points_to_array(sim.particles().x, 0);
  out["velocities"] = points_to_array(sim.particles().v, 0);
  out["result"] = to_python(result);
  if (every) {
    const std::size_t n = scene.particles.size();
    py::dict f;
    f["steps"] = py::array_t<long long>(static_cast<py::ssize_t>(frames.steps.size()), frames.steps.data());
    f["times"] = py::array_t<double>(static_cast<py::ssize_t>(frames.times.size()), frames.times.data());
    f["positions"] = points_to_array(frames.x, n).reshape({static_cast<py::ssize_t>(frames.steps.size()), static_cast<py::ssize_t>(n), py::ssize_t{3}});
    f["velocities"] = points_to_array(frames.v, n).reshape({static_cast<py::ssize_t>(frames.steps.size()), static_cast<py::ssize_t>(n), py::ssize_t{3}});
    out["frames"] = f;
  }
  return out;
}

}  // namespace tecido::python
