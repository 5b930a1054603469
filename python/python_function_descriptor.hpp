#pragma once

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "descriptors/descriptor.hpp"
#include "descriptors/runtime_defined.hpp"

namespace radarpr::python {

namespace py = pybind11;

// A Python object kept for the rest of the process: a registered descriptor's functions stay in
// the global registry until exit, after the interpreter has finalised, when no reference may be
// released any more. So the reference is taken once and deliberately never given back.
class PythonCallable {
 public:
  explicit PythonCallable(const py::object& object) : object_(object.inc_ref().ptr()) {}
  py::handle get() const { return object_; }

 private:
  PyObject* object_;
};

// What register_descriptor was given.
struct PythonDescriptorSpec {
  std::string name;
  std::shared_ptr<const PythonCallable> extract;
  // "l2", "cosine", or empty with `distance` set: a Python function of two values.
  std::string distance_name;
  std::shared_ptr<const PythonCallable> distance;
  DescriptorShape shape;
  bool rotation_invariant = false;
};

// A descriptor whose extraction (and optionally distance) is a Python function. Extraction calls
// into Python with the GIL taken, so several extraction threads take turns. "l2" and "cosine"
// rank exactly as `precomputed` with that distance ranks (a KD-tree over the values, or over
// unit-length values); a Python distance is ranked exhaustively.
class PythonFunctionDescriptor final : public Descriptor, public RuntimeDefined {
 public:
  explicit PythonFunctionDescriptor(PythonDescriptorSpec spec);

  // Calls extract(image, range_resolution): image a read-only uint8 A x R array, the result any
  // array of the declared shape's size, converted to float32. Throws std::runtime_error carrying
  // the Python exception, or naming the shape it returned.
  DescriptorValue extract(const PolarImage& scan) const override;
  double distance(const DescriptorValue& a, const DescriptorValue& b) const override;
  bool rotation_invariant() const override { return spec_.rotation_invariant; }
  DescriptorShape shape(const ScanGeometry& geometry) const override;
  RetrievalMethod retrieval_method() const override;
  std::vector<float> search_key(const DescriptorValue& value) const override;

 private:
  PythonDescriptorSpec spec_;
  std::unique_ptr<Descriptor> ranking_;  // precomputed's l2 / cosine; null for a Python distance
};

}  // namespace radarpr::python
