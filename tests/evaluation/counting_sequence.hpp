#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "evaluation/config/experiment_config.hpp"

namespace radarpr::testing {

// A sequence that counts the scans decoded through it.
class CountingSequence final : public ScanSequence {
 public:
  CountingSequence(std::unique_ptr<ScanSequence> inner, std::atomic<std::size_t>& loads)
      : inner_(std::move(inner)), loads_(loads) {}
  std::string name() const override { return inner_->name(); }
  std::string fingerprint() const override { return inner_->fingerprint(); }
  const std::vector<ScanRecord>& records() const override { return inner_->records(); }
  PolarImage load_image(std::size_t index) const override {
    ++loads_;
    return inner_->load_image(index);
  }
  PositionFrame position_frame() const override { return inner_->position_frame(); }
  DatasetReport describe() const override { return inner_->describe(); }

 private:
  std::unique_ptr<ScanSequence> inner_;
  std::atomic<std::size_t>& loads_;
};

// Makes every sequence `spec` opens count its decoded scans in `loads`.
inline void count_loads(SequenceConfig& spec, std::atomic<std::size_t>& loads) {
  spec.open = [open = spec.open, &loads] {
    return std::make_unique<CountingSequence>(open(), loads);
  };
}

}  // namespace radarpr::testing
