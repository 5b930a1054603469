#include "python/json_values.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace radarpr::python {

nlohmann::json json_from_python(const py::handle& object, const std::string& what) {
  if (object.is_none()) return nullptr;
  // bool before int: Python's True is an int too.
  if (py::isinstance<py::bool_>(object)) return object.cast<bool>();
  if (py::isinstance<py::int_>(object)) return object.cast<std::int64_t>();
  if (py::isinstance<py::float_>(object)) {
    const double number = object.cast<double>();
    if (!std::isfinite(number)) {
      throw std::invalid_argument(
          fmt::format("{}: expected a finite number, got {}", what, number));
    }
    return number;
  }
  if (py::isinstance<py::str>(object)) return object.cast<std::string>();
  if (py::hasattr(object, "__fspath__")) {
    return py::str(py::module_::import("os").attr("fspath")(object)).cast<std::string>();
  }
  if (py::isinstance<py::dict>(object)) {
    nlohmann::json json = nlohmann::json::object();
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(object)) {
      if (!py::isinstance<py::str>(key)) {
        throw std::invalid_argument(fmt::format("{}: keys must be strings, got {}", what,
                                                py::repr(key).cast<std::string>()));
      }
      const std::string name = key.cast<std::string>();
      json[name] = json_from_python(value, what + "." + name);
    }
    return json;
  }
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object)) {
    nlohmann::json json = nlohmann::json::array();
    std::size_t index = 0;
    for (const auto& item : object) {
      json.push_back(json_from_python(item, fmt::format("{}[{}]", what, index++)));
    }
    return json;
  }
  // numpy scalars (np.float64(20.0), np.int64(3)) convert through their Python value.
  if (py::hasattr(object, "item") && py::hasattr(object, "dtype") &&
      py::len(object.attr("shape")) == 0) {
    return json_from_python(object.attr("item")(), what);
  }
  throw std::invalid_argument(
      fmt::format("{}: expected a dict, list, str, number, bool or None, got a {}", what,
                  py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>()));
}

py::object python_from_json(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(value.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(value.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& item : value) list.append(python_from_json(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = python_from_json(item);
      return dict;
    }
    default:
      return py::none();  // binary and discarded values never occur in radarpr's JSON
  }
}

}  // namespace radarpr::python
