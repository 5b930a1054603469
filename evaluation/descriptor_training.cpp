#include "evaluation/descriptor_training.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "descriptors/learnt_codebook.hpp"
#include "descriptors/training_progress.hpp"
#include "evaluation/progress.hpp"

namespace radarpr {
namespace {

// A sequence as training scans; counts which scans a descriptor actually loads, so result files
// say what it learnt from rather than what it could have.
class SequenceTrainingScans final : public TrainingScans {
 public:
  explicit SequenceTrainingScans(const ScanSequence& sequence)
      : sequence_(sequence), loaded_(sequence.size(), false) {}
  std::size_t size() const override { return sequence_.size(); }
  PolarImage load(std::size_t index) const override {
    PolarImage image = sequence_.load_image(index);
    bool all_read = false;
    {
      const std::lock_guard lock(mutex_);
      if (!loaded_.at(index)) {
        loaded_[index] = true;
        all_read = ++distinct_ == loaded_.size();
      }
    }
    if (progress_ != nullptr) {
      progress_->advance();
      // What follows is the learning itself (its own lines: report_training_step).
      if (all_read) progress_->finish(all_read_line_);
    }
    return image;
  }
  std::string description() const override { return sequence_.name(); }

  // Counts the scans loaded into `progress` (null: none) from now on, ending it with
  // `all_read_line` once every scan has been read.
  void report_to(Progress* progress, std::string all_read_line = {}) {
    progress_ = progress;
    all_read_line_ = std::move(all_read_line);
  }

  // Forgets what was loaded, for the next descriptor.
  std::size_t take_loaded_count() {
    const std::lock_guard lock(mutex_);
    const auto count = static_cast<std::size_t>(std::count(loaded_.begin(), loaded_.end(), true));
    std::fill(loaded_.begin(), loaded_.end(), false);
    distinct_ = 0;
    return count;
  }

 private:
  const ScanSequence& sequence_;
  mutable std::mutex mutex_;
  mutable std::vector<bool> loaded_;
  mutable std::size_t distinct_ = 0;
  Progress* progress_ = nullptr;
  std::string all_read_line_;
};

// The steps of a descriptor's learning (a codebook's k-means) as progress lines, one Progress per
// stage: "training open_radvlad, k-means iterations (at most 300): 12/300 (9.0 s, ...)".
class LearningProgress {
 public:
  LearningProgress(std::string descriptor_id, bool enabled)
      : descriptor_id_(std::move(descriptor_id)), enabled_(enabled) {}

  void step(std::string_view stage, std::size_t total) {
    if (!progress_ || stage != stage_) {
      stage_ = stage;
      progress_ = std::make_unique<Progress>(fmt::format("training {}, {}", descriptor_id_, stage),
                                             total, enabled_);
    }
    progress_->advance();
  }

 private:
  std::string descriptor_id_;
  bool enabled_;
  std::string stage_;
  std::unique_ptr<Progress> progress_;
};

}  // namespace

TrainedDescriptors train_descriptors(const std::vector<DescriptorInstance>& descriptors,
                                     const ScanSequence& training, bool show_progress,
                                     const std::vector<std::string>& positions) {
  TrainedDescriptors trained;
  SequenceTrainingScans scans(training);
  for (std::size_t d = 0; d < descriptors.size(); ++d) {
    const DescriptorInstance& instance = descriptors[d];
    if (!instance.descriptor->trainable()) {
      trained.instances.push_back(instance);
      trained.training.emplace_back();
      continue;
    }
    if (!instance.create_fresh) {
      throw std::logic_error(fmt::format(
          "descriptor {} is trainable but cannot create a fresh instance", instance.id));
    }
    if (show_progress) {
      fmt::print(stderr, "  training {}{} on {} ({} scans)\n", instance.id,
                 d < positions.size() ? positions[d] : std::string(), training.name(),
                 training.size());
    }
    // Reading the scans is most of a codebook's training on real data; the lines say it is
    // alive (a descriptor may read fewer than all of them).
    Progress reading("training " + instance.id + ", scans read", training.size(), show_progress);
    scans.report_to(&reading, fmt::format("training {}: all {} scans read, now learning from them",
                                          instance.id, training.size()));
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<Descriptor> descriptor = instance.create_fresh();
    scans.take_loaded_count();
    LearningProgress learning(instance.id, show_progress);
    const ScopedTrainingProgress learning_lines(
        [&learning](std::string_view stage, std::size_t total) { learning.step(stage, total); });
    try {
      descriptor->train(scans);
      scans.report_to(nullptr);
    } catch (const std::exception& error) {
      scans.report_to(nullptr);
      throw std::runtime_error(fmt::format("training descriptor {} on {} failed: {}", instance.id,
                                           training.name(), error.what()));
    }
    if (!descriptor->is_trained()) {
      throw std::logic_error(
          fmt::format("descriptor {} is still untrained after train()", instance.id));
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t loaded = scans.take_loaded_count();
    reading.finish(fmt::format("trained {} in {:.1f} s ({} of {} scans read)", instance.id, seconds,
                               loaded, training.size()));
    std::string codebook_hash;
    if (const LearntCodebook* codebook = learnt_codebook_of(*descriptor)) {
      codebook_hash = codebook->codebook_sha256();
    }
    DescriptorInstance trained_instance = instance;
    trained_instance.descriptor = std::move(descriptor);
    trained.instances.push_back(std::move(trained_instance));
    trained.training.push_back(TrainingRecord{training.name(), training.size(), loaded, seconds,
                                              false, std::move(codebook_hash)});
  }
  return trained;
}

}  // namespace radarpr
