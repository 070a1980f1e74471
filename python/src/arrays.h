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
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace tecido::python {

namespace py = pybind11;

/// A float64 array of N blocks of `rows` points, shape and dtype checked, read in place: point(i, j)
/// checks the coordinates as it reads them. Holds a reference to the array, so it may be read
/// with the GIL released.
class PointBlocks {
 public:
  /// Shape (N, rows, 3), or (N, 3) when rows is 0; io::UsageError for another shape or dtype.
  PointBlocks(py::handle value, const std::string& name, std::size_t rows, double max_abs);
  std::size_t size() const { return n_; }
  /// Point j of block i; io::InputError(name, "/i/j/c", ...) for a non-finite or out-of-range coordinate.
  Vec3 point(std::size_t i, std::size_t j) const {
    const char* p = base_ + static_cast<py::ssize_t>(i) * s0_ + static_cast<py::ssize_t>(j) * s1_;
    Vec3 v;
    for (std::size_t c = 0; c < 3; ++c) {
      const double x = *reinterpret_cast<const double*>(p + static_cast<py::ssize_t>(c) * s2_);
      if (!(std::abs(x) <= max_abs_)) bad_coordinate(i, j, c, x);
      v[static_cast<Eigen::Index>(c)] = x;
    }
    return v;
  }

 private:
  [[noreturn]] void bad_coordinate(std::size_t i, std::size_t j, std::size_t c, double x) const;
  py::array array_;
  std::string name_;
  bool blocks_;
  double max_abs_;
  std::size_t n_ = 0;
  const char* base_ = nullptr;
  py::ssize_t s0_ = 0, s1_ = 0, s2_ = 0;
};

/// `value` as N blocks of `rows` points, row-major (N * rows points): shape (N, rows, 3), or
/// (N, 3) when rows is 0 (N points). |coordinate| <= max_abs. `name` names the argument.
std::vector<Vec3> point_array(py::handle value, const std::string& name, std::size_t rows, double max_abs);

/// Triangles of `vertex_count` vertices: an integer array of shape (M, 3), 0-based indices, three
/// different vertices each; at least one triangle.
std::vector<std::array<int, 3>> face_array(py::handle value, const std::string& name, std::size_t vertex_count);

/// A new float64 array of shape (points.size() / rows, rows, 3) ((N, 3) for rows 0).
py::array_t<double> points_to_array(const std::vector<Vec3>& points, std::size_t rows);

}  // namespace tecido::python
