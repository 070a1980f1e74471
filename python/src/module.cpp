// `import tecido`: the module's functions and their documentation (docs/python.md). Each function
// is one call into the harness's C++ code, the same code the command line runs; the work runs
// with the GIL released.
#include "engine_choice.h"
#include "errors.h"
#include "mesh_calls.h"
#include "query_calls.h"
#include "run_call.h"
#include "suite_call.h"

#include "comparisons/cli/commands.h"
#include "comparisons/engines/continuous_self_collision_engines.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/io/limits.h"
#include "comparisons/io/provenance.h"

#include <pybind11/stl.h>

namespace py = pybind11;
using namespace tecido;
using namespace tecido::python;

namespace {

constexpr const char* kModuleDoc = R"doc(tecido: a validation harness for cloth and particle physics, in Python.

The same engines, referees, readers, limits and suites as the `tecido` command line, called on
numpy arrays. Coordinates are float64 arrays in metres (any strides; another dtype is refused,
not converted); results are numpy arrays. Bad input raises ValueError (a shape, a dtype, a
non-finite or out-of-range coordinate, a bad scene value) or OSError (a file), with the one-line
message the command line prints; a failing engine raises tecido.EngineError.

Functions: tri_tri, ccd, self_collisions, continuous_self_collisions, run, suite, engines.
An engine argument is a built-in engine's name (tecido.engines(...)) or a Python object with
tri_tri / ccd / create+step methods (see help(tecido.tri_tri) and docs/python.md).)doc";

constexpr const char* kTriTriDoc = R"doc(tri_tri(a, b, engine="core", *, answered=False)

Whether closed triangles a[i] and b[i] intersect (touching counts), for every i.

a, b      float64 arrays of shape (N, 3, 3): N triangles of three corners [x, y, z] [m];
          |coordinate| <= 1e15, finite (the bounds of `tecido tritri --pairs`).
engine    a built-in engine's name, as on the command line: tecido.engines("tri_tri") lists
          them (core, core-rotation, core-mt, fcl, ccd-gjk, ccd-mpr, exact; "exact" is the
          exact GMP referee); or a Python engine object (a tri_tri(a, b) or tri_tri_batch(a, b)
          method; docs/python.md).
answered  when True, also return which queries the engine answered.

Returns a bool array (N,); with answered=True, (hits, answered). An engine that cannot answer
some query raises ValueError naming it, unless answered=True (the hit is then False there).

Raises ValueError for a wrong shape or dtype, a non-finite or out-of-range coordinate
("a: /5/1/2: number is not finite (nan)"), an unknown engine; tecido.EngineError when a Python
engine raises (its name, the query and the exception; the exception is __cause__).)doc";

constexpr const char* kCcdDoc = R"doc(ccd(t0, t1, kind, engine="core", *, answered=False)

Continuous collision over one time step: points moving linearly from t0[i] (time 0) to t1[i]
(time 1); whether the primitives touch at some t in [0, 1], and the first such t.

t0, t1    float64 arrays of shape (N, 4, 3) [m], finite.
          kind "vf" (or "vertex-face"): rows are the vertex, then the triangle's three corners;
          kind "ee" (or "edge-edge"): rows are a0, a1 (first edge), b0, b1 (second edge).
engine    a built-in engine's name, as on the command line: tecido.engines("ccd") lists them
          (core, exact, fcl, bullet; "exact" is the exact rational referee; bullet answers
          vertex-face only); or a Python engine object (a ccd(kind, t0, t1) or
          ccd_batch(kinds, t0, t1) method; docs/python.md).
answered  when True, also return which queries the engine answered.

Returns (hits, toi): hits a bool array (N,), toi a float64 array (N,) of times of impact in
[0, 1] (a fraction of the step), NaN where there is no hit. With answered=True, (hits, toi,
answered). An engine that cannot answer some query (bullet on edge-edge) raises ValueError
unless answered=True.

Raises ValueError for a wrong shape or dtype, a non-finite coordinate, an unknown kind or
engine; tecido.EngineError when a Python engine raises.)doc";

constexpr const char* kSelfDoc = R"doc(self_collisions(V, F, engine="core")

The intersecting pairs of triangles of a mesh that share no vertex, as `tecido selfcollide`.

V         float64 array (n, 3): vertex positions [m], finite; at most 2^20 vertices.
F         integer array (m, 3): each triangle's three different vertex indices, 0-based;
          at least one triangle, at most 2^21.
engine    core (box tree + exact narrow phase), core-brute (every pair, exact narrow phase),
          fcl, exact (every pair, CGAL's exact test); core-brute and exact take at most 2^14
          triangles.

Returns an int64 array (K, 2) of triangle index pairs (i, j), i < j, sorted.)doc";

constexpr const char* kContinuousDoc = R"doc(continuous_self_collisions(V0, V1, F, engine="core")

Continuous self-collision of one mesh moving linearly from V0 to V1, as
`tecido selfcollide --mesh V0 --to V1`.

V0, V1    float64 arrays (n, 3): vertex positions at the start and the end [m].
F         integer array (m, 3): the triangles, 0-based vertex indices.
engine    core (broad phase + core's test, confirmed by the exact referee: the exact answer),
          core-brute (core's test on every pair, unconfirmed; at most 2^14 triangles),
          exact (the exact referee on every pair; at most 2^11 triangles).

Returns {"vertex_face": int64 (K, 2) of [vertex, face], "edge_edge": int64 (L, 2, 2) of
[[a, b], [c, d]]}: every vertex-face pair (vertex not a corner of the face) and edge-edge pair
(no shared vertex) that touches during the motion, sorted.)doc";

constexpr const char* kRunDoc = R"doc(run(scene, *, steps=None, dt=None, integrator=None, frames=None, max_work=1e11)

Simulates a scene with the core engine, as `tecido run`.

scene       a dict (tecido's scene JSON: docs/design.md section 3) or a path to a scene file.
steps, dt   override the scene's step count and step [s] (the limits of --steps, --dt).
integrator  "euler", "symplectic", "midpoint" or "rk4" (overrides the scene's).
frames      K: also return the state every K-th step, the first and the last.
max_work    the largest work of the run, steps x elements (as --max-work).

Returns a dict:
  status      "ok" or "unstable" (the run went non-finite; a result, not an error)
  steps, time the steps done and the simulated time [s]
  positions   float64 (n, 3) [m], velocities float64 (n, 3) [m/s]: the last state
  result      the document `tecido run --json` prints (contacts, instability, ...)
  frames      with frames=K: {"steps": int64 (F,), "times": float64 (F,) [s],
              "positions": (F, n, 3), "velocities": (F, n, 3)}

Raises ValueError for a bad scene value ("scene: /particles/0/mass: ..." for a dict, the file's
name for a path), OSError for a file that cannot be read.)doc";

constexpr const char* kSuiteDoc = R"doc(suite(names, engines=None, out=None, *, quick=False, seed=20141, threads=0, tolerances=None, data=None, verbose=False)

Runs comparison suites, as `tecido suite`, and returns the report.

names       a suite name, a list of them, or "all" (tritri, ccd, plane, stability, ...).
engines     None (every engine), or a list of built-in engine names and Python engine objects
            (as --engines with --engine-cmd: a suite runs the named engines it knows, its
            referee always runs). A Python object answers in-process what its methods answer.
out         a directory for report.json, report.md and the suites' files; None: a temporary
            directory, removed afterwards (the report is returned either way).
quick, seed, threads, tolerances, data: as the options of `tecido suite`.
verbose     print the suites' progress lines on stderr.

Returns the report as a dict (report.json's content: each suite's checks, pass or fail, and
data). Results do not depend on threads.)doc";

py::list engine_names(const std::string& question) {
  std::vector<std::string> names;
  if (question == "tri_tri") names = tri_tri_engine_names(nullptr);
  else if (question == "ccd") names = ccd_engine_names(nullptr);
  else if (question == "self_collision")
    for (const auto& e : self_collision_engines()) names.push_back(e.name);
  else if (question == "continuous_self_collision") names = continuous_self_collision_engines();
  else if (question == "suite") names = builtin_engine_names();
  else
    throw io::UsageError("question: expected tri_tri, ccd, self_collision, continuous_self_collision or suite, got \"" +
                         question + "\"");
  return py::cast(names);
}

/// The reports' "command_line" (io/provenance.h): the Python process that wrote them,
/// sys.executable and sys.argv.
void record_command_line() {
  const py::module_ sys = py::module_::import("sys");
  std::vector<std::string> args = {py::str(sys.attr("executable"))};
  if (py::hasattr(sys, "argv"))
    for (const py::handle a : sys.attr("argv")) args.push_back(py::str(a));
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  io::set_command_line(static_cast<int>(argv.size()), argv.data());
}

}  // namespace

PYBIND11_MODULE(tecido, m) {
  py::options options;
  options.disable_function_signatures();  // each docstring's first line is the signature, in Python's words
  m.doc() = kModuleDoc;
  m.attr("__version__") = io::tecido_version();
  m.attr("commit") = io::tecido_commit();
  register_errors(m);
  record_command_line();
  m.def("tri_tri", &tri_tri_call, kTriTriDoc, py::arg("a"), py::arg("b"), py::arg("engine") = "core", py::kw_only(),
        py::arg("answered") = false);
  m.def("ccd", &ccd_call, kCcdDoc, py::arg("t0"), py::arg("t1"), py::arg("kind"), py::arg("engine") = "core",
        py::kw_only(), py::arg("answered") = false);
  m.def("self_collisions", &self_collisions_call, kSelfDoc, py::arg("V"), py::arg("F"), py::arg("engine") = "core");
  m.def("continuous_self_collisions", &continuous_self_collisions_call, kContinuousDoc, py::arg("V0"), py::arg("V1"),
        py::arg("F"), py::arg("engine") = "core");
  m.def(
      "run",
      [](py::object scene, py::object steps, py::object dt, py::object integrator, py::object frames, double max_work) {
        return run_call({std::move(scene), std::move(steps), std::move(dt), std::move(integrator), std::move(frames), max_work});
      },
      kRunDoc, py::arg("scene"), py::kw_only(), py::arg("steps") = py::none(), py::arg("dt") = py::none(),
      py::arg("integrator") = py::none(), py::arg("frames") = py::none(), py::arg("max_work") = io::kDefaultMaxWork);
  m.def(
      "suite",
      [](py::object names, py::object engines, py::object out, bool quick, std::uint64_t seed, int threads,
         py::object tolerances, py::object data, bool verbose) {
        SuiteArgs a;
        a.names = std::move(names), a.engines = std::move(engines), a.out = std::move(out);
        a.quick = quick, a.seed = seed, a.threads = threads;
        a.tolerances = std::move(tolerances), a.data = std::move(data), a.verbose = verbose;
        return suite_call(a);
      },
      kSuiteDoc, py::arg("names"), py::arg("engines") = py::none(), py::arg("out") = py::none(), py::kw_only(),
      py::arg("quick") = false, py::arg("seed") = 20141, py::arg("threads") = 0, py::arg("tolerances") = py::none(),
      py::arg("data") = py::none(), py::arg("verbose") = false);
  m.def("engines", &engine_names,
        "engines(question)\n\nThe built-in engines' names for a question: \"tri_tri\", \"ccd\", \"self_collision\", "
        "\"continuous_self_collision\", or \"suite\" (every built-in name). Returns a list of str.",
        py::arg("question"));
  m.def("_time_tri_tri", &time_tri_tri,
        "_time_tri_tri(a, b, engine=\"core\", repeats=3)\n\nSeconds per pair of a plain C++ loop calling built-in engine "
        "`engine` on the pairs (best of `repeats`): the baseline of python/bench_overhead.py.",
        py::arg("a"), py::arg("b"), py::arg("engine") = "core", py::arg("repeats") = 3);
}
