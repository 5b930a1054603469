// summary.md's per-dataset table, worked by hand on a constructed run: the columns, and the note
// that says why a Recall@K is n/a for a key-then-rerank descriptor.
#include <gtest/gtest.h>

#include "evaluation/results/summary_table.hpp"

namespace radarpr {
namespace {

DescriptorRun descriptor_run(const std::string& id, std::optional<double> recall_at_5) {
  DescriptorRun run;
  run.id = id;
  run.label = id;
  run.rows = 2;
  run.cols = 3;
  run.payload_bytes = 24;
  run.paper_bytes = 176;
  Metrics& m = run.evaluation.metrics;
  m.queries = 10;
  m.revisits = 4;
  m.roc_auc = 0.9;
  m.f1_max = 0.8;
  m.recall_at_1 = 0.5;
  m.recall_at_k = {{1, 0.5}, {5, recall_at_5}};
  return run;
}

Protocol recall_1_and_5() {
  Protocol protocol;
  protocol.recall_at_k = {1, 5};
  return protocol;
}

TEST(SummaryTable, ColumnsPerRecallAtK) {
  DatasetRun dataset;
  dataset.descriptors = {descriptor_run("a", 0.75)};
  EXPECT_EQ(
      summary_table(dataset, recall_1_and_5()),
      "| descriptor | shape | element type | payload bytes | paper bytes | ROC AUC | F1-max | "
      "Recall@1 | Recall@5 | queries | revisits |\n"
      "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
      "| a | 2x3 | float32 | 24 | 176 | 0.900 | 0.800 | 0.500 | 0.750 | 10 | 4 |\n");
}

TEST(SummaryTable, SaysWhyARecallBeyondTheRerankedCandidatesIsNa) {
  DatasetRun dataset;
  dataset.descriptors = {descriptor_run("a", 0.75), descriptor_run("sc:candidates=3", {})};
  const std::string table = summary_table(dataset, recall_1_and_5());
  EXPECT_NE(table.find("| 0.500 | n/a | 10 | 4 |\n"), std::string::npos) << table;
  EXPECT_TRUE(table.ends_with(
      "\nn/a under Recall@5 for sc:candidates=3: these descriptors re-rank only the candidates "
      "their key pre-search hands over (their `candidates` parameter), so a K beyond them cannot "
      "be judged.\n"))
      << table;
}

TEST(SummaryTable, NoNoteWhenEveryRecallIsUndefinedForLackOfRevisits) {
  DatasetRun dataset;
  dataset.descriptors = {descriptor_run("a", {})};
  dataset.descriptors[0].evaluation.metrics.recall_at_1.reset();
  dataset.descriptors[0].evaluation.metrics.recall_at_k[1].reset();
  EXPECT_EQ(summary_table(dataset, recall_1_and_5()).find("n/a under"), std::string::npos);
}

}  // namespace
}  // namespace radarpr
