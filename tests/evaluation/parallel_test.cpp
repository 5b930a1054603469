#include "evaluation/parallel.hpp"

#include <sched.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
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

// Restores an environment variable on destruction.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value != nullptr) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// The default follows the affinity mask (what taskset, cpusets and cluster schedulers set), not
// the machine's core count: a thread allowed one processor sees one.
TEST(ThreadCount, FollowsTheAffinityMask) {
  const ScopedEnvironment no_slurm("SLURM_CPUS_PER_TASK", nullptr);
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof(all), &all), 0);
  EXPECT_EQ(available_processor_count(), CPU_COUNT(&all));
  int seen = 0;
  std::thread([&] {
    cpu_set_t one;
    CPU_ZERO(&one);
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
      if (CPU_ISSET(cpu, &all)) {
        CPU_SET(cpu, &one);
        break;
      }
    }
    if (sched_setaffinity(0, sizeof(one), &one) == 0) seen = available_processor_count();
  }).join();
  EXPECT_EQ(seen, 1);
}

TEST(ThreadCount, SlurmCpusPerTaskCapsIt) {
  const int processors = [] {
    const ScopedEnvironment no_slurm("SLURM_CPUS_PER_TASK", nullptr);
    return available_processor_count();
  }();
  {
    const ScopedEnvironment slurm("SLURM_CPUS_PER_TASK", "1");
    EXPECT_EQ(available_processor_count(), 1);
  }
  {
    const ScopedEnvironment slurm("SLURM_CPUS_PER_TASK", "100000");  // larger: the mask rules
    EXPECT_EQ(available_processor_count(), processors);
  }
  for (const char* nonsense : {"", "0", "-2", "2x", "abc"}) {
    const ScopedEnvironment slurm("SLURM_CPUS_PER_TASK", nonsense);
    EXPECT_EQ(available_processor_count(), processors) << "'" << nonsense << "'";
  }
}

// --threads sets the default every parallel_for(..., 0, ...) uses; 0 goes back to the processors.
TEST(ThreadCount, TheDefaultCanBeSetForTheProcess) {
  const ScopedEnvironment no_slurm("SLURM_CPUS_PER_TASK", nullptr);
  set_default_thread_count(3);
  EXPECT_EQ(default_thread_count(), 3);
  EXPECT_EQ(resolve_thread_count(0), 3);
  EXPECT_EQ(resolve_thread_count(5), 5);
  auto workers = [] {
    std::mutex mutex;
    std::set<std::thread::id> seen;
    parallel_for(300, 0, [&](std::size_t) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      std::lock_guard lock(mutex);
      seen.insert(std::this_thread::get_id());
    });
    return seen;
  };
  EXPECT_EQ(workers().size(), 3u);  // 60 ms of work: every thread gets some
  set_default_thread_count(1);
  EXPECT_EQ(workers(), std::set<std::thread::id>{std::this_thread::get_id()});
  set_default_thread_count(0);
  EXPECT_EQ(default_thread_count(), available_processor_count());
}

}  // namespace
}  // namespace radarpr
