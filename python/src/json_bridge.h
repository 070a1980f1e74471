#pragma once
/// JSON documents between tecido (io::Json) and Python (dicts, lists, numbers, strings, None),
/// through Python's json module: the same documents the files and the JSON-lines door carry.
#include "comparisons/io/json_reader.h"

#include <pybind11/pybind11.h>

#include <string>

namespace tecido::python {

namespace py = pybind11;

/// A Python value of the document (the GIL held).
py::object to_python(const io::Json& doc);

/// The document of a Python value (dicts, lists, tuples, numbers, strings, booleans, None; numpy
/// arrays and scalars as their .tolist()). A value JSON cannot hold (NaN, infinity, another type)
/// is io::InputError(name, "", problem).
io::Json from_python(py::handle value, const std::string& name);

}  // namespace tecido::python
