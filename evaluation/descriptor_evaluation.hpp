#pragma once

#include <cstddef>
#include <functional>
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
  // How many nearest frames each query's ranking covers: QueryResult::first_correct_rank is 0
  // for a query whose first correct frame lies beyond them. A key-then-rerank descriptor ranks
  // only its candidates.
  std::size_t ranked_frames = 0;
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
// Single session when `database` is null (query values searched against their own past). Each
// query's nearest frames are ranked to the protocol's largest Recall@K, or to `rank_depth` when
// that is larger (the report's Recall@N curve).
DescriptorEvaluation evaluate_descriptor(const Descriptor& descriptor,
                                         const std::vector<DescriptorValue>& query_values,
                                         const std::vector<ScanRecord>& query_records,
                                         const std::vector<DescriptorValue>* database_values,
                                         const std::vector<ScanRecord>* database_records,
                                         const Protocol& protocol, std::size_t rank_depth = 0);

// evaluate_descriptor for a single session of an exhaustive_l2 descriptor whose values are read
// in place (a memory-mapped cache entry, L2Rows): the search streams them a block at a time; the
// result equals evaluate_descriptor's on the same values.
DescriptorEvaluation evaluate_single_session_rows(const Descriptor& descriptor,
                                                  const L2Rows& values,
                                                  const std::vector<ScanRecord>& records,
                                                  const Protocol& protocol,
                                                  std::size_t rank_depth = 0);

// Values handed over a block at a time (a memory-mapped cache entry): `count` values; read(begin,
// end, values) puts values [begin, end) into `values` (whose memory it may reuse), called with at
// most `block` values at a time.
struct ValueBlocks {
  std::size_t count = 0;
  std::size_t block = 1;
  std::function<void(std::size_t begin, std::size_t end, std::vector<DescriptorValue>& values)>
      read;
};

// evaluate_descriptor for two sessions whose values are read a block at a time, so that it holds
// one block of queries and one block of the database, never both sessions: each query block is
// searched against each database block, and a query's k nearest are the k nearest of the blocks'
// (every retrieval method finds the exact k nearest of what it is given, ties to the smaller
// index, but key_then_rerank, whose database is therefore read as one block). The result equals
// evaluate_descriptor's on the whole values.
DescriptorEvaluation evaluate_descriptor_in_blocks(const Descriptor& descriptor,
                                                   const ValueBlocks& query_values,
                                                   const std::vector<ScanRecord>& query_records,
                                                   const ValueBlocks& database_values,
                                                   const std::vector<ScanRecord>& database_records,
                                                   const Protocol& protocol,
                                                   std::size_t rank_depth = 0);

std::string_view to_string(GraphLabel label);

}  // namespace radarpr
