#include "evaluation/descriptor_evaluation.hpp"

#include <algorithm>
#include <stdexcept>

namespace radarpr {

std::string_view to_string(GraphLabel label) {
  switch (label) {
    case GraphLabel::tp:
      return "TP";
    case GraphLabel::fp:
      return "FP";
    case GraphLabel::fn:
      return "FN";
  }
  return "?";
}

std::vector<QueryResult> build_query_results(const std::vector<std::vector<Neighbour>>& neighbours,
                                             const std::vector<Position2D>& query_positions,
                                             const RevisitGroundTruth& ground_truth,
                                             const std::vector<std::size_t>& eligible_ends) {
  std::vector<QueryResult> results;
  for (std::size_t q = 0; q < neighbours.size(); ++q) {
    if (neighbours[q].empty()) continue;
    const Position2D& position = query_positions[q];
    QueryResult result;
    result.query = q;
    result.match = neighbours[q].front().index;
    result.distance = neighbours[q].front().distance;
    result.correct = ground_truth.is_positive(position, result.match);
    result.revisit = ground_truth.has_revisit(position, eligible_ends[q]);
    for (std::size_t rank = 0; rank < neighbours[q].size(); ++rank) {
      if (ground_truth.is_positive(position, neighbours[q][rank].index)) {
        result.first_correct_rank = rank + 1;
        break;
      }
    }
    results.push_back(result);
  }
  return results;
}

std::vector<MatchingGraphEdge> build_matching_graph(const std::vector<QueryResult>& results,
                                                    double threshold, LabelRule rule,
                                                    ThresholdComparison comparison) {
  std::vector<MatchingGraphEdge> edges;
  for (const auto& result : results) {
    const bool accepted = accepts(result.distance, threshold, comparison);
    const bool missed = rule == LabelRule::standard ? result.revisit : result.correct;
    if (!accepted && !missed) continue;  // a true negative is not drawn
    const GraphLabel label =
        accepted ? (result.correct ? GraphLabel::tp : GraphLabel::fp) : GraphLabel::fn;
    edges.push_back({result.query, result.match, result.distance, label});
  }
  return edges;
}

namespace {

std::size_t largest_k(const Protocol& protocol, std::size_t rank_depth) {
  const std::size_t k =
      protocol.recall_at_k.empty()
          ? 1
          : static_cast<std::size_t>(std::max(
                1, *std::max_element(protocol.recall_at_k.begin(), protocol.recall_at_k.end())));
  return std::max(k, rank_depth);
}

// Everything after retrieval: ground truth, sweep, curve, metrics, graph.
DescriptorEvaluation evaluate_neighbours(const Descriptor& descriptor,
                                         const std::vector<std::vector<Neighbour>>& neighbours,
                                         const std::vector<ScanRecord>& query_records,
                                         const std::vector<ScanRecord>& db_records,
                                         const std::vector<std::size_t>& eligible_ends,
                                         bool single_session, const Protocol& protocol,
                                         std::size_t depth) {
  const RevisitGroundTruth ground_truth(positions_of(db_records), protocol.revisit_radius_m,
                                        protocol.radius_comparison, protocol.revisit_max_yaw_deg);

  DescriptorEvaluation evaluation;
  evaluation.results =
      build_query_results(neighbours, positions_of(query_records), ground_truth, eligible_ends);
  evaluation.curve = compute_curve(
      evaluation.results, sweep_thresholds(evaluation.results, protocol.sweep, !single_session),
      protocol.labels, protocol.threshold_comparison);
  evaluation.metrics = compute_metrics(evaluation.results, evaluation.curve, protocol.recall_at_k,
                                       protocol.roc_auc, protocol.threshold_comparison);
  evaluation.ranked_frames = depth;
  // A key pre-search hands over only its re-ranked candidates: a K beyond them cannot be judged.
  if (descriptor.retrieval_method() == RetrievalMethod::key_then_rerank) {
    evaluation.ranked_frames = std::min(depth, descriptor.rerank_candidates());
    for (auto* recalls :
         {&evaluation.metrics.recall_at_k, &evaluation.metrics.recall_at_k_all_queries,
          &evaluation.metrics.recall_at_k_with_positive}) {
      for (auto& [k_value, recall] : *recalls) {
        if (static_cast<std::size_t>(k_value) > descriptor.rerank_candidates()) recall.reset();
      }
    }
  }
  if (evaluation.metrics.f1_max_threshold) {
    evaluation.matching_graph =
        build_matching_graph(evaluation.results, *evaluation.metrics.f1_max_threshold,
                             protocol.labels, protocol.threshold_comparison);
  }
  return evaluation;
}

// Nearest first, ties: the smaller database index (retrieve_nearest's order).
bool nearer_neighbour(const Neighbour& a, const Neighbour& b) {
  return a.distance < b.distance || (a.distance == b.distance && a.index < b.index);
}

}  // namespace

DescriptorEvaluation evaluate_descriptor(const Descriptor& descriptor,
                                         const std::vector<DescriptorValue>& query_values,
                                         const std::vector<ScanRecord>& query_records,
                                         const std::vector<DescriptorValue>* database_values,
                                         const std::vector<ScanRecord>* database_records,
                                         const Protocol& protocol, std::size_t rank_depth) {
  const bool single_session = database_values == nullptr;
  const auto& db_values = single_session ? query_values : *database_values;
  const auto& db_records = single_session ? query_records : *database_records;
  if (query_values.size() != query_records.size() || db_values.size() != db_records.size()) {
    throw std::logic_error("evaluate_descriptor: values and records differ in length");
  }
  const std::vector<std::size_t> eligible_ends =
      single_session ? single_session_eligible_ends(query_records, protocol)
                     : std::vector<std::size_t>(query_records.size(), db_records.size());
  const std::size_t depth = largest_k(protocol, rank_depth);
  const auto neighbours =
      retrieve_nearest(descriptor, db_values, query_values, eligible_ends, depth);
  return evaluate_neighbours(descriptor, neighbours, query_records, db_records, eligible_ends,
                             single_session, protocol, depth);
}

DescriptorEvaluation evaluate_single_session_rows(const Descriptor& descriptor,
                                                  const L2Rows& values,
                                                  const std::vector<ScanRecord>& records,
                                                  const Protocol& protocol,
                                                  std::size_t rank_depth) {
  if (values.size() != records.size()) {
    throw std::logic_error("evaluate_single_session_rows: values and records differ in length");
  }
  const std::vector<std::size_t> eligible_ends = single_session_eligible_ends(records, protocol);
  const std::size_t depth = largest_k(protocol, rank_depth);
  const auto neighbours = retrieve_nearest_l2(descriptor, values, values, eligible_ends, depth);
  return evaluate_neighbours(descriptor, neighbours, records, records, eligible_ends,
                             /*single_session=*/true, protocol, depth);
}

DescriptorEvaluation evaluate_descriptor_in_blocks(const Descriptor& descriptor,
                                                   const ValueBlocks& query_values,
                                                   const std::vector<ScanRecord>& query_records,
                                                   const ValueBlocks& database_values,
                                                   const std::vector<ScanRecord>& database_records,
                                                   const Protocol& protocol,
                                                   std::size_t rank_depth) {
  if (query_values.count != query_records.size() ||
      database_values.count != database_records.size()) {
    throw std::logic_error("evaluate_descriptor_in_blocks: values and records differ in length");
  }
  if (query_values.block == 0 || database_values.block == 0) {
    throw std::logic_error("evaluate_descriptor_in_blocks: a block holds at least one value");
  }
  const std::size_t k = largest_k(protocol, rank_depth);
  // A key pre-search is no exact k-nearest search: over database blocks it would re-rank other
  // candidates than over the whole database, so its database is one block.
  const std::size_t database_block =
      descriptor.retrieval_method() == RetrievalMethod::key_then_rerank
          ? std::max<std::size_t>(1, database_values.count)
          : database_values.block;
  const std::size_t database_blocks = (database_values.count + database_block - 1) / database_block;
  // One database block is read once; several are read again for every query block, into the
  // same memory.
  std::vector<DescriptorValue> database;
  if (database_blocks == 1) database_values.read(0, database_values.count, database);

  std::vector<std::vector<Neighbour>> neighbours(query_values.count);
  std::vector<DescriptorValue> queries;
  for (std::size_t query_begin = 0; query_begin < query_values.count;
       query_begin += query_values.block) {
    const std::size_t query_end = std::min(query_values.count, query_begin + query_values.block);
    query_values.read(query_begin, query_end, queries);
    for (std::size_t begin = 0; begin < database_values.count; begin += database_block) {
      const std::size_t end = std::min(database_values.count, begin + database_block);
      if (database_blocks > 1) database_values.read(begin, end, database);
      const auto found = retrieve_nearest(descriptor, database, queries,
                                          std::vector<std::size_t>(queries.size(), end - begin), k);
      // Each block's k nearest, exact, hold the k nearest of all: merged, the k first remain.
      for (std::size_t q = 0; q < queries.size(); ++q) {
        std::vector<Neighbour>& merged = neighbours[query_begin + q];
        for (Neighbour neighbour : found[q]) {
          neighbour.index += begin;
          merged.push_back(neighbour);
        }
        std::sort(merged.begin(), merged.end(), nearer_neighbour);
        if (merged.size() > k) merged.resize(k);
      }
    }
  }
  const std::vector<std::size_t> eligible_ends(query_records.size(), database_records.size());
  return evaluate_neighbours(descriptor, neighbours, query_records, database_records, eligible_ends,
                             /*single_session=*/false, protocol, k);
}

}  // namespace radarpr
