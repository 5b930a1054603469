#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// `radarpr run` ends with the report; without gnuplot it warns once and still succeeds.
TEST(RunReport, RunWritesTheReportAndAMissingGnuplotIsOnlyAWarning) {
  const fs::path root = testing::scratch_folder("run_cli");
  std::ofstream(root / "config.json") << testing::small_report_experiment("run_cli").dump();
  const fs::path out = root / "out";
  const auto result = testing::run_cli(
      fmt::format("run {} --out {} --quiet", (root / "config.json").string(), out.string()),
      "RADARPR_GNUPLOT=/nonexistent/gnuplot");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find(fmt::format(
                "radarpr: warning: gnuplot not found: figures' data and scripts written to {}, "
                "install gnuplot to draw them",
                (out / "figures").string())),
            std::string::npos)
      << result.output;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "town" / "trajectory.csv"));
  EXPECT_TRUE(fs::exists(out / "figures" / "pr_town.csv"));
  EXPECT_TRUE(fs::exists(out / "figures" / "pr_town.gp"));
  EXPECT_FALSE(fs::exists(out / "figures" / "pr_town.svg"));
  EXPECT_TRUE(fs::exists(out / "table1.tex"));
  EXPECT_TRUE(fs::exists(out / "index.html"));

  // `radarpr report` redraws from the files alone: the run's summary is left as it was.
  const std::string summary = testing::read_text(out / "summary.json");
  const auto report = testing::run_cli("report " + out.string() + " --missed");
  EXPECT_EQ(report.exit_code, 0) << report.output;
  EXPECT_EQ(testing::read_text(out / "summary.json"), summary);
  EXPECT_NE(report.output.find("report: " + (out / "index.html").string()), std::string::npos);
  fs::remove_all(root);
}

TEST(RunReport, VerbsExplainThemselves) {
  for (const char* verb : {"report", "compare"}) {
    const auto help = testing::run_cli(fmt::format("{} --help", verb));
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find(fmt::format("usage: radarpr {}", verb)), std::string::npos);
  }
  const auto usage = testing::run_cli("report");
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_NE(usage.output.find("see radarpr report --help"), std::string::npos) << usage.output;
}

}  // namespace
}  // namespace radarpr
