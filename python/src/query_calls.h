#pragma once
/// tecido.tri_tri and tecido.ccd (docs/python.md): arrays of queries in, arrays of answers out,
/// through the same engine registries as `tecido tritri` and `tecido ccd` (run_engines.h).
#include <pybind11/pybind11.h>

#include <string>

namespace tecido::python {

namespace py = pybind11;

/// Bool array (N,), or (hits, answered) with `answered`.
py::object tri_tri_call(py::handle a, py::handle b, py::handle engine, bool answered);
/// (hits (N,) bool, toi (N,) float64, NaN where no hit), plus `answered` when asked.
py::object ccd_call(py::handle t0, py::handle t1, const std::string& kind, py::handle engine, bool answered);
/// Seconds per pair of a plain C++ loop calling built-in engine `engine` on the pairs, best of
/// `repeats` (the benchmark's baseline: python/bench_overhead.py).
double time_tri_tri(py::handle a, py::handle b, const std::string& engine, int repeats);

}  // namespace tecido::python
