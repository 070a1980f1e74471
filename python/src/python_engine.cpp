#include "python_engine.h"

#include "arrays.h"
#include "errors.h"
#include "json_bridge.h"
#include "python_simulation.h"

#include "comparisons/engines/outside/plugin_library.h"
#include "comparisons/engines/outside/process_protocol.h"
#include "comparisons/io/input_error.h"

#include <pybind11/numpy.h>

#include <cmath>

namespace tecido::python {

namespace {

bool has(const py::object& o, const char* method) { return py::hasattr(o, method); }

bool is_bool(py::handle v) {
  if (PyBool_Check(v.ptr())) return true;
  return py::str(py::type::handle_of(v).attr("__name__")).cast<std::string>() == "bool_";
}

bool is_number(py::handle v) {
  if (PyFloat_Check(v.ptr()) || PyLong_Check(v.ptr())) return true;
  return py::isinstance(v, py::module_::import("numpy").attr("number"));
}

std::string type_of(py::handle v) { return py::str(py::type::handle_of(v).attr("__name__")); }

/// One scalar of an answer as JSON; ProtocolError for another type.
io::Json scalar_json(py::handle v) {
  if (v.is_none()) return nullptr;
  if (is_bool(v)) return v.cast<bool>();
  if (is_number(v)) return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
  throw outside::ProtocolError("a value of type " + type_of(v) + " where a boolean, a number or None belongs");
}

/// The (N, rows, 3) float64 array of a batch's points.
py::array_t<double> batch_array(const std::vector<Vec3>& points, std::size_t rows) { return points_to_array(points, rows); }

py::list point_list(const Vec3* p, std::size_t n) {
  py::list l(n);
  for (std::size_t k = 0; k < n; ++k) l[k] = py::make_tuple(p[k].x(), p[k].y(), p[k].z());
  return l;
}

/// The N answers of a batch method, as a list; ProtocolError when not a sequence of N.
std::vector<py::object> batch_answers(const py::object& r, std::size_t n) {
  if (!py::isinstance<py::sequence>(r) && !py::hasattr(r, "__len__"))
    throw outside::ProtocolError("expected a sequence of " + std::to_string(n) + " answers, got " + type_of(r));
  const py::sequence s = py::reinterpret_borrow<py::sequence>(r);
  if (py::len(s) != n)
    throw outside::ProtocolError("expected " + std::to_string(n) + " answers, got " + std::to_string(py::len(s)));
  std::vector<py::object> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) out.push_back(s[k]);
  return out;
}

/// A tri_tri answer whose meaning needs no JSON reply: True, False or None, alone or as
/// {"hit": b}, exactly what parse_tri_tri makes of {"hit": b}, written into `out`. False for any
/// other answer (the JSON path decides it).
bool direct_hit(py::handle r, std::vector<std::optional<bool>>& out) {
  if (PyDict_CheckExact(r.ptr()) && PyDict_Size(r.ptr()) == 1) {
    PyObject* hit = PyDict_GetItemString(r.ptr(), "hit");
    return hit && (PyBool_Check(hit) || hit == Py_None) && direct_hit(hit, out);
  }
  if (PyBool_Check(r.ptr())) {
    out.push_back(r.ptr() == Py_True);
    return true;
  }
  if (!r.is_none()) return false;
  out.emplace_back();
  return true;
}

/// A ccd answer whose meaning needs no JSON reply: {"hit": b, "toi": t} or (b, t) with b True,
/// False or None and t None or a finite float, exactly what parse_ccd makes of the same reply,
/// written into `out` (hit true with a toi of None is an error: left to the JSON path, which
/// words it). False for any other answer.
bool direct_ccd(py::handle r, std::vector<std::optional<CcdAnswer>>& out) {
  PyObject *hit = nullptr, *toi = nullptr;
  if (PyDict_CheckExact(r.ptr()) && PyDict_Size(r.ptr()) == 2) {
    hit = PyDict_GetItemString(r.ptr(), "hit");
    toi = PyDict_GetItemString(r.ptr(), "toi");
  } else if (PyTuple_CheckExact(r.ptr()) && PyTuple_GET_SIZE(r.ptr()) == 2) {
    hit = PyTuple_GET_ITEM(r.ptr(), 0);
    toi = PyTuple_GET_ITEM(r.ptr(), 1);
  }
  if (!hit || !toi) return false;
  const bool toi_finite = PyFloat_CheckExact(toi) && std::isfinite(PyFloat_AS_DOUBLE(toi));
  if (toi != Py_None && !toi_finite) return false;
  if (hit == Py_None) {
    out.emplace_back();
  } else if (hit == Py_False) {
    out.push_back(CcdAnswer{false, 0.0});
  } else if (hit == Py_True && toi_finite) {
    out.push_back(CcdAnswer{true, PyFloat_AS_DOUBLE(toi)});
  } else {
    return false;
  }
  return true;
}

}  // namespace

io::Json answer_json(py::handle answer, std::initializer_list<const char*> fields) {
  if (py::isinstance<py::dict>(answer)) return from_python(answer, "answer");
  io::Json j = io::Json::object();
  if (py::isinstance<py::tuple>(answer) || py::isinstance<py::list>(answer)) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(answer);
    if (py::len(s) != fields.size())
      throw outside::ProtocolError("expected a tuple of " + std::to_string(fields.size()) + ", got " +
                                   std::to_string(py::len(s)) + " values");
    std::size_t k = 0;
    for (const char* f : fields) j[f] = scalar_json(s[k++]);
    return j;
  }
  j[*fields.begin()] = scalar_json(answer);
  return j;
}

PythonEngine::PythonEngine(py::object engine) : engine_(std::move(engine)) {
  const py::handle type = py::type::handle_of(engine_);
  type_name_ = py::str(type.attr("__module__")).cast<std::string>() + "." + py::str(type.attr("__qualname__")).cast<std::string>();
  const py::object name = py::getattr(engine_, "name", py::none());
  if (name.is_none()) name_ = py::str(type.attr("__name__"));
  else if (py::isinstance<py::str>(name)) name_ = name.cast<std::string>();
  else throw io::UsageError("engine " + type_name_ + ": its name attribute is a " + type_of(name) + ", not a string");
  if (!outside::valid_engine_name(name_))
    throw io::UsageError("engine " + type_name_ + ": engine name \"" + name_ + "\" is not 1-64 of [A-Za-z0-9_.-]");
  tri_tri_batch_ = has(engine_, "tri_tri_batch");
  ccd_batch_ = has(engine_, "ccd_batch");
  capabilities_.tri_tri = tri_tri_batch_ || has(engine_, "tri_tri");
  capabilities_.ccd_vertex_face = capabilities_.ccd_edge_edge = ccd_batch_ || has(engine_, "ccd");
  capabilities_.dynamics = has(engine_, "create") && has(engine_, "step");
  if (!capabilities_.tri_tri && !capabilities_.ccd_vertex_face && !capabilities_.dynamics)
    throw io::UsageError("engine " + name_ + " (Python object " + type_name_ +
                         "): it has none of the methods tri_tri, tri_tri_batch, ccd, ccd_batch, create and step");
  const py::object order = py::getattr(engine_, "order", py::none());
  if (!order.is_none()) {
    if (!is_number(order) || is_bool(order))
      throw io::UsageError(error_door() + ": its order attribute is a " + type_of(order) + ", not a number");
    order_ = py::float_(order).cast<double>();
  }
}

PythonEngine::~PythonEngine() {
  if (!Py_IsInitialized()) {
    engine_.release();  // the interpreter is gone: nothing to give back
    return;
  }
  py::gil_scoped_acquire gil;
  engine_ = py::object();
}

void PythonEngine::fail(const std::string& where, const std::string& problem) const {
  throw outside::EngineError(error_door(), where, problem);
}

py::object PythonEngine::call(const char* method, const std::string& where, const py::tuple& args) {
  try {
    return engine_.attr(method)(*args);
  } catch (py::error_already_set& e) {
    throw PythonEngineError(error_door(), where, e);
  }
}

std::vector<std::optional<bool>> PythonEngine::tri_tri(const std::vector<outside::TriTriQuery>& queries) {
  py::gil_scoped_acquire gil;
  std::vector<std::optional<bool>> out;
  out.reserve(queries.size());
  auto parse = [&](py::handle r, std::size_t k, const char* op) {
    if (direct_hit(r, out)) return;
    try {
      out.push_back(outside::parse_tri_tri(answer_json(r, {"hit"})));
    } catch (const outside::ProtocolError& p) {
      fail("query " + std::to_string(k) + " (" + op + ")", p.what());
    }
  };
  if (tri_tri_batch_) {
    if (queries.empty()) return out;
    std::vector<Vec3> a, b;
    for (const auto& q : queries) a.insert(a.end(), q.a.begin(), q.a.end()), b.insert(b.end(), q.b.begin(), q.b.end());
    const std::string where = "queries 0-" + std::to_string(queries.size() - 1) + " (tri_tri_batch)";
    const py::object r = call("tri_tri_batch", where, py::make_tuple(batch_array(a, 3), batch_array(b, 3)));
    std::vector<py::object> answers;
    try {
      answers = batch_answers(r, queries.size());
    } catch (const outside::ProtocolError& p) {
      fail(where, p.what());
    }
    for (std::size_t k = 0; k < answers.size(); ++k) parse(answers[k], k, "tri_tri_batch");
    return out;
  }
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const std::string where = "query " + std::to_string(k) + " (tri_tri)";
    parse(call("tri_tri", where, py::make_tuple(point_list(queries[k].a.data(), 3), point_list(queries[k].b.data(), 3))), k,
          "tri_tri");
  }
  return out;
}

std::vector<std::optional<SegmentPlaneHit>> PythonEngine::segment_plane(const std::vector<outside::SegmentPlaneQuery>&) {
  fail("op plane", "a Python engine does not answer segment-plane queries");
}

std::vector<std::optional<CcdAnswer>> PythonEngine::ccd(const std::vector<CcdQuery>& queries) {
  py::gil_scoped_acquire gil;
  std::vector<std::optional<CcdAnswer>> out;
  out.reserve(queries.size());
  auto parse = [&](py::handle r, std::size_t k, const char* op) {
    if (direct_ccd(r, out)) return;
    try {
      out.push_back(outside::parse_ccd(answer_json(r, {"hit", "toi"})));
    } catch (const outside::ProtocolError& p) {
      fail("query " + std::to_string(k) + " (" + op + ")", p.what());
    }
  };
  if (ccd_batch_) {
    if (queries.empty()) return out;
    std::vector<Vec3> x0, x1;
    py::list kinds(queries.size());
    for (std::size_t k = 0; k < queries.size(); ++k) {
      x0.insert(x0.end(), queries[k].x0.begin(), queries[k].x0.end());
      x1.insert(x1.end(), queries[k].x1.begin(), queries[k].x1.end());
      kinds[k] = py::str(ccd_kind_name(queries[k].kind));
    }
    const std::string where = "queries 0-" + std::to_string(queries.size() - 1) + " (ccd_batch)";
    const py::object r = call("ccd_batch", where, py::make_tuple(kinds, batch_array(x0, 4), batch_array(x1, 4)));
    std::vector<py::object> answers;
    try {
      answers = batch_answers(r, queries.size());
    } catch (const outside::ProtocolError& p) {
      fail(where, p.what());
    }
    for (std::size_t k = 0; k < answers.size(); ++k) parse(answers[k], k, "ccd_batch");
    return out;
  }
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const CcdQuery& q = queries[k];
    const std::string where = "query " + std::to_string(k) + " (ccd)";
    parse(call("ccd", where, py::make_tuple(ccd_kind_name(q.kind), point_list(q.x0.data(), 4), point_list(q.x1.data(), 4))),
          k, "ccd");
  }
  return out;
}

outside::Creation PythonEngine::create(const Scene& scene) {
  scene_.take(error_door(), "the Python object");
  outside::Creation c;
  try {
    std::optional<std::string> refusal;
    {
      py::gil_scoped_acquire gil;
      const io::Json request = outside::create_request(scene);
      const py::object r = call("create", "op create", py::make_tuple(to_python(request["scene"]), to_python(request["features"])));
      try {
        if (r.is_none() || (PyBool_Check(r.ptr()) && r.ptr() == Py_True)) refusal = std::nullopt;
        else if (py::isinstance<py::str>(r)) refusal = r.cast<std::string>();
        else if (py::isinstance<py::dict>(r)) refusal = outside::parse_create(from_python(r, "reply"));
        else throw outside::ProtocolError("expected None, True, a reason (str) or a dict, got " + type_of(r));
      } catch (const outside::ProtocolError& p) {
        fail("op create", p.what());
      }
    }
    if (refusal) {
      release_scene();
      c.refusal = refusal->empty() ? "refused the scene without a reason" : *refusal;
      return c;
    }
    c.simulation = std::make_unique<PythonSimulation>(shared_from_this(), scene);
  } catch (...) {
    release_scene();
    throw;
  }
  return c;
}

}  // namespace tecido::python
