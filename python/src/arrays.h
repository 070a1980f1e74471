#pragma once
/// Array arguments and results (docs/python.md, "Arrays"). Coordinates are float64 and nothing
/// else: a numpy array of another dtype (int, float32, ...) is refused with ValueError rather than
/// converted; a list is read with numpy.asarray(x) and must give float64 as well (Python floats
/// do). Any strides are read in place (a slice, a transpose: no copy asked of the caller). Every
/// coordinate must be finite and within the same bound the file formats set; a violation is
/// io::InputError(argument, "/i/j/c", problem), the JSON-pointer form of the files' messages.
#include "core/geometry/types.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tecido::python {

namespace py = pybind11;

/// `value` as N blocks of `rows` points, row-major (N * rows points): shape (N, rows, 3), or
/// (N, 3) when rows is 0 (N points). |coordinate| <= max_abs. `name` names the argument.
std::vector<Vec3> point_array(py::handle value, const std::string& name, std::size_t rows, double max_abs);

/// Triangles of `vertex_count` vertices: an integer array of shape (M, 3), 0-based indices, three
/// different vertices each; at least one triangle.
std::vector<std::array<int, 3>> face_array(py::handle value, const std::string& name, std::size_t vertex_count);

/// A new float64 array of shape (points.size() / rows, rows, 3) ((N, 3) for rows 0).
py::array_t<double> points_to_array(const std::vector<Vec3>& points, std::size_t rows);

}  // namespace tecido::python
