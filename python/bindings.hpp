#pragma once

#include <pybind11/pybind11.h>

// The parts of the `radarpr` Python module, one file each; module.cpp calls them in order.
namespace radarpr::python {

namespace py = pybind11;

// Defines radarpr.ConfigError (a ValueError) and maps radarpr's exceptions to Python's:
// ConfigError and ParameterError -> radarpr.ConfigError, FileError and NpyError -> OSError,
// std::invalid_argument -> ValueError, other std::exception -> RuntimeError; the message is
// radarpr's one line.
void bind_errors(py::module_& module);        // error_translation.cpp
void bind_scans(py::module_& module);         // scan_bindings.cpp
void bind_descriptors(py::module_& module);   // descriptor_bindings.cpp
void bind_evaluation(py::module_& module);    // evaluation_bindings.cpp
void bind_datasets(py::module_& module);      // dataset_bindings.cpp
void bind_results(py::module_& module);       // results_bindings.cpp
void bind_run(py::module_& module);           // run_bindings.cpp
void bind_registration(py::module_& module);  // registration_bindings.cpp

}  // namespace radarpr::python
