#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "evaluation/protocol.hpp"
#include "evaluation/retrieval/query_result.hpp"

namespace radarpr {

struct ConfusionCounts {
  std::size_t tp = 0;
  std::size_t fp = 0;
  std::size_t fn = 0;
  std::size_t tn = 0;
};

// One threshold of the sweep. A ratio whose denominator is zero is left empty (undefined).
struct CurvePoint {
  double threshold = 0.0;
  ConfusionCounts counts;
  std::optional<double> precision;  // TP/(TP+FP)
  std::optional<double> recall;     // TP/(TP+FN), also the ROC's TPR
  std::optional<double> f1;         // 2PR/(P+R); 0 when P+R == 0; empty when P or R is
  std::optional<double> fpr;        // FP/(FP+TN)
};

// Scalar metrics (protocols.md, "Metrics"); empty = undefined for this input (for example
// recall-based metrics of a sequence with no revisit), never a made-up 0.
struct Metrics {
  std::size_t queries = 0;   // evaluated queries (non-empty eligible database)
  std::size_t revisits = 0;  // of which revisits
  std::size_t correct_top1 = 0;
  std::optional<double> roc_auc;  // the protocol's variant (RocAucVariant)
  std::optional<double> f1_max;
  std::optional<double> f1_max_threshold;
  std::optional<double> pr_auc;             // trapezoid over the swept (recall, precision) points
  std::optional<double> average_precision;  // sum of (R_i - R_{i-1}) * P_i, R_0 = 0
  std::optional<double> pr_auc_mulran;      // trapezoid, first precision forced to 1 (MulRan)
  // VPR-Bench's (scikit-learn's precision_recall_curve then auc): the trapezoid over the swept
  // (recall, precision) points with (0, 1) put first.
  std::optional<double> pr_auc_vpr_bench;
  std::optional<double> recall_at_1;
  std::map<int, std::optional<double>> recall_at_k;  // denominator: revisit queries
  // The same hits over every evaluated query (Open-RadVLAD's code divides by all queries).
  std::map<int, std::optional<double>> recall_at_k_all_queries;
  // The same hits over the queries with a positive in the database they are searched against
  // (OpenPlaceRecognition's denominator). radarpr searches a query against exactly the frames it
  // may match, so these are the revisit queries and the values equal recall_at_k; they are
  // reported under their own name so that every evaluator's denominator is named.
  std::map<int, std::optional<double>> recall_at_k_with_positive;
  std::optional<double> recall_at_1_all_queries;
  std::optional<double> recall_at_1_with_positive;
  std::optional<double> recall_at_100_precision;
  std::optional<double> extended_precision;  // empty when no threshold has a non-zero recall
  // VPR-Bench's: (precision at the first threshold that accepts a query, whatever its recall,
  // + recall at 100% precision) / 2; empty when no threshold accepts a query.
  std::optional<double> extended_precision_vpr_bench;
};

// Recall@K under `denominator` (K = 1 included whether or not the protocol lists it).
std::optional<double> recall_at(const Metrics& metrics, int k, RecallDenominator denominator);

// Whether `threshold` accepts `distance` under `comparison`.
bool accepts(double distance, double threshold, ThresholdComparison comparison);

// Accepted = distance <= threshold (or < with ThresholdComparison::strict).
ConfusionCounts count_labels(const std::vector<QueryResult>& results, double threshold,
                             LabelRule rule,
                             ThresholdComparison comparison = ThresholdComparison::inclusive);
// Ascending thresholds of the sweep; empty when there are no results (and, for referee_grid,
// when no distance is above 0). `multi_session` matters to referee_grid only.
std::vector<double> sweep_thresholds(const std::vector<QueryResult>& results, ThresholdSweep sweep,
                                     bool multi_session = false);
std::vector<CurvePoint> compute_curve(
    const std::vector<QueryResult>& results, const std::vector<double>& thresholds, LabelRule rule,
    ThresholdComparison comparison = ThresholdComparison::inclusive);
// The ReFeree code's ROC AUC: at every threshold, every accepted result becomes one sample
// (label: wrong, score: its distance), and the samples of all thresholds are pooled into one ROC
// AUC with ties counted half (scikit-learn's roc_auc_score with the wrong pairs as the positive
// class). A result accepted at n thresholds counts n times. Undefined when the pool lacks a wrong
// or a right pair.
std::optional<double> roc_auc_pooled_pairs(const std::vector<QueryResult>& results,
                                           const std::vector<double>& thresholds,
                                           ThresholdComparison comparison);
// VPR-Bench's ROC AUC: scikit-learn's roc_auc_score over the results, one sample each (label:
// right; score: minus the distance), ties counted half. Undefined without a right and a wrong one.
std::optional<double> roc_auc_query_ranks(const std::vector<QueryResult>& results);
// `roc_auc` selects what Metrics::roc_auc is; pooled_pairs uses `comparison` to know which
// results each threshold of the curve accepted.
Metrics compute_metrics(const std::vector<QueryResult>& results,
                        const std::vector<CurvePoint>& curve, const std::vector<int>& recall_at_k,
                        RocAucVariant roc_auc = RocAucVariant::trapezoid,
                        ThresholdComparison comparison = ThresholdComparison::inclusive);

}  // namespace radarpr
