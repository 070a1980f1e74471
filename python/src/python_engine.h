#pragma once
/// A Python object as an outside engine, called in-process (docs/python.md, "Your engine in
/// Python"): the same questions as the JSON-lines door (comparisons/engines/outside/
/// process_protocol.h), asked as method calls, so every command and suite that reaches outside
/// engines reaches it unchanged. Methods, each optional (what it has is what it answers):
///   tri_tri(a, b) -> answer              a, b: lists of 3 points [x, y, z]
///   tri_tri_batch(a, b) -> N answers     a, b: float64 arrays (N, 3, 3)
///       answer: True | False | None (cannot say) | {"hit": ...}
///   ccd(kind, t0, t1) -> answer          kind "vertex-face" | "edge-edge"; t0, t1: lists of 4 points
///   ccd_batch(kinds, t0, t1) -> N answers  kinds: list of N kinds; t0, t1: float64 arrays (N, 4, 3)
///       answer: (hit, toi) | None | {"hit": bool|None, "toi": t|None}
///   create(scene, features) -> None | True (accepted) | "reason" (refused) | {"ok": true} | {"error": "..."}
///       scene: tecido's scene JSON as a dict; features: the list the hello-less door sends
///   step(dt, steps) -> (x, v) | {"x": x, "v": v}  positions and velocities (n, 3) after `steps` steps
///   order                                 attribute: the integration order it claims
///   name                                  attribute: its name in reports (default: its class name)
/// Batched forms are used when present (one call per batch). Answers are read by the door's own
/// parsers (a reply breaking the protocol is an EngineError naming the engine and the query); an
/// exception raised by a method becomes a PythonEngineError naming the engine, the query and the
/// exception. The GIL is taken only around the calls into Python; the object holds one scene at a
/// time (a SceneLease, as a process does).
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/engines/outside/scene_lease.h"
#include "comparisons/io/json_reader.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace tecido::python {

namespace py = pybind11;

class PythonEngine final : public outside::OutsideEngine, public std::enable_shared_from_this<PythonEngine> {
 public:
  /// Reads the object's name, order and methods (the GIL held). io::UsageError for an object that
  /// answers nothing or has an invalid name.
  explicit PythonEngine(py::object engine);
  ~PythonEngine() override;

  const std::string& name() const override { return name_; }
  std::string door() const override { return "Python object " + type_name_ + " (in-process)"; }
  bool is_process() const override { return false; }
  outside::Capabilities capabilities() const override { return capabilities_; }
  std::optional<double> claimed_order() const override { return order_; }

  std::vector<std::optional<bool>> tri_tri(const std::vector<outside::TriTriQuery>& queries) override;
  std::vector<std::optional<SegmentPlaneHit>> segment_plane(const std::vector<outside::SegmentPlaneQuery>& queries) override;
  std::vector<std::optional<CcdAnswer>> ccd(const std::vector<CcdQuery>& queries) override;
  outside::Creation create(const Scene& scene) override;

  /// Calls `method` of the object with `args` (the GIL held); `where` names the query in errors
  /// ("query 3 (tri_tri)"). A Python exception becomes a PythonEngineError.
  py::object call(const char* method, const std::string& where, const py::tuple& args);
  /// Throws the EngineError of a reply that breaks the protocol.
  [[noreturn]] void fail(const std::string& where, const std::string& problem) const;
  /// Ends the lease of a simulation (PythonSimulation's destructor).
  void release_scene() { scene_.release(); }
  /// "engine NAME (Python object TYPE)", the door part of errors.
  std::string error_door() const { return "engine " + name_ + " (Python object " + type_name_ + ")"; }

 private:
  py::object engine_;
  std::string name_, type_name_;
  outside::Capabilities capabilities_;
  bool tri_tri_batch_ = false, ccd_batch_ = false;
  std::optional<double> order_;
  outside::SceneLease scene_;
};

/// The Python value of an answer as the JSON reply the door's parsers read: None -> null,
/// booleans (numpy's too) and numbers as themselves, a dict through JSON; `fields` name a tuple's
/// members ({"hit","toi"} for (hit, toi)); a lone value is the first field.
io::Json answer_json(py::handle answer, std::initializer_list<const char*> fields);

}  // namespace tecido::python
