// The `radarpr` Python module: radarpr's descriptors, datasets and evaluation over numpy arrays
// (docs/python.md).
#include <string>

#include <pybind11/pybind11.h>

#include "evaluation/version.hpp"
#include "python/bindings.hpp"

PYBIND11_MODULE(radarpr, module) {
  module.doc() = R"(Radar place recognition: radarpr's descriptors, datasets and evaluation.

Scans are numpy uint8 arrays, azimuths x range bins; descriptor values are float32 arrays. See
docs/python.md in the radarpr repository.)";
  module.attr("__version__") = std::string(radarpr::radarpr_version());
  radarpr::python::bind_errors(module);
  radarpr::python::bind_scans(module);
  radarpr::python::bind_descriptors(module);
  radarpr::python::bind_evaluation(module);
  radarpr::python::bind_datasets(module);
  radarpr::python::bind_results(module);
  radarpr::python::bind_run(module);
  radarpr::python::bind_registration(module);
}
