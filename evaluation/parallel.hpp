#pragma once

#include <cstddef>
#include <functional>

namespace radarpr {

// Runs body(i) for every i in [0, count) on `threads` threads (0 = one per core), handing out
// indices in order. The first exception thrown by any body stops the remaining work and is
// rethrown here. Results must be written by index, so the outcome does not depend on scheduling.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

int resolve_thread_count(int requested);

}  // namespace radarpr
