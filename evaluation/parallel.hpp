#pragma once

#include <cstddef>
#include <functional>

namespace radarpr {

// Runs body(i) for every i in [0, count) on `threads` threads (0 = one per core), handing out
// indices in order. An exception stops handing out indices; the one thrown for the smallest
// index is rethrown here. That is the smallest failing index of all, whatever the scheduling:
// every smaller index was handed out earlier and runs to its end. Results must be written by
// index, so the outcome, errors included, does not depend on the thread count.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

int resolve_thread_count(int requested);

}  // namespace radarpr
