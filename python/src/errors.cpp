#include "errors.h"

#include "comparisons/cli/error_line.h"
#include "comparisons/io/input_error.h"
#include "comparisons/io/output_error.h"

#include <filesystem>

namespace tecido::python {

namespace {

std::string python_problem(py::error_already_set& error) {
  std::string type = "Exception";
  if (error.type()) type = py::str(error.type().attr("__name__"));
  const std::string text = py::str(error.value());
  return text.empty() ? type : type + ": " + text;
}

std::shared_ptr<PyObject> held_reference(py::error_already_set& error) {
  PyObject* value = error.value().ptr();
  if (!value) return nullptr;
  Py_INCREF(value);
  return std::shared_ptr<PyObject>(value, [](PyObject* o) {
    if (!Py_IsInitialized()) return;
    py::gil_scoped_acquire gil;
    Py_DECREF(o);
  });
}

/// Sets the Python error `type` with `message` on one line, and `cause` (a new reference) as its __cause__.
void set_error(PyObject* type, const std::string& message, PyObject* cause = nullptr) {
  PyErr_SetString(type, cli::one_line(message).c_str());
  if (!cause) return;
  PyObject *t = nullptr, *v = nullptr, *tb = nullptr;
  PyErr_Fetch(&t, &v, &tb);
  PyErr_NormalizeException(&t, &v, &tb);
  PyException_SetCause(v, cause);  // steals the reference
  PyErr_Restore(t, v, tb);
}

}  // namespace

PythonEngineError::PythonEngineError(const std::string& door, const std::string& where, py::error_already_set& error)
    : outside::EngineError(door, where, python_problem(error)), cause_(held_reference(error)) {}

PyObject* PythonEngineError::cause() const {
  if (!cause_) return nullptr;
  Py_INCREF(cause_.get());
  return cause_.get();
}

void register_errors(py::module_& m) {
  static py::exception<outside::EngineError> engine_error(m, "EngineError", PyExc_RuntimeError);
  engine_error.doc() =
      "An engine failed: a Python engine raised (the original exception is __cause__; the message names the "
      "engine, the query and the exception), answered outside the protocol, or an outside engine's door broke.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const PythonEngineError& e) {
      set_error(engine_error.ptr(), e.what(), e.cause());
    } catch (const outside::EngineError& e) {
      set_error(engine_error.ptr(), e.what());
    } catch (const io::FileError& e) {
      set_error(PyExc_OSError, e.what());
    } catch (const io::InputError& e) {
      set_error(PyExc_ValueError, e.what());
    } catch (const io::UsageError& e) {
      set_error(PyExc_ValueError, e.what());
    } catch (const io::OutputError& e) {
      set_error(PyExc_OSError, e.what());
    } catch (const std::filesystem::filesystem_error& e) {
      set_error(PyExc_OSError, e.path1().string() + ": " + e.code().message());
    }
  });
}

}  // namespace tecido::python
