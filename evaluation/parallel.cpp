#include "evaluation/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string_view>
#include <thread>
#include <vector>

#ifdef __linux__
#include <sched.h>
#endif

namespace radarpr {
namespace {

std::atomic<int> default_threads{0};  // 0: available_processor_count()

// The processors the affinity mask allows; the machine's count where there is no mask to read.
int affinity_processor_count() {
#ifdef __linux__
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return CPU_COUNT(&set);
#endif
  return static_cast<int>(std::thread::hardware_concurrency());
}

// $SLURM_CPUS_PER_TASK when it is a positive whole number.
int slurm_cpus_per_task() {
  const char* text = std::getenv("SLURM_CPUS_PER_TASK");
  if (text == nullptr) return 0;
  const std::string_view view(text);
  int value = 0;
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  return error == std::errc() && end == view.data() + view.size() && value > 0 ? value : 0;
}

}  // namespace

int available_processor_count() {
  int count = std::max(1, affinity_processor_count());
  if (const int slurm = slurm_cpus_per_task(); slurm > 0) count = std::min(count, slurm);
  return count;
}

int default_thread_count() {
  const int set = default_threads.load();
  return set > 0 ? set : available_processor_count();
}

void set_default_thread_count(int threads) {
  default_threads = std::max(0, threads);
}

int resolve_thread_count(int requested) {
  return requested > 0 ? requested : default_thread_count();
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body) {
  const auto workers =
      std::min<std::size_t>(static_cast<std::size_t>(resolve_thread_count(threads)), count);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::size_t first_error_index = count;
  std::mutex error_mutex;
  auto work = [&] {
    while (!failed.load()) {
      const std::size_t i = next.fetch_add(1);
      if (i >= count) return;
      try {
        body(i);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (i < first_error_index) {
          first_error_index = i;
          first_error = std::current_exception();
        }
        failed = true;
      }
    }
  };
  if (workers <= 1) {
    work();
  } else {
    std::vector<std::jthread> pool;
    for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(work);
  }
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace radarpr
