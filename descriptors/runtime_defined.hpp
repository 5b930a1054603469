#pragma once

#include "descriptors/descriptor.hpp"

namespace radarpr {

// Implemented, beside Descriptor, by descriptors defined while the process runs (a Python
// function registered through the Python module, docs/python.md). Their code has no file or build
// that could identify it, so their values are never stored in the descriptor cache: a changed
// function would otherwise be answered with the values of its previous version.
class RuntimeDefined {
 public:
  virtual ~RuntimeDefined() = default;
};

inline bool is_runtime_defined(const Descriptor& descriptor) {
  return dynamic_cast<const RuntimeDefined*>(&descriptor) != nullptr;
}

}  // namespace radarpr
