#include <gtest/gtest.h>

#include "evaluation/report/gnuplot_runner.hpp"
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
                "radarpr: warning: RADARPR_GNUPLOT names /nonexistent/gnuplot, which is not an "
                "executable file: figures' data and scripts written to {}, not drawn",
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

// Figures are drawn by several gnuplot processes at once: the files are the same as one by one.
TEST(RunReport, DrawingInParallelGivesTheSameFiles) {
  if (!find_gnuplot()) GTEST_SKIP() << "gnuplot is not installed: no figure is drawn";
  const fs::path root = testing::scratch_folder("parallel_figures");
  testing::write_small_results(root / "run");
  const fs::path one = testing::copy_of_run(root, "one");
  const fs::path two = testing::copy_of_run(root, "two");
  ASSERT_EQ(testing::run_cli("report " + one.string() + " --threads 1").exit_code, 0);
  const auto parallel = testing::run_cli("report " + two.string() + " --threads 2");
  ASSERT_EQ(parallel.exit_code, 0) << parallel.output;
  std::size_t svgs = 0;
  for (const auto& entry : fs::directory_iterator(one / "figures")) {
    EXPECT_EQ(testing::read_text(entry.path()),
              testing::read_text(two / "figures" / entry.path().filename()))
        << entry.path().filename();
    svgs += entry.path().extension() == ".svg" ? 1 : 0;
  }
  EXPECT_GT(svgs, 1u);
  EXPECT_EQ(testing::read_text(one / "index.html"), testing::read_text(two / "index.html"));
  fs::remove_all(root);
}

// A PATH folder that cannot be searched (here a symbolic link loop: ELOOP even for root) is
// skipped as a shell skips it; it used to throw, and `run` exited 1 after writing its results.
TEST(RunReport, AnUnsearchablePathFolderIsSkipped) {
  const fs::path root = testing::scratch_folder("path_loop");
  fs::create_directory_symlink(root / "loop", root / "loop");
  const std::string path = (root / "loop").string() + ":/usr/bin:/bin";
  {
    const testing::ScopedEnvironment search("PATH", path.c_str());
    const testing::ScopedEnvironment unset("RADARPR_GNUPLOT", "");
    std::optional<fs::path> found;
    EXPECT_NO_THROW(found = find_gnuplot());
    EXPECT_EQ(found.has_value(), fs::exists("/usr/bin/gnuplot") || fs::exists("/bin/gnuplot"));
  }
  std::ofstream(root / "config.json") << testing::small_report_experiment("path_loop").dump();
  const auto result =
      testing::run_cli(fmt::format("run {} --out {} --quiet", (root / "config.json").string(),
                                   (root / "out").string()),
                       "PATH='" + path + "' RADARPR_GNUPLOT=");
  EXPECT_EQ(result.exit_code, 0) << result.output;
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
