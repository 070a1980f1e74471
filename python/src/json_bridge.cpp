#include "json_bridge.h"

#include "comparisons/io/input_error.h"

namespace tecido::python {

py::object to_python(const io::Json& doc) { return py::module_::import("json").attr("loads")(doc.dump()); }

io::Json from_python(py::handle value, const std::string& name) {
  const py::module_ json = py::module_::import("json");
  const py::object ndarray = py::module_::import("numpy").attr("ndarray");
  const py::object generic = py::module_::import("numpy").attr("generic");
  const py::cpp_function as_list([ndarray, generic](py::handle o) -> py::object {
    if (py::isinstance(o, ndarray) || py::isinstance(o, generic)) return o.attr("tolist")();
    throw py::type_error("a value of type " + std::string(py::str(py::type::handle_of(o).attr("__name__"))) +
                         " is not JSON");
  });
  std::string text;
  try {
    text = py::str(json.attr("dumps")(value, py::arg("allow_nan") = false, py::arg("default") = as_list));
  } catch (py::error_already_set& e) {
    const std::string why = py::str(e.value());
    throw io::InputError(name, "", "not a JSON document: " + why);
  }
  return io::parse_json_text(text, name);
}

}  // namespace tecido::python
