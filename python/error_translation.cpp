#include "python/error_translation.hpp"

#include "python/bindings.hpp"

#include <exception>

#include "datasets/npy_file.hpp"
#include "descriptors/parameters.hpp"
#include "evaluation/config/config_error.hpp"

namespace radarpr::python {

void bind_errors(py::module_& module) {
  // Kept for the process's lifetime, as the module is (pybind11's documented pattern).
  static py::exception<ConfigError> config_error(module, "ConfigError", PyExc_ValueError);
  config_error.doc() =
      "A problem with an experiment config, a descriptor id or a parameter; the message names "
      "the file and key when known.";
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const ConfigError& error) {
      config_error(error.what());
    } catch (const ParameterError& error) {
      config_error(error.what());
    } catch (const FileError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    } catch (const NpyError& error) {
      PyErr_SetString(PyExc_OSError, error.what());
    }
    // Anything else falls through to pybind11's own translation: invalid_argument ->
    // ValueError, other std::exception -> RuntimeError.
  });
}

}  // namespace radarpr::python
