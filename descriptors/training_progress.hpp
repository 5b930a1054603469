#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace radarpr {

// How far a descriptor's learning has got, for whoever trains it: a trainable descriptor calls
// report_training_step once per step of a long computation (a k-means iteration), the caller
// (radarpr run) turns the steps into progress lines. Steps go to the sink installed on the
// calling thread by ScopedTrainingProgress; without one, reporting costs a thread-local read.
//
// `stage` names the kind of step and stays the same across one computation; `total` is how many
// such steps there are at most (an iterative method may stop sooner).
using TrainingStepSink = std::function<void(std::string_view stage, std::size_t total)>;

void report_training_step(std::string_view stage, std::size_t total);

// Installs `sink` for the calling thread while alive, restoring the previous one after.
class ScopedTrainingProgress {
 public:
  explicit ScopedTrainingProgress(TrainingStepSink sink);
  ~ScopedTrainingProgress();
  ScopedTrainingProgress(const ScopedTrainingProgress&) = delete;
  ScopedTrainingProgress& operator=(const ScopedTrainingProgress&) = delete;

 private:
  TrainingStepSink sink_;
  const TrainingStepSink* previous_;
};

}  // namespace radarpr
