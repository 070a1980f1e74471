#include "arrays.h"

#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"

#include <cmath>
#include <sstream>

namespace tecido::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t k = 0; k < a.ndim(); ++k) s += (k ? ", " : "") + std::to_string(a.shape(k));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtype_text(const py::array& a) { return py::str(a.dtype()); }

/// numpy.asarray(value): an ndarray as it is, a list read by numpy.
py::array as_array(py::handle value, const std::string& name) {
  try {
    return py::module_::import("numpy").attr("asarray")(value);
  } catch (py::error_already_set& e) {
    throw io::UsageError(name + ": not an array: " + std::string(py::str(e.value())));
  }
}

void check_shape(const py::array& a, const std::string& name, const std::vector<py::ssize_t>& trailing,
                 const std::string& expected) {
  bool ok = a.ndim() == static_cast<py::ssize_t>(trailing.size() + 1);
  for (std::size_t k = 0; ok && k < trailing.size(); ++k) ok = a.shape(static_cast<py::ssize_t>(k + 1)) == trailing[k];
  if (!ok) throw io::UsageError(name + ": expected an array of shape " + expected + ", got shape " + shape_text(a));
}

}  // namespace

PointBlocks::PointBlocks(py::handle value, const std::string& name, std::size_t rows, double max_abs)
    : array_(as_array(value, name)), name_(name), blocks_(rows > 0), max_abs_(max_abs) {
  const std::string expected = blocks_ ? "(N, " + std::to_string(rows) + ", 3)" : "(N, 3)";
  check_shape(array_, name, blocks_ ? std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows), 3} : std::vector<py::ssize_t>{3},
              expected);
  if (!py::isinstance<py::array_t<double, 0>>(array_))
    throw io::UsageError(name + ": dtype " + dtype_text(array_) + ", expected float64 (tecido converts no dtype: pass " +
                         "numpy.asarray(" + name + ", dtype=numpy.float64))");
  n_ = static_cast<std::size_t>(array_.shape(0));
  base_ = static_cast<const char*>(array_.data());
  s0_ = array_.strides(0);
  s1_ = blocks_ ? array_.strides(1) : 0;
  s2_ = array_.strides(blocks_ ? 2 : 1);
}

void PointBlocks::bad_coordinate(std::size_t i, std::size_t j, std::size_t c, double x) const {
  std::ostringstream s;
  if (!std::isfinite(x)) s << "number is not finite (" << x << ")";
  else s << "number " << x << " is out of range (|x| <= " << max_abs_ << ")";
  const std::string where = "/" + std::to_string(i) + (blocks_ ? "/" + std::to_string(j) : "") + "/" + std::to_string(c);
  throw io::InputError(name_, where, s.str());
}

std::vector<Vec3> point_array(py::handle value, const std::string& name, std::size_t rows, double max_abs) {
  const PointBlocks a(value, name, rows, max_abs);
  const std::size_t r = rows ? rows : 1;
  std::vector<Vec3> out;
  out.reserve(a.size() * r);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < r; ++j) out.push_back(a.point(i, j));
  return out;
}

std::vector<std::array<int, 3>> face_array(py::handle value, const std::string& name, std::size_t vertex_count) {
  const py::array a = as_array(value, name);
  check_shape(a, name, {3}, "(M, 3)");
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw io::UsageError(name + ": dtype " + dtype_text(a) + ", expected integers (vertex indices)");
  const std::size_t m = static_cast<std::size_t>(a.shape(0));
  if (m == 0) throw io::InputError(name, "", "the mesh has no face");
  if (m > io::kMaxMeshTriangles)
    throw io::InputError(name, "", "more than " + std::to_string(io::kMaxMeshTriangles) + " triangles (the limit)");
  const py::array_t<long long, py::array::forcecast> idx(a);  // integers of any width, exactly
  const auto f = idx.unchecked<2>();
  std::vector<std::array<int, 3>> out(m);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const long long v = f(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(c));
      const std::string where = "/" + std::to_string(i) + "/" + std::to_string(c);
      if (v < 0 || static_cast<unsigned long long>(v) >= vertex_count)
        throw io::InputError(name, where,
                             "face names missing vertex " + std::to_string(v) + " (the mesh has " +
                                 std::to_string(vertex_count) + " vertices, indices from 0)");
      out[i][c] = static_cast<int>(v);
      for (std::size_t d = 0; d < c; ++d)
        if (out[i][d] == out[i][c])
          throw io::InputError(name, where, "degenerate face: vertex " + std::to_string(v) + " is repeated");
    }
  return out;
}

py::array_t<double> points_to_array(const std::vector<Vec3>& points, std::size_t rows) {
  const std::size_t r = rows ? rows : 1;
  std::vector<py::ssize_t> shape = {static_cast<py::ssize_t>(points.size() / r)};
  if (rows) shape.push_back(static_cast<py::ssize_t>(rows));
  shape.push_back(3);
  py::array_t<double> out(shape);
  double* p = out.mutable_data();
  for (const Vec3& v : points)
    for (int c = 0; c < 3; ++c) *p++ = v[c];
  return out;
}

}  // namespace tecido::python
