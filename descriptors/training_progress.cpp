#include "descriptors/training_progress.hpp"

#include <utility>

namespace radarpr {
namespace {

thread_local const TrainingStepSink* current_sink = nullptr;

}  // namespace

void report_training_step(std::string_view stage, std::size_t total) {
  if (current_sink != nullptr && *current_sink) (*current_sink)(stage, total);
}

ScopedTrainingProgress::ScopedTrainingProgress(TrainingStepSink sink)
    : sink_(std::move(sink)), previous_(current_sink) {
  current_sink = &sink_;
}

ScopedTrainingProgress::~ScopedTrainingProgress() {
  current_sink = previous_;
}

}  // namespace radarpr
