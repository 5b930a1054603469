#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "descriptors/descriptor_registry.hpp"

namespace radarpr::python {

namespace py = pybind11;

// radarpr.Descriptor: one configured descriptor of the global registry.
class PythonDescriptor {
 public:
  explicit PythonDescriptor(const std::string& id);

  const DescriptorInstance& instance() const { return instance_; }

  py::array_t<float> extract(const py::object& scan, std::optional<double> range_resolution,
                             std::optional<std::vector<double>> azimuths) const;
  py::array_t<float> extract_many(const py::object& images, std::optional<double> range_resolution,
                                  int num_threads, int scan_axis) const;
  double distance(const py::object& a, const py::object& b) const;
  double time_extract(const py::object& image, std::optional<double> range_resolution,
                      int repeats) const;
  py::tuple shape(int azimuths, int range_bins, double range_resolution) const;

 private:
  DescriptorInstance instance_;
};

// The registry's descriptor for `id`; an unknown name or a malformed id is a ParameterError
// (radarpr.ConfigError), like a bad parameter.
DescriptorInstance descriptor_from_id(const std::string& id);

// The descriptor of a radarpr.Descriptor object; null for any other object.
const DescriptorInstance* descriptor_of(const py::handle& object);

}  // namespace radarpr::python
