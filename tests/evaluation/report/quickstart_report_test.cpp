#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "evaluation/report/gnuplot_runner.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_writer.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

std::string without_bold(std::string text) {
  for (auto at = text.find("**"); at != std::string::npos; at = text.find("**")) text.erase(at, 2);
  return text;
}

// The README's main job, run as a user runs it: its summary is the committed reference, every
// figure the report promises is there, and the report's tables carry the summary's values.
TEST(QuickstartReport, FiguresAndTablesOfTheQuickstartEqualItsSummary) {
  const fs::path source(RADARPR_SOURCE_DIR);
  const fs::path out = testing::scratch_folder("quickstart") / "out";
  // --no-cache: the scans are rendered in memory, nothing is written beside the build.
  const auto run =
      testing::run_cli(fmt::format("run '{}' --out '{}' --quiet --no-cache",
                                   (source / "configs/quickstart.json").string(), out.string()));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(read_text(out / "summary.md"), read_text(source / "results/quickstart/summary.md"))
      << "the committed quickstart reference no longer matches a run: regenerate it";
  // So is what the report reads (summary.json holds no time; timing.json is not committed).
  for (const char* file :
       {"summary.json", "synthetic_town/trajectory.csv", "synthetic_town/referee_r/curve.csv",
        "synthetic_town_2_sessions/referee/matching_graph.csv",
        "synthetic_town_2_sessions/referee_a/matches.csv"}) {
    EXPECT_EQ(read_text(out / file), read_text(source / "results/quickstart" / file)) << file;
  }

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  std::set<std::string> datasets, descriptors;
  const CsvFile table1(out / "table1.csv");
  for (const auto& row : summary["rows"]) {
    const std::string dataset = row["dataset"];
    const std::string descriptor = row["descriptor"];
    datasets.insert(dataset);
    descriptors.insert(descriptor);
    std::size_t line = table1.row_count();
    for (std::size_t r = 0; r < table1.row_count(); ++r) {
      if (table1.text(r, table1.column("descriptor")) == descriptor) line = r;
    }
    ASSERT_LT(line, table1.row_count()) << descriptor << " missing from table1.csv";
    EXPECT_EQ(table1.text(line, table1.column(dataset + " AUC")),
              fmt::format("{:.3f}", row["roc_auc"].get<double>()));
    EXPECT_EQ(table1.text(line, table1.column(dataset + " F1-max")),
              fmt::format("{:.3f}", row["f1_max"].get<double>()));
  }
  EXPECT_EQ(datasets.size(), 2u);
  EXPECT_EQ(descriptors.size(), 4u);
  EXPECT_EQ(table1.row_count(), descriptors.size());
  // Table I in Markdown is summary.md's with the best of each column in bold.
  EXPECT_NE(read_text(out / "summary.md").find(without_bold(read_text(out / "table1.md"))),
            std::string::npos);
  for (const char* table : {"table1", "table2"}) {
    for (const char* format : {".md", ".csv", ".tex"}) {
      EXPECT_TRUE(fs::exists(out / (std::string(table) + format))) << table << format;
    }
  }

  std::vector<std::string> figures{"auc_vs_size"};
  for (const auto& dataset : datasets) {
    figures.push_back("pr_" + dataset);
    figures.push_back("roc_" + dataset);
    for (const auto& descriptor : descriptors) {
      figures.push_back("graph_" + dataset + "__" + descriptor_folder_name(descriptor));
    }
  }
  const bool drawn = find_gnuplot().has_value();
  for (const auto& name : figures) {
    for (const char* kind : {".csv", ".gp", ".svg", ".png"}) {
      if (!drawn && (kind == std::string(".svg") || kind == std::string(".png"))) continue;
      EXPECT_TRUE(fs::exists(out / "figures" / (name + kind))) << name << kind;
    }
  }
  const std::string page = read_text(out / "index.html");
  for (const auto& descriptor : descriptors) EXPECT_NE(page.find(descriptor), std::string::npos);
  fs::remove_all(out.parent_path());
  if (!drawn) GTEST_SKIP() << "gnuplot absent: the figures' svg and png were not checked";
}

}  // namespace
}  // namespace radarpr
