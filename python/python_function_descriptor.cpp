#include "python/python_function_descriptor.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include "descriptors/precomputed/precomputed.hpp"
#include "python/numpy_arrays.hpp"

namespace radarpr::python {

PythonFunctionDescriptor::PythonFunctionDescriptor(PythonDescriptorSpec spec)
    : spec_(std::move(spec)) {
  if (spec_.distance_name == "l2" || spec_.distance_name == "cosine") {
    PrecomputedParams params;
    params.distance =
        spec_.distance_name == "l2" ? PrecomputedDistance::l2 : PrecomputedDistance::cosine;
    ranking_ = std::make_unique<PrecomputedDescriptor>(params);
  }
}

DescriptorValue PythonFunctionDescriptor::extract(const PolarImage& scan) const {
  py::gil_scoped_acquire locked;
  try {
    const py::object result =
        // A copy the array owns: the function may keep the array after the scan is gone.
        spec_.extract->get()(image_array(ByteImage(scan.power)), scan.range_resolution_m);
    const auto values =
        py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(result);
    if (!values || static_cast<std::size_t>(values.size()) != spec_.shape.element_count()) {
      throw std::runtime_error(
          fmt::format("descriptor '{}': extract returned {}, expected {} numbers (shape {}x{})",
                      spec_.name, describe_object(result), spec_.shape.element_count(),
                      spec_.shape.rows, spec_.shape.cols));
    }
    DescriptorValue value{spec_.shape.rows, spec_.shape.cols,
                          std::vector<float>(values.data(), values.data() + values.size())};
    for (float element : value.values) {
      if (!std::isfinite(element)) {
        throw std::runtime_error(
            fmt::format("descriptor '{}': extract returned a value that is not finite ({})",
                        spec_.name, element));
      }
    }
    return value;
  } catch (py::error_already_set& error) {
    // Carried as text: the Python exception object must not outlive the GIL held here.
    throw std::runtime_error(
        fmt::format("descriptor '{}': extract raised {}", spec_.name, error.what()));
  }
}

double PythonFunctionDescriptor::distance(const DescriptorValue& a,
                                          const DescriptorValue& b) const {
  if (ranking_) return ranking_->distance(a, b);
  py::gil_scoped_acquire locked;
  try {
    const double result = spec_.distance->get()(value_array(a), value_array(b)).cast<double>();
    if (!std::isfinite(result)) {
      throw std::runtime_error(fmt::format(
          "descriptor '{}': distance returned {}, expected a finite number", spec_.name, result));
    }
    return result;
  } catch (py::error_already_set& error) {
    throw std::runtime_error(
        fmt::format("descriptor '{}': distance raised {}", spec_.name, error.what()));
  } catch (const py::cast_error&) {
    throw std::runtime_error(fmt::format(
        "descriptor '{}': distance returned something that is not a number", spec_.name));
  }
}

DescriptorShape PythonFunctionDescriptor::shape(const ScanGeometry& /*geometry*/) const {
  return spec_.shape;
}

RetrievalMethod PythonFunctionDescriptor::retrieval_method() const {
  return ranking_ ? ranking_->retrieval_method() : RetrievalMethod::exhaustive;
}

std::vector<float> PythonFunctionDescriptor::search_key(const DescriptorValue& value) const {
  return ranking_ ? ranking_->search_key(value) : value.values;
}

}  // namespace radarpr::python
