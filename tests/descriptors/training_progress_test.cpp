// A descriptor's learning reports its steps to the sink the trainer installed on its thread: a
// codebook's k-means says each seeding step and each Lloyd iteration, so `radarpr run` can show
// progress during minutes of k-means on real data.
#include "descriptors/training_progress.hpp"

#include <map>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "descriptors/open_radvlad/kmeans.hpp"

namespace radarpr {
namespace {

struct Recorded {
  std::vector<std::string> stages;                                   // in order, once per change
  std::map<std::string, std::pair<std::size_t, std::size_t>> steps;  // stage -> (count, total)
};

TrainingStepSink recorder(Recorded& recorded) {
  return [&recorded](std::string_view stage, std::size_t total) {
    const std::string name(stage);
    if (recorded.stages.empty() || recorded.stages.back() != name) recorded.stages.push_back(name);
    auto& [count, seen_total] = recorded.steps[name];
    ++count;
    seen_total = total;
  };
}

TEST(TrainingProgress, StepsReachTheSinkOfTheCallingThreadOnly) {
  report_training_step("nobody listens", 3);  // no sink installed: nothing happens
  Recorded outer, inner, other_thread;
  {
    const ScopedTrainingProgress scope(recorder(outer));
    report_training_step("a", 2);
    {
      const ScopedTrainingProgress nested(recorder(inner));
      report_training_step("b", 5);
    }
    report_training_step("a", 2);  // the outer sink again once the nested one is gone
    std::thread([&] { report_training_step("elsewhere", 1); }).join();
  }
  report_training_step("after", 1);
  EXPECT_EQ(outer.stages, (std::vector<std::string>{"a"}));
  EXPECT_EQ(outer.steps["a"], (std::pair<std::size_t, std::size_t>{2, 2}));
  EXPECT_EQ(inner.stages, (std::vector<std::string>{"b"}));
  EXPECT_TRUE(other_thread.stages.empty());
}

TEST(TrainingProgress, KMeansReportsEverySeedingStepAndIteration) {
  cv::Mat rows(400, 6, CV_32FC1);
  cv::RNG random(7);
  random.fill(rows, cv::RNG::UNIFORM, 0.0, 1.0);
  Recorded recorded;
  KMeansResult result;
  {
    const ScopedTrainingProgress scope(recorder(recorded));
    result = kmeans(
        rows, {.clusters = 8, .seed = 3, .max_iterations = 30, .seeding = KMeansSeeding::greedy});
  }
  ASSERT_EQ(recorded.stages.size(), 2u);
  EXPECT_EQ(recorded.stages[0], "k-means++ seeding, centres after the first");
  EXPECT_EQ(recorded.steps[recorded.stages[0]], (std::pair<std::size_t, std::size_t>{7, 7}));
  EXPECT_EQ(recorded.stages[1], "k-means iterations (at most 30)");
  EXPECT_EQ(recorded.steps[recorded.stages[1]].first, static_cast<std::size_t>(result.iterations));
  EXPECT_EQ(recorded.steps[recorded.stages[1]].second, 30u);
}

}  // namespace
}  // namespace radarpr
