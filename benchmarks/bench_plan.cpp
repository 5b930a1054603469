#include "benchmarks/bench_plan.hpp"

#include <stdexcept>
#include <utility>

namespace radarpr::bench {

BenchPlan::BenchPlan(const std::string& filter, RunLength length) : length_(length) {
  if (filter.empty()) return;
  try {
    filter_.emplace(filter, std::regex::ECMAScript);
  } catch (const std::regex_error& error) {
    throw std::invalid_argument("benchmark filter '" + filter +
                                "' is not a valid regular expression: " + error.what());
  }
}

bool BenchPlan::wanted(const std::string& name) const {
  return !filter_ || std::regex_search(name, *filter_);
}

void BenchPlan::add(BenchCase bench, std::function<void(benchmark::State&)> body, bool wall_clock,
                    bool cheap, int repetitions_override) {
  if (!wanted(bench.name)) return;
  auto* registered = benchmark::RegisterBenchmark(bench.name.c_str(), std::move(body));
  registered->Unit(benchmark::kMillisecond);
  if (length_.min_seconds > 0.0) registered->MinTime(length_.min_seconds);
  const int repetitions = repetitions_override > 0 ? repetitions_override
                          : cheap                  ? length_.cheap_repetitions
                                                   : length_.repetitions;
  if (repetitions > 0) registered->Repetitions(repetitions);
  if (wall_clock) registered->UseRealTime();
  cases_.push_back(std::move(bench));
}

void BenchPlan::skip(const std::string& name, std::string reason) {
  if (wanted(name)) skipped_.push_back({name, std::move(reason)});
}

}  // namespace radarpr::bench
