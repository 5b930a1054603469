// The committed reference results (results/quickstart, results/paper_table_synthetic) are whole
// enough for the report and the comparison: a timing-free summary.json and the per-dataset files
// the figures read, as a fresh clone has them.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "evaluation/report/compare.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/csv_file.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

// The committed files of a reference result, copied to `root`/`name` (the report writes beside
// them; the source tree stays untouched).
fs::path copy_of_reference(const fs::path& root, const std::string& name) {
  const fs::path source = fs::path(RADARPR_SOURCE_DIR) / "results" / name;
  const fs::path copy = root / name;
  fs::copy(source, copy, fs::copy_options::recursive);
  // A run in this checkout leaves its (uncommitted) timing.json there; a fresh clone has none.
  fs::remove(copy / "timing.json");
  return copy;
}

TEST(ReferenceResults, SummaryJsonHoldsNoTimingAndNoCacheState) {
  for (const char* name : {"quickstart", "paper_table_synthetic"}) {
    const fs::path folder = fs::path(RADARPR_SOURCE_DIR) / "results" / name;
    ASSERT_TRUE(fs::exists(folder / "summary.json")) << folder;
    const auto summary = nlohmann::json::parse(read_text(folder / "summary.json"));
    EXPECT_FALSE(summary.contains("seconds")) << name;
    EXPECT_FALSE(summary.contains("machine")) << name;
    for (const auto& row : summary["rows"]) {
      EXPECT_FALSE(row.contains("extract_ms_per_scan")) << name;
      EXPECT_FALSE(row.contains("values_from")) << name;
    }
  }
}

TEST(ReferenceResults, ReportAndCompareWorkOnTheCommittedFiles) {
  const fs::path root = testing::scratch_folder("reference");
  const fs::path quickstart = copy_of_reference(root, "quickstart");
  const fs::path paper = copy_of_reference(root, "paper_table_synthetic");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  const ReportOutcome report = write_report(quickstart, {});
  EXPECT_GT(report.figures, 0u);
  // Table I of the report is summary.md's, with the best values in bold.
  std::string table1 = read_text(quickstart / "table1.md");
  for (auto at = table1.find("**"); at != std::string::npos; at = table1.find("**"))
    table1.erase(at, 2);
  EXPECT_NE(read_text(quickstart / "summary.md").find(table1), std::string::npos) << table1;
  EXPECT_NE(read_text(quickstart / "index.html").find("not recorded"), std::string::npos);

  const ReportOutcome compared = write_comparison({quickstart, paper}, root / "cmp");
  EXPECT_TRUE(fs::exists(root / "cmp" / "index.html"));
  const CsvFile table(root / "cmp" / "compare.csv");
  // quickstart's 4 descriptors and the paper table's 7.
  EXPECT_EQ(table.row_count(), 11u);
  (void)compared;
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
