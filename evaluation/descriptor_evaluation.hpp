#pragma once

#include <optional>
#include <string>
#include <vector>

#include "datasets/scan_sequence.hpp"
#include "descriptors/descriptor.hpp"
#include "evaluation/ground_truth.hpp"
#include "evaluation/metrics.hpp"
#include "evaluation/protocol.hpp"
#include "evaluation/retrieval/query_result.hpp"
#include "evaluation/retrieval/retrieval.hpp"

namespace radarpr {

// Where a query stands in the matching graph at the F1-max threshold (protocols.md).
enum class GraphLabel { tp, fp, fn };

struct MatchingGraphEdge {
  std::size_t query = 0;
  std::size_t match = 0;
  double distance = 0.0;
  GraphLabel label = GraphLabel::tp;
};

// Everything one descriptor yields on one dataset.
struct DescriptorEvaluation {
  std::vector<QueryResult> results;  // one per query with a non-empty eligible database
  std::vector<CurvePoint> curve;
  Metrics metrics;
  // Accepted queries (tp, fp) and missed revisits (fn) at the F1-max threshold; empty when
  // F1-max is undefined.
  std::vector<MatchingGraphEdge> matching_graph;
};

// Ties retrieval results to the ground truth: the top-1 match, whether it is correct, whether
// the query is a revisit and the rank of the first correct frame. Queries without neighbours
// (empty eligible database) are skipped.
std::vector<QueryResult> build_query_results(const std::vector<std::vector<Neighbour>>& neighbours,
                                             const std::vector<Position2D>& query_positions,
                                             const RevisitGroundTruth& ground_truth,
                                             const std::vector<std::size_t>& eligible_ends);

std::vector<MatchingGraphEdge> build_matching_graph(
    const std::vector<QueryResult>& results, double threshold, LabelRule rule,
    ThresholdComparison comparison = ThresholdComparison::inclusive);

// The whole pipeline for one descriptor: retrieval, ground truth, sweep, curve, metrics, graph.
// Single session when `database` is null (query values searched against their own past).
DescriptorEvaluation evaluate_descriptor(const Descriptor& descriptor,
                                         const std::vector<DescriptorValue>& query_values,
                                         const std::vector<ScanRecord>& query_records,
                                         const std::vector<DescriptorValue>* database_values,
                                         const std::vector<ScanRecord>* database_records,
                                         const Protocol& protocol);

std::string_view to_string(GraphLabel label);

}  // namespace radarpr
