#include "evaluation/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

namespace radarpr {
namespace {

std::optional<double> ratio(std::size_t numerator, std::size_t denominator) {
  if (denominator == 0) return std::nullopt;
  return static_cast<double>(numerator) / static_cast<double>(denominator);
}

// Every function here counts on finite distances and on "correct" implying "revisit" (a correct
// top-1 is itself an eligible frame within the radius); anything else is a caller's bug.
void require_valid(const std::vector<QueryResult>& results, const char* caller) {
  for (std::size_t i = 0; i < results.size(); ++i) {
    const QueryResult& r = results[i];
    if (!std::isfinite(r.distance)) {
      throw std::invalid_argument(std::string(caller) + ": result " + std::to_string(i) +
                                  " (query " + std::to_string(r.query) +
                                  ") has a non-finite distance " + std::to_string(r.distance));
    }
    if (r.correct && !r.revisit) {
      throw std::invalid_argument(std::string(caller) + ": result " + std::to_string(i) +
                                  " (query " + std::to_string(r.query) +
                                  ") is marked correct but not a revisit");
    }
  }
}

void require_ascending(const std::vector<double>& thresholds, const char* caller) {
  for (std::size_t i = 0; i < thresholds.size(); ++i) {
    if (std::isnan(thresholds[i]) || (i > 0 && thresholds[i] < thresholds[i - 1])) {
      throw std::invalid_argument(std::string(caller) +
                                  ": thresholds must be ascending numbers; threshold " +
                                  std::to_string(i) + " is " + std::to_string(thresholds[i]));
    }
  }
}

// The counter a result falls into (protocols.md, "Labels per threshold").
std::size_t& label_of(ConfusionCounts& counts, const QueryResult& r, bool accepted,
                      LabelRule rule) {
  if (accepted) return r.correct ? counts.tp : counts.fp;
  // standard: a rejected revisit is a missed loop; retrieved_pair: only the retrieved pair counts.
  const bool positive = rule == LabelRule::standard ? r.revisit : r.correct;
  return positive ? counts.fn : counts.tn;
}

CurvePoint make_point(double threshold, const ConfusionCounts& c) {
  CurvePoint point;
  point.threshold = threshold;
  point.counts = c;
  point.precision = ratio(c.tp, c.tp + c.fp);
  point.recall = ratio(c.tp, c.tp + c.fn);
  point.fpr = ratio(c.fp, c.fp + c.tn);
  // 2PR/(P+R) written with counts, 2TP/(2TP+FP+FN), so equal F1s compare equal; 0 when TP = 0.
  if (point.precision && point.recall) {
    point.f1 = c.tp == 0 ? 0.0 : ratio(2 * c.tp, 2 * c.tp + c.fp + c.fn);
  }
  return point;
}

// Trapezoid rule over the points in the given order.
double trapezoid(const std::vector<std::pair<double, double>>& points) {
  double area = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    area += (points[i].first - points[i - 1].first) * (points[i].second + points[i - 1].second) / 2;
  }
  return area;
}

void append_linspace(double low, double high, int count, bool include_low,
                     std::vector<double>& out) {
  for (int i = include_low ? 0 : 1; i < count; ++i) {
    // The ends are assigned exactly so that 0.01 and 1 are not off by a rounding.
    const double value = i == 0           ? low
                         : i == count - 1 ? high
                                          : low + (high - low) * i / (count - 1);
    out.push_back(value);
  }
}

}  // namespace

bool accepts(double distance, double threshold, ThresholdComparison comparison) {
  return comparison == ThresholdComparison::strict ? distance < threshold : distance <= threshold;
}

ConfusionCounts count_labels(const std::vector<QueryResult>& results, double threshold,
                             LabelRule rule, ThresholdComparison comparison) {
  require_valid(results, "count_labels");
  ConfusionCounts counts;
  for (const QueryResult& r : results) {
    ++label_of(counts, r, accepts(r.distance, threshold, comparison), rule);
  }
  return counts;
}

std::vector<double> sweep_thresholds(const std::vector<QueryResult>& results, ThresholdSweep sweep,
                                     bool multi_session) {
  require_valid(results, "sweep_thresholds");
  std::vector<double> thresholds;
  if (results.empty()) return thresholds;
  switch (sweep) {
    case ThresholdSweep::exact: {
      // Every distinct top-1 distance, ascending.
      for (const QueryResult& r : results) thresholds.push_back(r.distance);
      std::sort(thresholds.begin(), thresholds.end());
      thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());
      break;
    }
    case ThresholdSweep::linear100: {
      // 100 evenly spaced from the smallest to the largest d*, both included; one when equal.
      const auto [low, high] = std::minmax_element(
          results.begin(), results.end(),
          [](const QueryResult& a, const QueryResult& b) { return a.distance < b.distance; });
      if (low->distance == high->distance) {
        thresholds.push_back(low->distance);
      } else {
        append_linspace(low->distance, high->distance, 100, true, thresholds);
      }
      break;
    }
    case ThresholdSweep::mulran_grid: {
      // The MulRan evaluator's [linspace(0, 0.01, 50), linspace(0.01, 1, 50)]: 100 thresholds,
      // 0.01 listed twice (a repeated point adds nothing to the trapezoids; it is kept so that
      // per-threshold counts line up with that evaluator's 100 columns).
      append_linspace(0.0, 0.01, 50, true, thresholds);
      append_linspace(0.01, 1.0, 50, true, thresholds);
      break;
    }
    case ThresholdSweep::referee_grid: {
      // The ReFeree code takes the smallest and largest non-zero top-1 distance (0 marks its
      // queries without candidates) and builds np.linspace over 100 points: single session from
      // the largest down to the smallest, multi session from the smallest up to the largest plus
      // a hundredth of the range (so that its strict comparison accepts the largest too).
      // Ascending here; the order changes no count.
      double low = 0.0;
      double high = 0.0;
      bool any = false;
      for (const QueryResult& r : results) {
        if (r.distance == 0.0) continue;
        low = any ? std::min(low, r.distance) : r.distance;
        high = any ? std::max(high, r.distance) : r.distance;
        any = true;
      }
      if (!any) break;
      if (multi_session) high += (high - low) / 100;
      if (low == high) {
        thresholds.assign(100, low);  // np.linspace of equal ends: 100 equal thresholds
      } else {
        append_linspace(low, high, 100, true, thresholds);
      }
      break;
    }
  }
  return thresholds;
}

std::vector<CurvePoint> compute_curve(const std::vector<QueryResult>& results,
                                      const std::vector<double>& thresholds, LabelRule rule,
                                      ThresholdComparison comparison) {
  require_valid(results, "compute_curve");
  require_ascending(thresholds, "compute_curve");
  // One pass: results sorted by distance move from their rejected to their accepted label as
  // the threshold rises, so a sweep over n distinct distances costs O(n log n), not O(n^2).
  std::vector<std::size_t> order(results.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return results[a].distance < results[b].distance;
  });
  ConfusionCounts counts;
  for (const QueryResult& r : results) ++label_of(counts, r, false, rule);

  std::vector<CurvePoint> curve;
  curve.reserve(thresholds.size());
  std::size_t next = 0;
  for (const double threshold : thresholds) {
    while (next < order.size() && accepts(results[order[next]].distance, threshold, comparison)) {
      const QueryResult& r = results[order[next]];
      --label_of(counts, r, false, rule);
      ++label_of(counts, r, true, rule);
      ++next;
    }
    curve.push_back(make_point(threshold, counts));
  }
  return curve;
}

std::optional<double> roc_auc_pooled_pairs(const std::vector<QueryResult>& results,
                                           const std::vector<double>& thresholds,
                                           ThresholdComparison comparison) {
  require_valid(results, "roc_auc_pooled_pairs");
  require_ascending(thresholds, "roc_auc_pooled_pairs");
  // A result's weight is the number of thresholds that accept it. The Mann-Whitney form of the
  // AUC over the weighted samples: for every (wrong, right) pair of samples, 1 when the wrong
  // one's distance is larger, 1/2 when equal; summed over results sorted by distance, with the
  // right weight seen below each distance, so the cost is O(n log n).
  struct Sample {
    double distance;
    bool wrong;
    double weight;
  };
  std::vector<Sample> samples;
  for (const QueryResult& r : results) {
    const auto first_accepting =
        comparison == ThresholdComparison::strict
            ? std::upper_bound(thresholds.begin(), thresholds.end(), r.distance)
            : std::lower_bound(thresholds.begin(), thresholds.end(), r.distance);
    const auto weight = static_cast<double>(thresholds.end() - first_accepting);
    if (weight > 0) samples.push_back({r.distance, !r.correct, weight});
  }
  std::sort(samples.begin(), samples.end(),
            [](const Sample& a, const Sample& b) { return a.distance < b.distance; });
  double wrong_total = 0.0;
  double right_total = 0.0;
  double right_below = 0.0;  // right weight at distances below the current group
  double area = 0.0;
  for (std::size_t begin = 0; begin < samples.size();) {
    std::size_t end = begin;
    double wrong_here = 0.0;
    double right_here = 0.0;
    while (end < samples.size() && samples[end].distance == samples[begin].distance) {
      (samples[end].wrong ? wrong_here : right_here) += samples[end].weight;
      ++end;
    }
    area += wrong_here * (right_below + right_here / 2);
    right_below += right_here;
    wrong_total += wrong_here;
    right_total += right_here;
    begin = end;
  }
  if (wrong_total == 0.0 || right_total == 0.0) return std::nullopt;
  return area / (wrong_total * right_total);
}

std::optional<double> roc_auc_query_ranks(const std::vector<QueryResult>& results) {
  require_valid(results, "roc_auc_query_ranks");
  if (results.empty()) return std::nullopt;
  // One threshold accepting every result makes each result one sample of the pooled AUC: the
  // Mann-Whitney AUC of (wrong, distance) equals that of (right, -distance).
  double largest = results.front().distance;
  for (const QueryResult& r : results) largest = std::max(largest, r.distance);
  return roc_auc_pooled_pairs(results, {largest}, ThresholdComparison::inclusive);
}

std::optional<double> recall_at(const Metrics& metrics, int k, RecallDenominator denominator) {
  if (k == 1) {
    switch (denominator) {
      case RecallDenominator::revisit_queries:
        return metrics.recall_at_1;
      case RecallDenominator::all_queries:
        return metrics.recall_at_1_all_queries;
      case RecallDenominator::queries_with_positive:
        return metrics.recall_at_1_with_positive;
    }
  }
  const auto& values =
      denominator == RecallDenominator::all_queries             ? metrics.recall_at_k_all_queries
      : denominator == RecallDenominator::queries_with_positive ? metrics.recall_at_k_with_positive
                                                                : metrics.recall_at_k;
  const auto it = values.find(k);
  return it == values.end() ? std::nullopt : it->second;
}

Metrics compute_metrics(const std::vector<QueryResult>& results,
                        const std::vector<CurvePoint>& curve, const std::vector<int>& recall_at_k,
                        RocAucVariant roc_auc, ThresholdComparison comparison) {
  require_valid(results, "compute_metrics");
  Metrics metrics;
  for (const int k : recall_at_k) {
    if (k < 1) {
      throw std::invalid_argument("compute_metrics: Recall@K needs K >= 1, got " +
                                  std::to_string(k));
    }
    metrics.recall_at_k[k] = std::nullopt;
    metrics.recall_at_k_all_queries[k] = std::nullopt;
    metrics.recall_at_k_with_positive[k] = std::nullopt;
  }
  std::vector<double> thresholds;
  for (const CurvePoint& point : curve) thresholds.push_back(point.threshold);
  require_ascending(thresholds, "compute_metrics");

  metrics.queries = results.size();
  // No evaluated query: nothing is defined (the map keeps its keys with empty values).
  if (results.empty()) return metrics;
  std::size_t correct_revisits = 0;
  for (const QueryResult& r : results) {
    if (r.revisit) ++metrics.revisits;
    if (r.correct) ++metrics.correct_top1;
    if (r.revisit && r.correct) ++correct_revisits;
  }

  // F1-max: the best defined F1; on ties the smallest threshold (the first in ascending order).
  for (const CurvePoint& point : curve) {
    if (point.f1 && (!metrics.f1_max || *point.f1 > *metrics.f1_max)) {
      metrics.f1_max = point.f1;
      metrics.f1_max_threshold = point.threshold;
    }
  }

  // ROC AUC: trapezoid over (FPR, TPR) in ascending threshold order, undefined points left out,
  // (0,0) prepended and (1,1) appended; undefined when no point is defined, when no threshold
  // accepts a query (a grid sweep that misses the distances' range: the curve is (0,0) only and
  // its 0.5 would mean nothing), or when no threshold has a true negative (every query a revisit
  // under the standard labels: FPR is 1 from the first wrong match on, and the area only says
  // how early that came).
  std::vector<std::pair<double, double>> roc;
  bool any_accepted = false;
  bool any_true_negative = false;
  for (const CurvePoint& point : curve) {
    if (point.fpr && point.recall) roc.emplace_back(*point.fpr, *point.recall);
    any_accepted = any_accepted || point.counts.tp + point.counts.fp > 0;
    any_true_negative = any_true_negative || point.counts.tn > 0;
  }
  if (roc_auc == RocAucVariant::pooled_pairs) {
    metrics.roc_auc = roc_auc_pooled_pairs(results, thresholds, comparison);
  } else if (roc_auc == RocAucVariant::query_ranks) {
    metrics.roc_auc = roc_auc_query_ranks(results);
  } else if (!roc.empty() && any_accepted && any_true_negative) {
    roc.insert(roc.begin(), {0.0, 0.0});
    roc.emplace_back(1.0, 1.0);
    metrics.roc_auc = trapezoid(roc);
  }

  // PR-AUC: trapezoid over the defined (recall, precision) points in threshold order, no ends
  // added. AP: sum of (R_i - R_{i-1}) * P_i over the same points with R_0 = 0.
  std::vector<std::pair<double, double>> pr;
  for (const CurvePoint& point : curve) {
    if (point.recall && point.precision) pr.emplace_back(*point.recall, *point.precision);
  }
  if (!pr.empty()) {
    metrics.pr_auc = trapezoid(pr);
    double average_precision = 0.0;
    double previous_recall = 0.0;
    for (const auto& [recall, precision] : pr) {
      average_precision += (recall - previous_recall) * precision;
      previous_recall = recall;
    }
    metrics.average_precision = average_precision;
    // VPR-Bench: scikit-learn's curve ends in (recall 0, precision 1); its auc() integrates the
    // points in order, which here is that end first.
    std::vector<std::pair<double, double>> from_origin = {{0.0, 1.0}};
    from_origin.insert(from_origin.end(), pr.begin(), pr.end());
    metrics.pr_auc_vpr_bench = trapezoid(from_origin);
  }

  // The MulRan evaluator's PR-AUC (prcurve_drawer.m): the trapezoid over every threshold's
  // (recall, precision) in threshold order with the first precision set to 1, whatever it was.
  // Undefined where that evaluator's would be NaN: a recall, or a later precision, 0/0.
  if (!curve.empty()) {
    double area = 0.0;
    bool defined = curve.front().recall.has_value();
    double previous_recall = curve.front().recall.value_or(0.0);
    double previous_precision = 1.0;
    for (std::size_t i = 1; i < curve.size() && defined; ++i) {
      defined = curve[i].recall.has_value() && curve[i].precision.has_value();
      if (!defined) break;
      area += (*curve[i].recall - previous_recall) * (*curve[i].precision + previous_precision) / 2;
      previous_recall = *curve[i].recall;
      previous_precision = *curve[i].precision;
    }
    if (defined) metrics.pr_auc_mulran = area;
  }

  // Recall@K over every evaluated query: a non-revisit query has no frame within the radius, so
  // it only adds to the denominator.
  for (const auto& [k, recall] : metrics.recall_at_k) {
    std::size_t found = 0;
    for (const QueryResult& r : results) {
      if (r.first_correct_rank >= 1 && r.first_correct_rank <= static_cast<std::size_t>(k)) {
        ++found;
      }
    }
    metrics.recall_at_k_all_queries[k] = ratio(found, metrics.queries);
  }
  metrics.recall_at_1_all_queries = ratio(metrics.correct_top1, metrics.queries);

  // VPR-Bench's extended precision: the precision of the first threshold that accepts a query
  // (scikit-learn's precision[-2]), whatever its recall, and the recall at 100 % precision only
  // when that precision is 1 (a later threshold cannot reach precision 1 after a wrong match).
  for (const CurvePoint& point : curve) {
    if (point.counts.tp + point.counts.fp == 0) continue;
    const double first_precision = *point.precision;
    double full_precision_recall = 0.0;
    if (first_precision == 1.0) {
      for (const CurvePoint& later : curve) {
        if (later.precision && *later.precision == 1.0 && later.recall) {
          full_precision_recall = std::max(full_precision_recall, *later.recall);
        }
      }
    }
    metrics.extended_precision_vpr_bench = (first_precision + full_precision_recall) / 2;
    break;
  }

  // Everything below is a share of revisit queries: undefined without any.
  if (metrics.revisits == 0) return metrics;

  // Recall@1: revisit queries whose top-1 is correct; Recall@K: with a correct frame in the
  // K nearest (first_correct_rank in [1, K]).
  metrics.recall_at_1 = ratio(correct_revisits, metrics.revisits);
  for (auto& [k, recall] : metrics.recall_at_k) {
    std::size_t found = 0;
    for (const QueryResult& r : results) {
      if (r.revisit && r.first_correct_rank >= 1 &&
          r.first_correct_rank <= static_cast<std::size_t>(k)) {
        ++found;
      }
    }
    recall = ratio(found, metrics.revisits);
  }
  // Queries with a positive in the database they were searched against: the revisit queries
  // (Metrics::recall_at_k_with_positive says why), counted from the same flag.
  std::size_t with_positive = 0;
  for (const QueryResult& r : results) with_positive += r.revisit ? 1 : 0;
  metrics.recall_at_1_with_positive = ratio(correct_revisits, with_positive);
  for (auto& [k, recall] : metrics.recall_at_k_with_positive) {
    recall = metrics.recall_at_k.at(k);
  }

  // Recall at 100% precision: the largest recall where precision is exactly 1; 0 when no
  // threshold reaches precision 1.
  double recall_at_full_precision = 0.0;
  for (const CurvePoint& point : curve) {
    if (point.precision && *point.precision == 1.0 && point.recall) {
      recall_at_full_precision = std::max(recall_at_full_precision, *point.recall);
    }
  }
  metrics.recall_at_100_precision = recall_at_full_precision;

  // EP = (precision at the smallest threshold with non-zero recall + R@100%P) / 2; undefined
  // (never 0) when no threshold reaches a non-zero recall: that precision does not exist.
  for (const CurvePoint& point : curve) {
    if (point.recall && *point.recall > 0.0 && point.precision) {
      metrics.extended_precision = (*point.precision + recall_at_full_precision) / 2;
      break;
    }
  }
  return metrics;
}

}  // namespace radarpr
