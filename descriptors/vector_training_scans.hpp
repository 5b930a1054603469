#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "datasets/polar_image.hpp"
#include "descriptors/descriptor.hpp"

namespace radarpr {

// Training scans already in memory: for tests, benchmarks and library callers that train a
// descriptor on images they hold (the runner trains on a dataset session instead).
class VectorTrainingScans final : public TrainingScans {
 public:
  VectorTrainingScans(std::vector<PolarImage> scans, std::string description)
      : scans_(std::move(scans)), description_(std::move(description)) {}

  std::size_t size() const override { return scans_.size(); }
  PolarImage load(std::size_t index) const override {
    if (index >= scans_.size()) {
      throw std::out_of_range("training scan " + std::to_string(index) + " of " + description_ +
                              " (" + std::to_string(scans_.size()) + " scans)");
    }
    // A copy (ByteImage copies are deep): load() hands out a scan by value, as sequences decode
    // theirs. Training reads each scan about once, so this is not a hot path.
    return scans_[index];
  }
  std::string description() const override { return description_; }

 private:
  std::vector<PolarImage> scans_;
  std::string description_;
};

}  // namespace radarpr
