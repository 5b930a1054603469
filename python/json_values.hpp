#pragma once

#include <string>

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace radarpr::python {

namespace py = pybind11;

// Python dicts, lists, str, int, float, bool, None (and os.PathLike, as its path) as JSON, the
// form radarpr's configs take. Anything else is a ValueError naming `what` and the key path.
nlohmann::json json_from_python(const py::handle& object, const std::string& what);

// JSON as Python dicts, lists, str, int, float, bool and None.
py::object python_from_json(const nlohmann::json& value);

}  // namespace radarpr::python
