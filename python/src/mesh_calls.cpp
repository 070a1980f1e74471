#include "mesh_calls.h"

#include "arrays.h"

#include "comparisons/cli/commands.h"
#include "comparisons/engines/continuous_self_collision_engines.h"
#include "comparisons/engines/self_collision_engines.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/limits.h"

#include <pybind11/numpy.h>

#include <limits>
#include <type_traits>

namespace tecido::python {

namespace {

std::vector<Vec3> vertex_array(py::handle value, const std::string& name) {
  std::vector<Vec3> v = point_array(value, name, 0, std::numeric_limits<double>::max());
  if (v.size() > io::kMaxMeshVertices)
    throw io::InputError(name, "", "more than " + std::to_string(io::kMaxMeshVertices) + " vertices (the limit)");
  return v;
}

/// One name of `known`, checked as --engines checks it.
std::string one_engine(const std::string& engine, const std::vector<std::string>& known, const std::string& what) {
  const auto names = cli::parse_engine_list(engine, known, what, "engine");
  if (names.size() != 1) throw io::UsageError("engine: one engine name, got \"" + engine + "\"");
  return names[0];
}

/// An int64 array of `rows` rows of `shape` (after the first axis) from flat values.
template <class Rows>
py::array_t<long long> index_array(const Rows& rows, std::vector<py::ssize_t> shape) {
  shape.insert(shape.begin(), static_cast<py::ssize_t>(rows.size()));
  py::array_t<long long> out(shape);
  long long* p = out.mutable_data();
  for (const auto& r : rows) {
    for (const auto& x : r) {
      if constexpr (std::is_integral_v<std::decay_t<decltype(x)>>) *p++ = x;
      else
        for (const int y : x) *p++ = y;
    }
  }
  return out;
}

}  // namespace

py::object self_collisions_call(py::handle vertices, py::handle faces, const std::string& engine) {
  std::vector<std::string> known;
  for (const auto& e : self_collision_engines()) known.push_back(e.name);
  const std::string name = one_engine(engine, known, "self-collision");
  const std::vector<Vec3> v = vertex_array(vertices, "V");
  const std::vector<std::array<int, 3>> f = face_array(faces, "F", v.size());
  check_self_collision_size(name, f.size(), "F", "engine");
  std::optional<std::vector<TrianglePair>> pairs;
  {
    py::gil_scoped_release release;
    pairs = find_self_collision_engine(name)->pairs(v, f);
  }
  if (!pairs) throw io::UsageError("engine " + name + " gives no answer for this mesh");
  return index_array(*pairs, {2});
}

py::object continuous_self_collisions_call(py::handle v0, py::handle v1, py::handle faces, const std::string& engine) {
  const std::string name = one_engine(engine, continuous_self_collision_engines(), "continuous self-collision");
  const std::vector<Vec3> x0 = vertex_array(v0, "V0"), x1 = vertex_array(v1, "V1");
  if (x0.size() != x1.size())
    throw io::UsageError("V1: " + std::to_string(x1.size()) + " vertices, but V0 has " + std::to_string(x0.size()) +
                         " (the frames must be one mesh: same vertices, same faces)");
  const std::vector<std::array<int, 3>> f = face_array(faces, "F", x0.size());
  check_continuous_self_collision_size(name, f.size(), "F", "engine");
  ContinuousContacts c;
  {
    py::gil_scoped_release release;
    c = continuous_self_collision_contacts(name, x0, x1, f);
  }
  py::dict out;
  out["vertex_face"] = index_array(c.vertex_face, {2});
  out["edge_edge"] = index_array(c.edge_edge, {2, 2});
  return out;
}

}  // namespace tecido::python
