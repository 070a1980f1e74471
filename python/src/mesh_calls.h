#pragma once
/// tecido.self_collisions and tecido.continuous_self_collisions (docs/python.md): `tecido
/// selfcollide` on arrays, through the same engines (self_collision_engines.h,
/// continuous_self_collision_engines.h) and the same size limits.
#include <pybind11/pybind11.h>

#include <string>

namespace tecido::python {

namespace py = pybind11;

/// int64 array (K, 2) of intersecting triangle pairs (i < j, sorted).
py::object self_collisions_call(py::handle vertices, py::handle faces, const std::string& engine);
/// {"vertex_face": int64 (K, 2) [vertex, face], "edge_edge": int64 (L, 2, 2) [[a, b], [c, d]]}.
py::object continuous_self_collisions_call(py::handle v0, py::handle v1, py::handle faces, const std::string& engine);

}  // namespace tecido::python
