// radarpr.register_descriptor: a descriptor written in Python, usable in configs run from this
// process.
#include <memory>
#include <regex>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "descriptors/descriptor_registry.hpp"
#include "python/bindings.hpp"
#include "python/python_function_descriptor.hpp"

namespace radarpr::python {
namespace {

DescriptorShape checked_shape(const py::object& shape) {
  std::vector<long long> sides;
  try {
    sides = shape.cast<std::vector<long long>>();
  } catch (const py::cast_error&) {
  }
  if (sides.size() == 1) sides.push_back(1);
  if (sides.size() != 2 || sides[0] < 1 || sides[1] < 1 || sides[0] > 1'000'000'000 ||
      sides[1] > 1'000'000'000 / sides[0]) {
    throw std::invalid_argument(
        fmt::format("shape: expected (rows, cols) or (D,) of positive sizes, got {}",
                    py::repr(shape).cast<std::string>()));
  }
  return {static_cast<int>(sides[0]), static_cast<int>(sides[1])};
}

std::string function_name(const py::object& function) {
  const std::string module =
      py::hasattr(function, "__module__") && !function.attr("__module__").is_none()
          ? py::str(function.attr("__module__")).cast<std::string>()
          : std::string("?");
  const std::string name = py::hasattr(function, "__qualname__")
                               ? py::str(function.attr("__qualname__")).cast<std::string>()
                               : py::repr(function).cast<std::string>();
  return module + "." + name;
}

void register_descriptor(const std::string& name, const py::object& extract,
                         const py::object& distance, const py::object& shape,
                         bool rotation_invariant, const std::string& summary) {
  // The characters a descriptor id and a results folder accept (docs/plugins.md).
  static const std::regex valid_name("[a-z][a-z0-9_]*");
  if (!std::regex_match(name, valid_name)) {
    throw std::invalid_argument(fmt::format(
        "name: expected lower-case letters, digits and '_', starting with a letter, got '{}'",
        name));
  }
  if (!PyCallable_Check(extract.ptr())) {
    throw std::invalid_argument("extract: expected a function of (image, range_resolution)");
  }
  PythonDescriptorSpec spec;
  spec.name = name;
  spec.extract = std::make_shared<PythonCallable>(extract);
  if (py::isinstance<py::str>(distance)) {
    spec.distance_name = distance.cast<std::string>();
    if (spec.distance_name != "l2" && spec.distance_name != "cosine") {
      throw std::invalid_argument(
          fmt::format("distance: expected 'l2', 'cosine' or a function of two values, got '{}'",
                      spec.distance_name));
    }
  } else if (PyCallable_Check(distance.ptr())) {
    spec.distance = std::make_shared<PythonCallable>(distance);
  } else {
    throw std::invalid_argument("distance: expected 'l2', 'cosine' or a function of two values");
  }
  spec.shape = checked_shape(shape);
  spec.rotation_invariant = rotation_invariant;

  DescriptorRegistry added;
  DescriptorInfo info;
  info.name = name;
  info.summary = summary.empty() ? "Python function " + function_name(extract) : summary;
  info.create = [spec](const ParameterValues&) {
    return std::make_unique<PythonFunctionDescriptor>(spec);
  };
  added.add(std::move(info));
  // Listed as coming from Python, like a plugin from its file; a name taken is refused.
  DescriptorRegistry::add_plugin_descriptors(added, "python " + function_name(extract), "");
}

}  // namespace

void bind_registration(py::module_& module) {
  module.def("register_descriptor", &register_descriptor, py::arg("name"), py::kw_only(),
             py::arg("extract"), py::arg("distance") = "l2", py::arg("shape"),
             py::arg("rotation_invariant") = false, py::arg("summary") = "",
             R"(Register a descriptor written in Python, for configs run from this process.

After registration, ``name`` is a descriptor like any other for ``radarpr.run`` (same retrieval,
metrics, tables and report), ``radarpr.Descriptor`` and ``radarpr.descriptors()``.

Parameters
----------
name : str
    Lower-case letters, digits and '_', starting with a letter; not a registered name.
extract : callable
    ``extract(image, range_resolution)``: image a read-only uint8 numpy array (azimuths x range
    bins), range_resolution in metres per bin; returns an array of ``shape``'s size (converted
    to float32).
distance : {'l2', 'cosine'} or callable
    'l2' and 'cosine' rank exactly as the ``precomputed`` descriptor with that distance (a
    KD-tree); a function ``distance(a, b) -> float`` of two float32 values (smaller = more
    similar) is ranked exhaustively.
shape : tuple of int
    (rows, cols) of every value, or (D,) for D x 1.
rotation_invariant : bool
    What the author claims; shown in the tables.
summary : str
    One line for listings.

Raises
------
ValueError
    A bad name, shape or distance, or a name already registered.

Notes
-----
Extraction calls into Python with the GIL held, so extraction threads take turns. Values of a
Python descriptor are never stored in the descriptor cache. Registrations last for the process.
)");
}

}  // namespace radarpr::python
