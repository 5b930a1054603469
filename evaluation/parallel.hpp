#pragma once

#include <cstddef>
#include <functional>

namespace radarpr {

// The most threads a command line or config may ask for.
inline constexpr int kMaxThreads = 1024;

// Runs body(i) for every i in [0, count) on `threads` threads (0 = default_thread_count()),
// handing out indices in order. An exception stops handing out indices; the one thrown for the
// smallest index is rethrown here. That is the smallest failing index of all, whatever the
// scheduling: every smaller index was handed out earlier and runs to its end. Results must be
// written by index, so the outcome, errors included, does not depend on the thread count.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

// `requested` when > 0, else default_thread_count().
int resolve_thread_count(int requested);

// The threads parallel work uses when it is given 0: what set_default_thread_count set (the
// command line's --threads), else available_processor_count().
int default_thread_count();
// 0 goes back to available_processor_count(). Process-wide, like the command line it serves.
void set_default_thread_count(int threads);

// The processors this process may run on: its CPU affinity mask, which honours taskset, cgroup
// cpusets and a cluster scheduler's binding (unlike the machine's core count), capped by
// $SLURM_CPUS_PER_TASK when that is a smaller positive number (a Slurm job step that does not
// bind). At least 1.
int available_processor_count();

}  // namespace radarpr
