#include <gtest/gtest.h>

#include <regex>

#include "evaluation/report/compare.hpp"
#include "evaluation/report/figure_files.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_error.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

TEST(ReportCompare, MergesTwoRunsIntoOneTableAndOverlaysCurves) {
  const fs::path root = testing::scratch_folder("compare");
  testing::write_small_results(root / "first");
  // The same experiment name in another folder: the labels take the folder names.
  fs::copy(root / "first", root / "second", fs::copy_options::recursive);
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  const ReportOutcome outcome = write_comparison({root / "first", root / "second"}, root / "cmp");
  const CsvFile table(root / "cmp" / "compare.csv");
  ASSERT_EQ(table.row_count(), 4u);  // 2 runs x 2 descriptors
  EXPECT_EQ(table.text(0, table.column("run")), "report_test (first)");
  EXPECT_EQ(table.text(3, table.column("run")), "report_test (second)");
  EXPECT_EQ(table.text(3, table.column("descriptor")), "referee_r:kernel=box,z_q=3");
  // Same values in both runs, as in their summaries.
  const auto summary = nlohmann::json::parse(read_text(root / "first" / "summary.json"));
  EXPECT_EQ(table.text(0, table.column("town AUC")),
            fmt::format("{:.3f}", summary["rows"][0]["roc_auc"].get<double>()));
  EXPECT_EQ(table.text(2, table.column("town AUC")), table.text(0, table.column("town AUC")));
  EXPECT_NE(read_text(root / "cmp" / "compare.md").find("**"), std::string::npos);
  EXPECT_EQ(outcome.figures, 4u);  // PR and ROC for both common datasets
  const std::string pr = read_text(root / "cmp" / "figures" / "pr_town.csv");
  EXPECT_NE(pr.find("\"report_test (second): referee\""), std::string::npos);
  EXPECT_TRUE(fs::exists(root / "cmp" / "index.html"));
  EXPECT_TRUE(fs::exists(root / "cmp" / "compare.json"));
  EXPECT_TRUE(fs::exists(root / "cmp" / "compare.tex"));

  // An earlier comparison is replaced; another folder is never.
  write_comparison({root / "first"}, root / "cmp");
  EXPECT_EQ(CsvFile(root / "cmp" / "compare.csv").row_count(), 2u);
  EXPECT_THROW(write_comparison({root / "first"}, root / "second"), ResultsError);
  EXPECT_TRUE(fs::exists(root / "second" / "summary.json"));

  // The verb: both runs in, one table out; a missing run named.
  const auto cli =
      testing::run_cli(fmt::format("compare {} {} --out {}", (root / "first").string(),
                                   (root / "second").string(), (root / "cmp").string()),
                       "RADARPR_GNUPLOT=off");
  EXPECT_EQ(cli.exit_code, 0) << cli.output;
  EXPECT_EQ(CsvFile(root / "cmp" / "compare.csv").row_count(), 4u);
  const auto missing = testing::run_cli(
      fmt::format("compare {} --out {}", (root / "nothing").string(), (root / "cmp2").string()));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.output.find((root / "nothing").string()), std::string::npos);
  EXPECT_FALSE(fs::exists(root / "cmp2"));
  fs::remove_all(root);
}

TEST(ReportCompare, SameNamedDatasetsThatDifferAreAWarningAndEachRunHasItsDash) {
  const fs::path root = testing::scratch_folder("compare_mismatch");
  testing::write_small_results(root / "first");
  fs::copy(root / "first", root / "second", fs::copy_options::recursive);
  // The second run's "town" was drawn from another drive: same name, other data.
  auto json = nlohmann::json::parse(read_text(root / "second" / "summary.json"));
  json["config"]["datasets"][0]["query"]["seed"] = 12;
  std::ofstream(root / "second" / "summary.json") << json.dump();
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  const ReportOutcome outcome = write_comparison({root / "first", root / "second"}, root / "cmp");
  ASSERT_EQ(outcome.warnings.size(), 2u);  // the mismatch, then gnuplot off
  EXPECT_TRUE(outcome.warnings[0].starts_with(
      "dataset 'town' differs between runs 'report_test (first)' and 'report_test (second)'"))
      << outcome.warnings[0];
  EXPECT_NE(outcome.warnings[0].find("\"seed\":12"), std::string::npos);
  const std::string html = read_text(root / "cmp" / "index.html");
  EXPECT_NE(html.find("class=\"warning\">Warning: dataset &#39;town&#39; differs"),
            std::string::npos);
  // town_2_sessions is the same in both: no warning for it.
  EXPECT_EQ(html.find("dataset &#39;town_2_sessions&#39; differs"), std::string::npos);
  // The version as text, not JSON ("0.1.0" without quotes).
  EXPECT_EQ(html.find("radarpr &quot;"), std::string::npos);
  // A descriptor keeps its colour and marker across runs; each run its dash type.
  const std::string gp = read_text(root / "cmp" / "figures" / "pr_town.gp");
  const std::regex first("dt 1 pt 6 [^\\n]* lc rgb '" + figure_palette()[1] + "'");
  const std::regex second("dt 2 pt 6 [^\\n]* lc rgb '" + figure_palette()[1] + "'");
  EXPECT_TRUE(std::regex_search(gp, first)) << gp;
  EXPECT_TRUE(std::regex_search(gp, second)) << gp;
  // The key below the plot, the bottom margin keeping the axis label clear of it.
  EXPECT_NE(gp.find("set key at screen 0.5, screen "), std::string::npos) << gp;
  EXPECT_NE(gp.find("set bmargin at screen "), std::string::npos) << gp;
  // The CLI prints the warning on stderr.
  const auto cli =
      testing::run_cli(fmt::format("compare {} {} --out {}", (root / "first").string(),
                                   (root / "second").string(), (root / "cmp").string()),
                       "RADARPR_GNUPLOT=off");
  EXPECT_EQ(cli.exit_code, 0) << cli.output;
  EXPECT_NE(cli.output.find("radarpr: warning: dataset 'town' differs"), std::string::npos)
      << cli.output;
  fs::remove_all(root);
}

// --out never touches what it compares: not a results folder it reads, nothing inside one (a
// comparison replaces its folder whole), not an earlier comparison that holds one, however the
// path is spelled (.., a link); nor the file system's root. The runs are left as they were.
TEST(ReportCompare, OutNeverReplacesOrEntersAFolderItReads) {
  const fs::path root = testing::scratch_folder("compare_out");
  testing::write_small_results(root / "run");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  // An earlier comparison with the run moved into it.
  write_comparison({root / "run"}, root / "cmp");
  fs::rename(root / "run", root / "cmp" / "run");
  const fs::path run = root / "cmp" / "run";
  const std::string summary = read_text(run / "summary.json");
  fs::create_directory_symlink(run, root / "link");
  const std::vector<std::pair<fs::path, std::string>> refused = {
      {run, "is inside the results folder"},
      {run / "cmp", "is inside the results folder"},
      {run / "figures" / ".." / "cmp", "is inside the results folder"},
      {root / "link" / "cmp", "is inside the results folder"},
      {root / "cmp", "holds the results folder"},
      {root / "cmp" / "run" / "..", "holds the results folder"},
      {"/", "needs a folder of its own"},
  };
  for (const auto& [out, reason] : refused) {
    try {
      write_comparison({run}, out);
      ADD_FAILURE() << out << ": accepted";
    } catch (const ResultsError& error) {
      EXPECT_NE(std::string(error.what()).find(reason), std::string::npos)
          << out << ": " << error.what();
    }
  }
  // The verb too: exit 1 with the reason, before writing anything.
  const auto cli =
      testing::run_cli(fmt::format("compare {} --out {}", run.string(), (run / "cmp").string()),
                       "RADARPR_GNUPLOT=off");
  EXPECT_EQ(cli.exit_code, 1) << cli.output;
  EXPECT_NE(cli.output.find("is inside the results folder"), std::string::npos) << cli.output;
  EXPECT_FALSE(fs::exists(run / "cmp"));
  EXPECT_EQ(read_text(run / "summary.json"), summary);
  EXPECT_TRUE(fs::exists(root / "cmp" / "compare.json"));
  // Beside the run is fine.
  EXPECT_NO_THROW(write_comparison({root / "link"}, root / "beside"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
