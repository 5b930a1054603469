#include "evaluation/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace radarpr {
namespace {

QueryResult result(std::size_t query, double distance, bool correct, bool revisit,
                   std::size_t first_correct_rank) {
  QueryResult r;
  r.query = query;
  r.match = 0;
  r.distance = distance;
  r.correct = correct;
  r.revisit = revisit;
  r.first_correct_rank = first_correct_rank;
  return r;
}

// Five hand-made queries:     d   correct revisit rank
//   A                         1   yes     yes     1
//   B                         2   no      yes     3   (a revisit whose top-1 is wrong)
//   C                         3   no      no      0
//   D                         4   yes     yes     1
//   E                         4   no      no      0   (ties with D)
std::vector<QueryResult> five_queries() {
  return {result(0, 1.0, true, true, 1), result(1, 2.0, false, true, 3),
          result(2, 3.0, false, false, 0), result(3, 4.0, true, true, 1),
          result(4, 4.0, false, false, 0)};
}

void expect_counts(const ConfusionCounts& c, std::size_t tp, std::size_t fp, std::size_t fn,
                   std::size_t tn) {
  EXPECT_EQ(c.tp, tp);
  EXPECT_EQ(c.fp, fp);
  EXPECT_EQ(c.fn, fn);
  EXPECT_EQ(c.tn, tn);
}

void expect_near(const std::optional<double>& actual, double expected) {
  ASSERT_TRUE(actual.has_value());
  EXPECT_NEAR(*actual, expected, 1e-12);
}

TEST(CountLabels, StandardRule) {
  const auto results = five_queries();
  // tau 0.5: nothing accepted; revisits A, B, D -> FN 3; C, E -> TN 2.
  expect_counts(count_labels(results, 0.5, LabelRule::standard), 0, 0, 3, 2);
  // tau 1: A accepted correct -> TP; rejected B, D revisits -> FN 2; C, E -> TN 2.
  expect_counts(count_labels(results, 1.0, LabelRule::standard), 1, 0, 2, 2);
  // tau 2: + B accepted wrong -> FP 1; rejected D -> FN 1; C, E -> TN 2.
  expect_counts(count_labels(results, 2.0, LabelRule::standard), 1, 1, 1, 2);
  // tau 3: + C accepted wrong -> FP 2; rejected D -> FN 1, E -> TN 1.
  expect_counts(count_labels(results, 3.0, LabelRule::standard), 1, 2, 1, 1);
  // tau 4: all accepted: A, D -> TP 2; B, C, E -> FP 3.
  expect_counts(count_labels(results, 4.0, LabelRule::standard), 2, 3, 0, 0);
}

TEST(CountLabels, RetrievedPairRule) {
  const auto results = five_queries();
  // Rejected -> FN only when the retrieved frame is correct (A, D), otherwise TN (B too).
  // tau 0.5: FN A, D = 2; TN B, C, E = 3.
  expect_counts(count_labels(results, 0.5, LabelRule::retrieved_pair), 0, 0, 2, 3);
  // tau 1: TP A; FN D; TN B, C, E.
  expect_counts(count_labels(results, 1.0, LabelRule::retrieved_pair), 1, 0, 1, 3);
  // tau 2: TP A; FP B; FN D; TN C, E.
  expect_counts(count_labels(results, 2.0, LabelRule::retrieved_pair), 1, 1, 1, 2);
  // tau 3: TP A; FP B, C; FN D; TN E.
  expect_counts(count_labels(results, 3.0, LabelRule::retrieved_pair), 1, 2, 1, 1);
  // tau 4: TP A, D; FP B, C, E.
  expect_counts(count_labels(results, 4.0, LabelRule::retrieved_pair), 2, 3, 0, 0);
}

TEST(SweepThresholds, ExactIsEveryDistinctDistanceAscending) {
  // Distances 1, 2, 3, 4, 4 -> 1, 2, 3, 4.
  EXPECT_EQ(sweep_thresholds(five_queries(), ThresholdSweep::exact),
            (std::vector<double>{1.0, 2.0, 3.0, 4.0}));
}

TEST(SweepThresholds, Linear100SpansSmallestToLargestDistance) {
  const auto thresholds = sweep_thresholds(five_queries(), ThresholdSweep::linear100);
  ASSERT_EQ(thresholds.size(), 100u);
  EXPECT_EQ(thresholds.front(), 1.0);
  EXPECT_EQ(thresholds.back(), 4.0);
  // Step (4 - 1) / 99: t[33] = 1 + 33 * 3 / 99 = 2, t[66] = 3.
  EXPECT_DOUBLE_EQ(thresholds[33], 2.0);
  EXPECT_DOUBLE_EQ(thresholds[66], 3.0);
  EXPECT_DOUBLE_EQ(thresholds[1], 1.0 + 3.0 / 99.0);
  for (std::size_t i = 1; i < thresholds.size(); ++i) EXPECT_LT(thresholds[i - 1], thresholds[i]);
}

TEST(SweepThresholds, Linear100WithOneDistinctDistanceIsOneThreshold) {
  const std::vector<QueryResult> results = {result(0, 2.5, false, false, 0),
                                            result(1, 2.5, true, true, 1)};
  EXPECT_EQ(sweep_thresholds(results, ThresholdSweep::linear100), (std::vector<double>{2.5}));
}

TEST(SweepThresholds, MulranGridHasTheEvaluatorsHundredThresholds) {
  const auto thresholds = sweep_thresholds(five_queries(), ThresholdSweep::mulran_grid);
  // [linspace(0, 0.01, 50), linspace(0.01, 1, 50)]: 100 thresholds, 0.01 twice.
  ASSERT_EQ(thresholds.size(), 100u);
  EXPECT_EQ(thresholds[0], 0.0);
  EXPECT_DOUBLE_EQ(thresholds[1], 0.01 / 49);  // first step 0.01 / 49
  EXPECT_EQ(thresholds[49], 0.01);
  EXPECT_EQ(thresholds[50], 0.01);
  EXPECT_DOUBLE_EQ(thresholds[51], 0.01 + 0.99 / 49);  // second step 0.99 / 49
  EXPECT_EQ(thresholds[99], 1.0);
  for (std::size_t i = 1; i < thresholds.size(); ++i) {
    if (i != 50) {
      EXPECT_LT(thresholds[i - 1], thresholds[i]) << i;
    }
  }
}

// By hand: A d 0.1 correct revisit, B d 0.2 wrong revisit, C d 0.3 correct revisit, D d 0.4
// non-revisit. Thresholds 0, 0.15, 0.35 (standard labels): TP/FP/FN 0/0/3, 1/0/2, 2/1/0, so
// (R, P) = (0, undefined), (1/3, 1), (1, 2/3). The MulRan evaluator forces the first precision
// to 1: 1/2 (1 + 1) 1/3 + 1/2 (1 + 2/3) 2/3 = 1/3 + 5/9 = 8/9; the plain trapezoid over the
// defined points is only 1/2 (1 + 2/3) 2/3 = 5/9.
TEST(ComputeMetrics, MulranPrAucForcesTheFirstPrecisionToOne) {
  const std::vector<QueryResult> results = {
      result(0, 0.1, true, true, 1), result(1, 0.2, false, true, 0), result(2, 0.3, true, true, 1),
      result(3, 0.4, false, false, 0)};
  const auto curve = compute_curve(results, {0.0, 0.15, 0.35}, LabelRule::standard);
  const Metrics m = compute_metrics(results, curve, {1});
  expect_near(m.pr_auc_mulran, 8.0 / 9.0);
  expect_near(m.pr_auc, 5.0 / 9.0);
  // A later threshold accepting nothing new keeps it defined; one with 0/0 precision after the
  // first would be NaN in the evaluator: undefined here.
  // Recall@1 over revisit queries: A and C of A, B, C; over all four queries: 2/4.
  expect_near(m.recall_at_k.at(1), 2.0 / 3.0);
  expect_near(m.recall_at_k_all_queries.at(1), 0.5);
  const auto undefined_later = compute_curve(results, {0.0, 0.05, 0.35}, LabelRule::standard);
  EXPECT_FALSE(compute_metrics(results, undefined_later, {1}).pr_auc_mulran.has_value());
}

// The ReFeree code's grid: np.linspace over the non-zero distances' range, 100 points; in a multi
// session the top is raised by a hundredth of the range.
TEST(SweepThresholds, RefereeGridIsTheCodesLinspace) {
  std::vector<QueryResult> results = five_queries();   // distances 1, 2, 3, 4, 4
  results.push_back(result(5, 0.0, false, false, 0));  // 0: left out of the range
  const auto single = sweep_thresholds(results, ThresholdSweep::referee_grid, false);
  ASSERT_EQ(single.size(), 100u);
  EXPECT_EQ(single.front(), 1.0);
  EXPECT_EQ(single.back(), 4.0);
  const auto multi = sweep_thresholds(results, ThresholdSweep::referee_grid, true);
  ASSERT_EQ(multi.size(), 100u);
  EXPECT_EQ(multi.front(), 1.0);
  EXPECT_EQ(multi.back(), 4.03);  // 4 + (4 - 1) / 100
  EXPECT_DOUBLE_EQ(multi[1], 1.0 + 3.03 / 99);
  // Only zeros: no range, no thresholds.
  EXPECT_TRUE(sweep_thresholds({result(0, 0.0, true, true, 1)}, ThresholdSweep::referee_grid, true)
                  .empty());
}

TEST(CountLabels, StrictComparisonRejectsADistanceEqualToTheThreshold) {
  const auto results = five_queries();
  // tau 2 strict: only A (d 1) accepted; B (d 2) is rejected and wrong -> TN (retrieved pair).
  expect_counts(count_labels(results, 2.0, LabelRule::retrieved_pair, ThresholdComparison::strict),
                1, 0, 1, 3);
  const auto curve =
      compute_curve(results, {2.0, 4.0}, LabelRule::retrieved_pair, ThresholdComparison::strict);
  expect_counts(curve[0].counts, 1, 0, 1, 3);
  expect_counts(curve[1].counts, 1, 2, 1, 1);  // d 4 (D, E) still rejected at 4
}

// Pooled pairs by hand on the five queries (A 1 right, B 2 wrong, C 3 wrong, D 4 right, E 4
// wrong), thresholds 1..5. Strict: each result counts once per threshold above its distance:
// A 4, B 3, C 2, D 1, E 1. Right weight 5, wrong 6. Wrong-above-right pairs: B>A 3*4, C>A 2*4,
// E>A 1*4, and E = D half of 1*1: 24.5 / 30. Inclusive: A 5, B 4, C 3, D 2, E 2: (4*5 + 3*5 + 2*5
// + 0.5*2*2) / (7*9) = 47/63. Both are what scikit-learn's roc_auc_score gives on the pooled
// samples the ReFeree code builds (labels 1 = wrong, scores = distances).
TEST(RocAucPooledPairs, HandComputedWeightsAndTies) {
  const auto results = five_queries();
  const std::vector<double> thresholds = {1, 2, 3, 4, 5};
  expect_near(roc_auc_pooled_pairs(results, thresholds, ThresholdComparison::strict), 24.5 / 30);
  expect_near(roc_auc_pooled_pairs(results, thresholds, ThresholdComparison::inclusive), 47.0 / 63);
  // Only right (or only wrong) pairs accepted: undefined, as scikit-learn refuses one class.
  EXPECT_FALSE(roc_auc_pooled_pairs(results, {1.5}, ThresholdComparison::strict).has_value());
  EXPECT_FALSE(roc_auc_pooled_pairs(results, {0.5}, ThresholdComparison::strict).has_value());
}

// The ReFeree code's multi-session evaluation replayed on the five queries: its grid
// linspace(1, 4.03, 100), strict acceptance, retrieved-pair labels. Accepted sets grow
// {A} (t > 1), {A, B} (t > 2), {A, B, C} (t > 3), all (t > 4): F1 2/3, 1/2, 2/5, 4/7, so F1-max
// 2/3 at the grid's second threshold 1 + 3.03 / 99. Pooled weights: A 99, B 67 (i >= 33), C 34
// (i >= 66), D and E 1 (i = 99): (67*99 + 34*99 + 1*99 + 0.5) / (100 * 102) = 10098.5 / 10200.
// scikit-learn on the code's pooled samples: 0.9900490196078431.
TEST(ComputeMetrics, RefereeCodeMultiSessionByHand) {
  const auto results = five_queries();
  const auto thresholds = sweep_thresholds(results, ThresholdSweep::referee_grid, true);
  const auto curve =
      compute_curve(results, thresholds, LabelRule::retrieved_pair, ThresholdComparison::strict);
  expect_counts(curve[0].counts, 0, 0, 2, 3);   // t = 1 accepts nothing
  expect_counts(curve[1].counts, 1, 0, 1, 3);   // {A}
  expect_counts(curve[33].counts, 1, 1, 1, 2);  // {A, B}
  expect_counts(curve[66].counts, 1, 2, 1, 1);  // {A, B, C}
  expect_counts(curve[98].counts, 1, 2, 1, 1);  // t = 3.9997: D, E still out
  expect_counts(curve[99].counts, 2, 3, 0, 0);  // t = 4.03: all
  const Metrics m = compute_metrics(results, curve, {1}, RocAucVariant::pooled_pairs,
                                    ThresholdComparison::strict);
  expect_near(m.f1_max, 2.0 / 3.0);
  expect_near(m.f1_max_threshold, 1.0 + 3.03 / 99);
  expect_near(m.roc_auc, 10098.5 / 10200);
  // The trapezoid variant of the same curve differs: the variant is what the protocol says.
  const Metrics trapezoid =
      compute_metrics(results, curve, {1}, RocAucVariant::trapezoid, ThresholdComparison::strict);
  ASSERT_TRUE(trapezoid.roc_auc.has_value());
  EXPECT_NE(*trapezoid.roc_auc, *m.roc_auc);
}

TEST(SweepThresholds, NoResultsNoThresholds) {
  for (const auto sweep :
       {ThresholdSweep::exact, ThresholdSweep::linear100, ThresholdSweep::mulran_grid}) {
    EXPECT_TRUE(sweep_thresholds({}, sweep).empty());
  }
}

TEST(ComputeCurve, AgreesWithCountLabelsAtEveryThreshold) {
  const auto results = five_queries();
  const std::vector<double> thresholds = {-1.0, 0.5, 1.0, 1.5, 2.0, 3.0, 3.99, 4.0, 10.0};
  for (const auto rule : {LabelRule::standard, LabelRule::retrieved_pair}) {
    const auto curve = compute_curve(results, thresholds, rule);
    ASSERT_EQ(curve.size(), thresholds.size());
    for (std::size_t i = 0; i < thresholds.size(); ++i) {
      const ConfusionCounts expected = count_labels(results, thresholds[i], rule);
      EXPECT_EQ(curve[i].threshold, thresholds[i]);
      expect_counts(curve[i].counts, expected.tp, expected.fp, expected.fn, expected.tn);
    }
  }
}

TEST(ComputeCurve, StandardRatios) {
  const auto curve = compute_curve(five_queries(), {0.5, 1.0, 2.0, 3.0, 4.0}, LabelRule::standard);
  // tau 0.5 (TP0 FP0 FN3 TN2): P undefined, R = 0/3, FPR = 0/2, F1 undefined.
  EXPECT_FALSE(curve[0].precision.has_value());
  expect_near(curve[0].recall, 0.0);
  expect_near(curve[0].fpr, 0.0);
  EXPECT_FALSE(curve[0].f1.has_value());
  // tau 1 (1 0 2 2): P 1, R 1/3, FPR 0, F1 = 2*(1/3)/(4/3) = 1/2.
  expect_near(curve[1].precision, 1.0);
  expect_near(curve[1].recall, 1.0 / 3);
  expect_near(curve[1].fpr, 0.0);
  expect_near(curve[1].f1, 0.5);
  // tau 2 (1 1 1 2): P 1/2, R 1/2, FPR 1/3, F1 1/2.
  expect_near(curve[2].precision, 0.5);
  expect_near(curve[2].recall, 0.5);
  expect_near(curve[2].fpr, 1.0 / 3);
  expect_near(curve[2].f1, 0.5);
  // tau 3 (1 2 1 1): P 1/3, R 1/2, FPR 2/3, F1 = 2*(1/6)/(5/6) = 2/5.
  expect_near(curve[3].precision, 1.0 / 3);
  expect_near(curve[3].recall, 0.5);
  expect_near(curve[3].fpr, 2.0 / 3);
  expect_near(curve[3].f1, 0.4);
  // tau 4 (2 3 0 0): P 2/5, R 1, FPR 1, F1 = 2*(2/5)/(7/5) = 4/7.
  expect_near(curve[4].precision, 0.4);
  expect_near(curve[4].recall, 1.0);
  expect_near(curve[4].fpr, 1.0);
  expect_near(curve[4].f1, 4.0 / 7);
}

TEST(ComputeCurve, UndefinedRatiosStayEmpty) {
  // One correct query accepted: FP + TN = 0 -> FPR undefined.
  const auto accepted = compute_curve({result(0, 1.0, true, true, 1)}, {1.0}, LabelRule::standard);
  expect_near(accepted[0].precision, 1.0);
  expect_near(accepted[0].recall, 1.0);
  EXPECT_FALSE(accepted[0].fpr.has_value());
  expect_near(accepted[0].f1, 1.0);
  // One wrong non-revisit query accepted: TP + FN = 0 -> recall and F1 undefined; P = 0/1.
  const auto wrong = compute_curve({result(0, 1.0, false, false, 0)}, {1.0}, LabelRule::standard);
  expect_near(wrong[0].precision, 0.0);
  EXPECT_FALSE(wrong[0].recall.has_value());
  expect_near(wrong[0].fpr, 1.0);
  EXPECT_FALSE(wrong[0].f1.has_value());
  // An accepted wrong non-revisit (FP) and a rejected revisit (FN): P = 0/1, R = 0/1 ->
  // F1 = 0 (P + R = 0), not undefined.
  const auto zero = compute_curve({result(0, 1.0, false, false, 0), result(1, 2.0, false, true, 0)},
                                  {1.0}, LabelRule::standard);
  expect_near(zero[0].precision, 0.0);
  expect_near(zero[0].recall, 0.0);
  expect_near(zero[0].f1, 0.0);
  // Empty results: every count 0, every ratio undefined.
  const auto empty = compute_curve({}, {1.0}, LabelRule::standard);
  ASSERT_EQ(empty.size(), 1u);
  expect_counts(empty[0].counts, 0, 0, 0, 0);
  EXPECT_FALSE(empty[0].precision || empty[0].recall || empty[0].fpr || empty[0].f1);
}

TEST(ComputeMetrics, StandardRuleByHand) {
  const auto results = five_queries();
  const auto curve =
      compute_curve(results, sweep_thresholds(results, ThresholdSweep::exact), LabelRule::standard);
  const Metrics m = compute_metrics(results, curve, {1, 2, 5});
  EXPECT_EQ(m.queries, 5u);
  EXPECT_EQ(m.revisits, 3u);      // A, B, D
  EXPECT_EQ(m.correct_top1, 2u);  // A, D
  // F1 per threshold 1/2, 1/2, 2/5, 4/7 -> max 4/7 at tau 4.
  expect_near(m.f1_max, 4.0 / 7);
  expect_near(m.f1_max_threshold, 4.0);
  // ROC (FPR, TPR): (0,0) (0,1/3) (1/3,1/2) (2/3,1/2) (1,1) (1,1):
  // 0 + 1/3*(1/3+1/2)/2 + 1/3*(1/2+1/2)/2 + 1/3*(1/2+1)/2 + 0 = 5/36 + 6/36 + 9/36 = 5/9.
  expect_near(m.roc_auc, 5.0 / 9);
  // PR (R, P): (1/3,1) (1/2,1/2) (1/2,1/3) (1,2/5):
  // 1/6*(1+1/2)/2 + 0 + 1/2*(1/3+2/5)/2 = 1/8 + 11/60 = 37/120.
  expect_near(m.pr_auc, 37.0 / 120);
  // AP: (1/3-0)*1 + (1/2-1/3)*1/2 + 0*1/3 + (1-1/2)*2/5 = 1/3 + 1/12 + 1/5 = 37/60.
  expect_near(m.average_precision, 37.0 / 60);
  // Recall@1: A and D of the 3 revisits; ranks A 1, B 3, D 1 -> @2 2/3, @5 3/3.
  expect_near(m.recall_at_1, 2.0 / 3);
  ASSERT_EQ(m.recall_at_k.size(), 3u);
  expect_near(m.recall_at_k.at(1), 2.0 / 3);
  expect_near(m.recall_at_k.at(2), 2.0 / 3);
  expect_near(m.recall_at_k.at(5), 1.0);
  // Precision 1 only at tau 1 (R 1/3); EP = (P at tau 1 = 1 + 1/3) / 2 = 2/3.
  expect_near(m.recall_at_100_precision, 1.0 / 3);
  expect_near(m.extended_precision, 2.0 / 3);
}

TEST(ComputeMetrics, RetrievedPairRuleByHand) {
  const auto results = five_queries();
  const auto curve = compute_curve(results, sweep_thresholds(results, ThresholdSweep::exact),
                                   LabelRule::retrieved_pair);
  const Metrics m = compute_metrics(results, curve, {1, 5, 10});
  // (TP FP FN TN) tau 1: 1 0 1 3; tau 2: 1 1 1 2; tau 3: 1 2 1 1; tau 4: 2 3 0 0.
  // P: 1, 1/2, 1/3, 2/5; R: 1/2, 1/2, 1/2, 1; FPR: 0, 1/3, 2/3, 1.
  // F1: 2*(1/2)/(3/2) = 2/3, 1/2, 2/5, 4/7 -> max 2/3 at tau 1.
  expect_near(m.f1_max, 2.0 / 3);
  expect_near(m.f1_max_threshold, 1.0);
  // ROC: (0,0) (0,1/2) (1/3,1/2) (2/3,1/2) (1,1) (1,1): 0 + 1/6 + 1/6 + 1/3*(3/2)/2 = 7/12.
  expect_near(m.roc_auc, 7.0 / 12);
  // PR: (1/2,1) (1/2,1/2) (1/2,1/3) (1,2/5): 0 + 0 + 1/2*(1/3+2/5)/2 = 11/60.
  expect_near(m.pr_auc, 11.0 / 60);
  // AP: 1/2*1 + 0 + 0 + 1/2*2/5 = 7/10.
  expect_near(m.average_precision, 0.7);
  // R@100%P: precision 1 at tau 1 with R 1/2; EP = (1 + 1/2)/2 = 3/4.
  expect_near(m.recall_at_100_precision, 0.5);
  expect_near(m.extended_precision, 0.75);
  // Recall@K does not depend on the label rule: 2/3, and 1 from K = 3 on.
  expect_near(m.recall_at_1, 2.0 / 3);
  expect_near(m.recall_at_k.at(1), 2.0 / 3);
  expect_near(m.recall_at_k.at(5), 1.0);
  expect_near(m.recall_at_k.at(10), 1.0);
}

TEST(ComputeMetrics, F1TiesTakeTheSmallestThreshold) {
  // d 1, 2, 3; correct yes, yes, no; all revisits.
  // tau 1: TP1 FP0 FN2 -> F1 2/(2+0+2) = 1/2; tau 2: TP2 FN1 -> 4/5; tau 3: TP2 FP1 -> 4/5.
  const std::vector<QueryResult> results = {
      result(0, 1.0, true, true, 1), result(1, 2.0, true, true, 1), result(2, 3.0, false, true, 0)};
  const auto curve = compute_curve(results, {1.0, 2.0, 3.0}, LabelRule::standard);
  const Metrics m = compute_metrics(results, curve, {1});
  expect_near(m.f1_max, 0.8);
  expect_near(m.f1_max_threshold, 2.0);
}

TEST(ComputeMetrics, NoRevisitLeavesRecallMetricsUndefined) {
  const std::vector<QueryResult> results = {result(0, 1.0, false, false, 0),
                                            result(1, 2.0, false, false, 0),
                                            result(2, 3.0, false, false, 0)};
  const auto curve =
      compute_curve(results, sweep_thresholds(results, ThresholdSweep::exact), LabelRule::standard);
  // Every point has TP + FN = 0: recall undefined; precision 0 where anything is accepted.
  for (const CurvePoint& point : curve) {
    EXPECT_FALSE(point.recall.has_value());
    expect_near(point.precision, 0.0);
  }
  const Metrics m = compute_metrics(results, curve, {1, 5});
  EXPECT_EQ(m.queries, 3u);
  EXPECT_EQ(m.revisits, 0u);
  EXPECT_FALSE(m.roc_auc.has_value());
  EXPECT_FALSE(m.f1_max.has_value());
  EXPECT_FALSE(m.f1_max_threshold.has_value());
  EXPECT_FALSE(m.pr_auc.has_value());
  EXPECT_FALSE(m.average_precision.has_value());
  EXPECT_FALSE(m.recall_at_1.has_value());
  EXPECT_FALSE(m.recall_at_k.at(1).has_value());
  EXPECT_FALSE(m.recall_at_k.at(5).has_value());
  EXPECT_FALSE(m.recall_at_100_precision.has_value());
  EXPECT_FALSE(m.extended_precision.has_value());
}

TEST(ComputeMetrics, RevisitsWithoutAnyCorrectMatchScoreZero) {
  // A revisit whose top-1 is wrong (d 1) and a non-revisit (d 2): no TP anywhere.
  const std::vector<QueryResult> results = {result(0, 1.0, false, true, 0),
                                            result(1, 2.0, false, false, 0)};
  const auto curve = compute_curve(results, {1.0, 2.0}, LabelRule::standard);
  const Metrics m = compute_metrics(results, curve, {1});
  // tau 1: FP1 TN1, tau 2: FP2 -> recall undefined (TP + FN = 0) at both: no ROC, no F1.
  EXPECT_FALSE(m.roc_auc.has_value());
  EXPECT_FALSE(m.f1_max.has_value());
  // There is a revisit: Recall@1 = 0/1, R@100%P = 0 (no point with precision 1); EP is
  // undefined, not 0: no threshold reaches a non-zero recall, so its precision does not exist.
  expect_near(m.recall_at_1, 0.0);
  expect_near(m.recall_at_k.at(1), 0.0);
  expect_near(m.recall_at_100_precision, 0.0);
  EXPECT_FALSE(m.extended_precision.has_value());
}

// The five queries with every distance raised by 100: the MulRan grid (thresholds <= 1) accepts
// none of them. Every point is then TP 0, FP 0, FN 3 (revisits A, B, D), TN 2: TPR 0, FPR 0, so
// the curve is (0,0) alone and the trapezoid with the (1,1) end would be a meaningless 0.5.
TEST(ComputeMetrics, ASweepThatAcceptsNothingHasNoRocAuc) {
  auto results = five_queries();
  for (auto& r : results) r.distance += 100.0;
  const auto curve = compute_curve(results, sweep_thresholds(results, ThresholdSweep::mulran_grid),
                                   LabelRule::standard);
  expect_counts(curve.back().counts, 0, 0, 3, 2);
  const Metrics m = compute_metrics(results, curve, {1});
  EXPECT_FALSE(m.roc_auc.has_value());
  EXPECT_FALSE(m.f1_max.has_value());     // precision undefined everywhere
  expect_near(m.recall_at_1, 2.0 / 3.0);  // A and D of the revisits A, B, D: independent of tau
}

// Every query a revisit (a second session driving only places the first one saw):
//   A d 1 correct, B d 2 wrong, C d 3 correct.
// tau 1: TP1 FN2 -> FPR undefined; tau 2: TP1 FP1 FN1 -> FPR 1/1, TPR 1/2; tau 3: TP2 FP1 FN0
// -> FPR 1, TPR 1. No threshold can have a true negative, so the curve would be (0,0), (1, 1/2),
// (1, 1), (1, 1) with area 1/4, which only says how early the first wrong match came: left
// undefined. F1-max stays: tau 3, P 2/3, R 1, F1 0.8.
TEST(ComputeMetrics, NoTrueNegativeAnywhereHasNoRocAuc) {
  const std::vector<QueryResult> results = {
      result(0, 1.0, true, true, 1), result(1, 2.0, false, true, 2), result(2, 3.0, true, true, 1)};
  const auto curve = compute_curve(results, {1.0, 2.0, 3.0}, LabelRule::standard);
  expect_counts(curve[1].counts, 1, 1, 1, 0);
  const Metrics m = compute_metrics(results, curve, {1});
  EXPECT_FALSE(m.roc_auc.has_value());
  expect_near(m.f1_max, 0.8);
}

TEST(ComputeMetrics, EmptyResultsAreUndefined) {
  const std::vector<QueryResult> none;
  const auto curve =
      compute_curve(none, sweep_thresholds(none, ThresholdSweep::exact), LabelRule::standard);
  EXPECT_TRUE(curve.empty());
  const Metrics m = compute_metrics(none, curve, {1, 5, 10});
  EXPECT_EQ(m.queries, 0u);
  EXPECT_EQ(m.revisits, 0u);
  EXPECT_EQ(m.correct_top1, 0u);
  EXPECT_FALSE(m.roc_auc || m.f1_max || m.f1_max_threshold || m.pr_auc || m.average_precision ||
               m.pr_auc_mulran || m.recall_at_1 || m.recall_at_100_precision ||
               m.extended_precision);
  ASSERT_EQ(m.recall_at_k.size(), 3u);
  for (const auto& [k, recall] : m.recall_at_k) EXPECT_FALSE(recall.has_value()) << k;
  for (const auto& [k, recall] : m.recall_at_k_all_queries) EXPECT_FALSE(recall) << k;
}

TEST(Metrics, RejectBadInput) {
  const double nan = std::nan("");
  EXPECT_THROW(sweep_thresholds({result(0, nan, false, false, 0)}, ThresholdSweep::exact),
               std::invalid_argument);
  EXPECT_THROW(count_labels({result(0, std::numeric_limits<double>::infinity(), false, false, 0)},
                            1.0, LabelRule::standard),
               std::invalid_argument);
  // Correct but not a revisit is contradictory.
  EXPECT_THROW(compute_curve({result(0, 1.0, true, false, 1)}, {1.0}, LabelRule::standard),
               std::invalid_argument);
  EXPECT_THROW(compute_curve(five_queries(), {2.0, 1.0}, LabelRule::standard),
               std::invalid_argument);
  EXPECT_THROW(compute_curve(five_queries(), {nan}, LabelRule::standard), std::invalid_argument);
  EXPECT_THROW(compute_metrics(five_queries(), {}, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
