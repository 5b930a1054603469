#pragma once

#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "descriptors/descriptor.hpp"

namespace radarpr {

// The sequence whose values an external source is asked for: where it sits in the experiment
// (the dataset's name and the role "query", "database" or "training") and its scans' records.
struct ExternalSequence {
  std::string dataset;
  std::string role;
  std::string name;  // ScanSequence::name(), for messages
  const std::vector<ScanRecord>& records;
};

// Implemented, beside Descriptor, by descriptors whose values come from outside radarpr instead
// of from the scans' images (`precomputed`): the evaluation asks for a whole sequence's values at
// once, one per record in order, and never calls extract() or decodes a scan for them. Such
// values are not stored in the descriptor cache: reading them again is as cheap as a cache entry.
class ExternalValues {
 public:
  virtual ~ExternalValues() = default;
  // Throws std::runtime_error naming the files and the first offending rows or scans.
  virtual std::vector<DescriptorValue> values_for(const ExternalSequence& sequence) const = 0;
};

// The descriptor's ExternalValues side, or nullptr for a descriptor of images.
inline const ExternalValues* external_values_of(const Descriptor& descriptor) {
  return dynamic_cast<const ExternalValues*>(&descriptor);
}

}  // namespace radarpr
