#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "evaluation/report/gnuplot_runner.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_writer.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/figure_images.hpp"
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
    figures.push_back("recall_at_n_" + dataset);
    for (const auto& descriptor : descriptors) {
      figures.push_back("graph_" + dataset + "__" + descriptor_folder_name(descriptor));
      figures.push_back("graphxy_" + dataset + "__" + descriptor_folder_name(descriptor));
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
  if (!drawn) {
    fs::remove_all(out.parent_path());
    GTEST_SKIP() << "gnuplot absent: the figures' svg, png and pdf were not checked";
  }

  // Every figure kind drawn in both styles: the screen style's images above, then the same
  // results redrawn in the paper style. Each PNG is the size its script asks for (paper: one
  // 3.5 in column at 300 dpi), each PDF a whole PDF whose page is the script's size (paper: 252 pt
  // wide), as pdfinfo reads it too when it is installed.
  const bool pdf = testing::has_pdfcairo();
  const bool pdfinfo = testing::has_pdfinfo();
  const auto check_images = [&](const std::string& style) {
    for (const auto& name : figures) {
      const std::string script = read_text(out / "figures" / (name + ".gp"));
      EXPECT_NE(script.find("# radarpr figure (" + style + " style)"), std::string::npos) << name;
      std::smatch match;
      ASSERT_TRUE(
          std::regex_search(script, match, std::regex(R"(set terminal pngcairo size (\d+),(\d+))")))
          << name;
      const auto png = testing::png_size(out / "figures" / (name + ".png"));
      ASSERT_TRUE(png) << name << ".png is not a PNG";
      EXPECT_EQ(png->first, std::stoul(match[1])) << name;
      EXPECT_EQ(png->second, std::stoul(match[2])) << name;
      if (style == "paper") {
        EXPECT_EQ(png->first, 1050u) << name;
      }
      if (!pdf) continue;
      ASSERT_TRUE(std::regex_search(
          script, match, std::regex(R"(set terminal pdfcairo size ([0-9.]+)in,([0-9.]+)in)")))
          << name;
      const auto sheet = testing::pdf_page(out / "figures" / (name + ".pdf"));
      ASSERT_TRUE(sheet) << name << ".pdf is missing or not a whole PDF";
      // cairo rounds the page to whole points.
      EXPECT_NEAR(sheet->first, std::stod(match[1]) * 72.0, 1.0) << name;
      EXPECT_NEAR(sheet->second, std::stod(match[2]) * 72.0, 1.0) << name;
      if (style == "paper") {
        EXPECT_NEAR(sheet->first, 252.0, 0.5) << name;
      }
      if (pdfinfo) {
        EXPECT_EQ(testing::pdfinfo_page_size(out / "figures" / (name + ".pdf")),
                  fmt::format("{:g} x {:g}", sheet->first, sheet->second))
            << name;
      }
    }
  };
  check_images("screen");
  const auto paper = testing::run_cli(fmt::format("report '{}' --style paper", out.string()));
  ASSERT_EQ(paper.exit_code, 0) << paper.output;
  EXPECT_NE(paper.output.find(fmt::format("({} figures, {} drawn", figures.size(), figures.size())),
            std::string::npos)
      << paper.output;
  check_images("paper");
  fs::remove_all(out.parent_path());
  if (!pdf) GTEST_SKIP() << "gnuplot without the pdfcairo terminal: no PDF was checked";
}

}  // namespace
}  // namespace radarpr
