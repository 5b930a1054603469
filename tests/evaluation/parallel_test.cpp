#include "evaluation/parallel.hpp"

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

TEST(ParallelFor, VisitsEveryIndexOnce) {
  std::vector<std::atomic<int>> visits(1000);
  parallel_for(visits.size(), 2, [&](std::size_t i) { ++visits[i]; });
  for (const auto& count : visits) EXPECT_EQ(count.load(), 1);
}

// Errors must not depend on scheduling: with every index failing, or two failing, the error of
// the smallest failing index is the one reported, run after run (a race shows within a few runs).
TEST(ParallelFor, RethrowsTheSmallestFailingIndex) {
  auto reported = [](const std::function<bool(std::size_t)>& fails) {
    try {
      parallel_for(64, 4, [&](std::size_t i) {
        if (fails(i)) throw std::runtime_error(std::to_string(i));
      });
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("none");
  };
  for (int run = 0; run < 200; ++run) {
    ASSERT_EQ(reported([](std::size_t) { return true; }), "0") << "run " << run;
    ASSERT_EQ(reported([](std::size_t i) { return i == 9 || i == 3; }), "3") << "run " << run;
  }
  EXPECT_EQ(reported([](std::size_t) { return false; }), "none");
}

TEST(ParallelFor, NothingToDoIsFine) {
  parallel_for(0, 2, [](std::size_t) { FAIL() << "no index to visit"; });
}

}  // namespace
}  // namespace radarpr
