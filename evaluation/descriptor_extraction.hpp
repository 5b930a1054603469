#pragma once

#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr {

struct ExtractedDescriptors {
  std::vector<std::vector<DescriptorValue>> values;  // [descriptor][scan]
  std::vector<double> mean_extract_ms;               // [descriptor], wall time per scan
};

// Decodes every scan of `sequence` once and runs every descriptor on it, in parallel over scans.
// An extraction error names the scan's source.
ExtractedDescriptors extract_descriptors(const ScanSequence& sequence,
                                         const std::vector<DescriptorInstance>& descriptors,
                                         int threads, const std::string& progress_label,
                                         bool show_progress);

}  // namespace radarpr
