#pragma once

#include <string>

#include "evaluation/experiment_runner.hpp"

namespace radarpr {

// "0.912", or "n/a" for an undefined metric.
std::string format_metric(const std::optional<double>& value);
// The Markdown table of one dataset's descriptors, and under it why a Recall@K is n/a where a
// key-then-rerank descriptor hands over fewer candidates than K: the console output of
// `radarpr run` and the body of summary.md.
std::string summary_table(const DatasetRun& dataset, const Protocol& protocol);
// "single session (50 most recent frames excluded)" or "multi session".
std::string describe_session(const DatasetRun& dataset, const Protocol& protocol);

}  // namespace radarpr
