#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <set>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "evaluation/report/gnuplot_runner.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_writer.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

class ReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(testing::scratch_folder("report"));
    testing::write_small_results(*root_ / "run");
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete root_;
  }
  static fs::path fresh_copy(const std::string& name) { return testing::copy_of_run(*root_, name); }
  static fs::path* root_;
};
fs::path* ReportTest::root_ = nullptr;

const std::vector<std::string> kDatasets = {"town", "town_2_sessions"};
const std::vector<std::string> kDescriptors = {"referee", "referee_r:kernel=box,z_q=3"};

std::vector<std::string> expected_figures() {
  std::vector<std::string> names{"auc_vs_size"};
  for (const auto& d : kDatasets) {
    names.push_back("pr_" + d);
    names.push_back("roc_" + d);
    names.push_back("recall_at_n_" + d);
    for (const auto& id : kDescriptors) {
      names.push_back("graph_" + d + "__" + descriptor_folder_name(id));
      names.push_back("graphxy_" + d + "__" + descriptor_folder_name(id));
    }
  }
  return names;
}

TEST_F(ReportTest, TableValuesEqualTheSummary) {
  const fs::path folder = fresh_copy("tables");
  write_report(folder, {});
  const auto summary = nlohmann::json::parse(read_text(folder / "summary.json"));
  const CsvFile table1(folder / "table1.csv");
  ASSERT_EQ(table1.row_count(), kDescriptors.size());
  for (const auto& row : summary["rows"]) {
    const auto d = std::find(kDescriptors.begin(), kDescriptors.end(), row["descriptor"]) -
                   kDescriptors.begin();
    const std::string dataset = row["dataset"];
    // summary.md's rounding: 3 decimals; an undefined metric is n/a (the multi session here:
    // every query is a revisit, so ROC AUC has no negatives).
    auto shown = [](const nlohmann::json& value) {
      return value.is_null() ? std::string("n/a") : fmt::format("{:.3f}", value.get<double>());
    };
    EXPECT_EQ(table1.text(static_cast<std::size_t>(d), table1.column(dataset + " AUC")),
              shown(row["roc_auc"]));
    EXPECT_EQ(table1.text(static_cast<std::size_t>(d), table1.column(dataset + " F1-max")),
              shown(row["f1_max"]));
  }
  // The Markdown Table I is summary.md's, with the best of each column in bold.
  const std::string md = read_text(folder / "table1.md");
  std::string plain = md;
  for (auto at = plain.find("**"); at != std::string::npos; at = plain.find("**")) {
    plain.erase(at, 2);
  }
  EXPECT_NE(read_text(folder / "summary.md").find(plain), std::string::npos) << md;
  EXPECT_NE(md.find("**"), std::string::npos);
  EXPECT_NE(read_text(folder / "table1.tex").find("\\textbf{"), std::string::npos);

  const CsvFile table2(folder / "table2.csv");
  ASSERT_EQ(table2.row_count(), kDescriptors.size());
  EXPECT_EQ(table2.text(0, table2.column("payload bytes")), "200");  // 50 float32
  EXPECT_EQ(table2.text(0, table2.column("paper bytes")), "528");    // 50 x 8 + 128
  EXPECT_EQ(table2.text(1, table2.column("id")), "referee_r:kernel=box,z_q=3");
  EXPECT_EQ(table2.text(1, table2.column("shape")), "10x1");  // 840 bins / 80
  EXPECT_TRUE(fs::exists(folder / "table2.md") && fs::exists(folder / "table2.tex"));
}

TEST_F(ReportTest, EveryFigureHasDataAndScriptAndIsDrawnWithGnuplot) {
  const fs::path folder = fresh_copy("figures");
  const ReportOutcome outcome = write_report(folder, {});
  EXPECT_EQ(outcome.figures, expected_figures().size());
  for (const auto& name : expected_figures()) {
    EXPECT_TRUE(fs::exists(folder / "figures" / (name + ".csv"))) << name;
    const std::string script = read_text(folder / "figures" / (name + ".gp"));
    EXPECT_NE(script.find("'" + name + ".csv'"), std::string::npos) << name;  // relative path
    EXPECT_NE(script.find("set output '" + name + ".svg'"), std::string::npos) << name;
  }
  // The PR data holds each descriptor's sweep and the F1-max points, with the summary's values.
  const std::string pr = read_text(folder / "figures" / "pr_town.csv");
  EXPECT_TRUE(pr.starts_with("recall,precision,threshold,series\n"));
  EXPECT_NE(pr.find("\"referee_r:kernel=box,z_q=3\""), std::string::npos);
  if (!find_gnuplot()) GTEST_SKIP() << "gnuplot absent: svg and png not checked";
  EXPECT_TRUE(outcome.warnings.empty()) << outcome.warnings.front();
  EXPECT_EQ(outcome.drawn, outcome.figures);
  for (const auto& name : expected_figures()) {
    EXPECT_NE(read_text(folder / "figures" / (name + ".svg")).find("<svg"), std::string::npos);
    const cv::Mat png = cv::imread((folder / "figures" / (name + ".png")).string());
    ASSERT_FALSE(png.empty()) << name;
    cv::Scalar mean, deviation;
    cv::meanStdDev(png, mean, deviation);
    EXPECT_GT(deviation[0], 5.0) << name << ": a blank image";
  }
}

TEST_F(ReportTest, PageIsSelfContained) {
  const fs::path folder = fresh_copy("page");
  const ReportOutcome outcome = write_report(folder, {});
  const std::string html = read_text(folder / "index.html");
  EXPECT_TRUE(html.starts_with("<!DOCTYPE html>"));
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  for (const char* reference :
       {"src=\"http", "src='http", "href=\"http", "href='http", "url(http", "@import"}) {
    EXPECT_EQ(html.find(reference), std::string::npos) << reference;
  }
  EXPECT_EQ(html.find("http"), std::string::npos) << "the page links nothing outside its folder";
  // The tables, protocol and descriptor ids are on the page; the machine and times are linked
  // (timing.json), never copied: the page is reproduced byte for byte by a rerun.
  EXPECT_NE(html.find("<strong>"), std::string::npos);
  EXPECT_NE(html.find("Revisit radius 10 m"), std::string::npos);
  EXPECT_NE(html.find("<code>referee_r:kernel=box,z_q=3</code>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"timing.json\">"), std::string::npos);
  EXPECT_EQ(html.find("logical_cores"), std::string::npos);
  // Every drawn figure is linked from figures/ (never inlined: the SVGs are files already), and
  // every link names a file that exists.
  EXPECT_EQ(html.find("<svg"), std::string::npos);
  std::size_t images = 0;
  const std::string link = "<img src=\"figures/";
  for (auto at = html.find(link); at != std::string::npos; at = html.find(link, at + 1)) {
    const auto start = at + link.size();
    const std::string name = html.substr(start, html.find('"', start) - start);
    EXPECT_TRUE(fs::exists(folder / "figures" / name)) << name;
    ++images;
  }
  EXPECT_EQ(images, outcome.drawn);
}

TEST_F(ReportTest, MissingGnuplotWarnsAndStillWritesTheData) {
  const fs::path folder = fresh_copy("nognuplot");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "/nonexistent/gnuplot");
  const ReportOutcome outcome = write_report(folder, {});
  ASSERT_EQ(outcome.warnings.size(), 1u);
  EXPECT_EQ(outcome.warnings[0],
            fmt::format("RADARPR_GNUPLOT names /nonexistent/gnuplot, which is not an executable "
                        "file: figures' data and scripts written to {}, not drawn",
                        (folder / "figures").string()));
  EXPECT_EQ(outcome.drawn, 0u);
  for (const auto& name : expected_figures()) {
    EXPECT_TRUE(fs::exists(folder / "figures" / (name + ".csv"))) << name;
    EXPECT_TRUE(fs::exists(folder / "figures" / (name + ".gp"))) << name;
    EXPECT_FALSE(fs::exists(folder / "figures" / (name + ".svg"))) << name;
  }
  const std::string html = read_text(folder / "index.html");
  EXPECT_NE(html.find("Not drawn"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder / "table1.md"));
}

TEST_F(ReportTest, TheWarningSaysWhyNoFigureIsDrawn) {
  const fs::path folder = fresh_copy("why_not_drawn");
  const std::string written = fmt::format(": figures' data and scripts written to {}, not drawn",
                                          (folder / "figures").string());
  {
    const testing::ScopedEnvironment off("RADARPR_GNUPLOT", "off");
    EXPECT_EQ(write_report(folder, {}).warnings,
              std::vector<std::string>{"gnuplot is off (RADARPR_GNUPLOT=off)" + written});
  }
  {
    const testing::ScopedEnvironment unset("RADARPR_GNUPLOT", "");
    const testing::ScopedEnvironment no_gnuplot_on_path("PATH", (folder / "nowhere").c_str());
    EXPECT_EQ(write_report(folder, {}).warnings,
              std::vector<std::string>{"gnuplot not found on PATH (install gnuplot to draw them)" +
                                       written});
  }
  {
    // A folder is not a program: named as what it is.
    const testing::ScopedEnvironment folder_path("RADARPR_GNUPLOT", folder.c_str());
    EXPECT_EQ(write_report(folder, {}).warnings,
              std::vector<std::string>{"RADARPR_GNUPLOT names " + folder.string() +
                                       ", which is not an executable file" + written});
  }
}

// A figure whose data is rewritten but which is not drawn again loses its old images: an image
// beside newer data would show something the data no longer says.
TEST_F(ReportTest, ImagesOfAFigureNotDrawnAgainAreRemoved) {
  if (!find_gnuplot()) GTEST_SKIP() << "gnuplot absent: no image to go stale";
  const fs::path folder = fresh_copy("stale_images");
  ASSERT_EQ(write_report(folder, {}).drawn, expected_figures().size());
  std::ofstream(folder / "figures" / "my_own.svg") << "<svg/>";
  {
    const testing::ScopedEnvironment off("RADARPR_GNUPLOT", "off");
    EXPECT_EQ(write_report(folder, {}).drawn, 0u);
  }
  for (const auto& name : expected_figures()) {
    EXPECT_TRUE(fs::exists(folder / "figures" / (name + ".csv"))) << name;
    EXPECT_FALSE(fs::exists(folder / "figures" / (name + ".svg"))) << name;
    EXPECT_FALSE(fs::exists(folder / "figures" / (name + ".png"))) << name;
  }
  EXPECT_TRUE(fs::exists(folder / "figures" / "my_own.svg")) << "a file the report did not write";
}

TEST_F(ReportTest, AFailingScriptIsAWarningNamingIt) {
  const fs::path folder = fresh_copy("failing");
  // /bin/false stands for a gnuplot that rejects every script.
  const testing::ScopedEnvironment failing("RADARPR_GNUPLOT", "/bin/false");
  const ReportOutcome outcome = write_report(folder, {});
  ASSERT_EQ(outcome.warnings.size(), expected_figures().size());
  EXPECT_EQ(outcome.warnings[0], fmt::format("{}: gnuplot failed (exit code 1)",
                                             (folder / "figures" / "auc_vs_size.gp").string()));
  EXPECT_TRUE(fs::exists(folder / "index.html"));
}

TEST_F(ReportTest, MatchingGraphHoldsTheSummaryEdgesAndMissedOnRequest) {
  const fs::path folder = fresh_copy("graph");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(folder, {});
  const std::string name = "graph_town__referee";
  const std::string without = read_text(folder / "figures" / (name + ".csv"));
  write_report(folder, {.include_missed = true});
  const std::string with = read_text(folder / "figures" / (name + ".csv"));
  // One data row per TP / FP edge (+ the path); the FN rows only with include_missed.
  const CsvFile edges(folder / "town" / "referee" / "matching_graph.csv");
  std::size_t tp = 0, fp = 0, fn = 0;
  for (std::size_t i = 0; i < edges.row_count(); ++i) {
    const std::string& label = edges.text(i, edges.column("label"));
    (label == "TP" ? tp : label == "FP" ? fp : fn) += 1;
  }
  auto count = [](const std::string& csv, const std::string& kind) {
    std::size_t n = 0;
    for (auto at = csv.find("," + kind + "\n"); at != std::string::npos;
         at = csv.find("," + kind + "\n", at + 1))
      ++n;
    return n;
  };
  ASSERT_GT(tp, 0u);
  EXPECT_EQ(count(without, "tp"), tp);
  EXPECT_EQ(count(without, "fp"), fp);
  EXPECT_EQ(count(without, "fn"), 0u);
  EXPECT_EQ(count(with, "fn"), fn);
  EXPECT_EQ(count(without, "path"), 160u);  // every frame of the single session
  EXPECT_NE(read_text(folder / "figures" / (name + ".gp")).find("title 'TP (" + std::to_string(tp)),
            std::string::npos);
}

}  // namespace
}  // namespace radarpr

namespace radarpr {
namespace {

TEST_F(ReportTest, ResultsWithoutTrajectoryDrawThePathFromTheMatches) {
  // Results written before trajectory.csv existed: the frames matches.csv names make the path.
  const fs::path folder = fresh_copy("old_results");
  fs::remove(folder / "town" / "trajectory.csv");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(folder, {});
  const CsvFile matches(folder / "town" / "referee" / "matches.csv");
  std::set<std::string> frames;
  for (std::size_t i = 0; i < matches.row_count(); ++i) {
    frames.insert(matches.text(i, matches.column("query")));
    frames.insert(matches.text(i, matches.column("match")));
  }
  const std::string graph = read_text(folder / "figures" / "graph_town__referee.csv");
  std::size_t path_rows = 0;
  for (auto at = graph.find(",path\n"); at != std::string::npos; at = graph.find(",path\n", at + 1))
    ++path_rows;
  EXPECT_EQ(path_rows, frames.size());
  EXPECT_LT(path_rows, 160u);  // the first 30 frames are never queried, nor all matched
}

}  // namespace
}  // namespace radarpr

namespace radarpr {
namespace {

TEST_F(ReportTest, AucSizeMeansAreOnThePageAndInTable3) {
  const fs::path folder = fresh_copy("auc_means");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(folder, {});
  const auto summary = nlohmann::json::parse(read_text(folder / "summary.json"));
  const CsvFile table3(folder / "table3.csv");
  // One single-session dataset (town) and one multi (its AUCs n/a: no true negatives).
  ASSERT_EQ(table3.row_count(), 4u);
  for (std::size_t r = 0; r < 2; ++r) {
    EXPECT_EQ(table3.text(r, table3.column("session")), "single");
    EXPECT_EQ(table3.text(r, table3.column("mean ROC AUC")),
              fmt::format("{:.3f}", summary["rows"][r]["roc_auc"].get<double>()));
    EXPECT_EQ(table3.text(r, table3.column("datasets averaged")), "1 of 1");
    EXPECT_EQ(table3.text(r + 2, table3.column("mean ROC AUC")), "n/a");
    EXPECT_EQ(table3.text(r + 2, table3.column("datasets averaged")), "0 of 1");
  }
  const std::string html = read_text(folder / "index.html");
  EXPECT_NE(html.find("averaged over the datasets of one session kind"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">1 of 1</td>"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder / "table3.md") && fs::exists(folder / "table3.tex"));
  // Every descriptor alike (0 of 1) in the multi session: the means compare, no note.
  EXPECT_EQ(html.find("class=\"warning\""), std::string::npos);
}

// PR-AUC, Recall@1 and R@100P per dataset: summary.json's values, in table4 and on the page.
TEST_F(ReportTest, RetrievalMetricsAreOnThePageAndInTable4) {
  const fs::path folder = fresh_copy("retrieval");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(folder, {});
  const auto summary = nlohmann::json::parse(read_text(folder / "summary.json"));
  const CsvFile table4(folder / "table4.csv");
  const auto shown = [](const nlohmann::json& value) {
    return value.is_null() ? std::string("n/a") : fmt::format("{:.3f}", value.get<double>());
  };
  std::size_t checked = 0;
  for (const auto& row : summary["rows"]) {
    const std::string dataset = row["dataset"].get<std::string>();
    std::size_t r = 0;
    while (r < table4.row_count() && table4.text(r, 0) != row["label"].get<std::string>()) ++r;
    ASSERT_LT(r, table4.row_count()) << row["label"];
    EXPECT_EQ(table4.text(r, table4.column(dataset + " PR-AUC")), shown(row["pr_auc_trapezoid"]));
    EXPECT_EQ(table4.text(r, table4.column(dataset + " R@1")), shown(row["recall_at_1"]));
    EXPECT_EQ(table4.text(r, table4.column(dataset + " R@100P")),
              shown(row["recall_at_100_precision"]));
    ++checked;
  }
  EXPECT_EQ(checked, 4u);
  const std::string html = read_text(folder / "index.html");
  EXPECT_NE(html.find("Retrieval per dataset: PR-AUC, Recall@1 and R@100P"), std::string::npos);
  EXPECT_NE(
      html.find(fmt::format("<td class=\"num\">{}</td>", shown(summary["rows"][0]["recall_at_1"]))),
      std::string::npos);
  // Table I says which label rule and sweep its AUC comes from.
  EXPECT_NE(html.find(fmt::format("with labels <code>{}</code> and threshold sweep <code>{}</code>",
                                  summary["protocol"]["labels"].get<std::string>(),
                                  summary["protocol"]["sweep"].get<std::string>())),
            std::string::npos);
  EXPECT_TRUE(fs::exists(folder / "table4.md") && fs::exists(folder / "table4.tex"));

  // Results written before these metrics were recorded still report: n/a, not an error.
  auto older = summary;
  for (auto& row : older["rows"]) row.erase("recall_at_100_precision");
  std::ofstream(folder / "summary.json") << older.dump();
  write_report(folder, {});
  EXPECT_EQ(CsvFile(folder / "table4.csv").text(0, 3), "n/a");
}

TEST_F(ReportTest, UnevenAucMeansAreAWarningOnThePageAndInTheCsv) {
  const fs::path folder = fresh_copy("auc_uneven");
  auto json = nlohmann::json::parse(read_text(folder / "summary.json"));
  json["rows"][0]["roc_auc"] = nullptr;  // town, referee: n/a, the other descriptor 0.x
  std::ofstream(folder / "summary.json") << json.dump();
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  const ReportOutcome outcome = write_report(folder, {});
  ASSERT_EQ(outcome.warnings.size(), 2u);  // the uneven means, then gnuplot off
  EXPECT_TRUE(outcome.warnings[0].starts_with((folder / "figures" / "auc_vs_size.csv").string() +
                                              ": the mean ROC AUCs are over different numbers"))
      << outcome.warnings[0];
  EXPECT_NE(
      outcome.warnings[0].find("single session: referee 0 of 1, referee_r:kernel=box,z_q=3 1 of 1"),
      std::string::npos)
      << outcome.warnings[0];
  EXPECT_NE(read_text(folder / "figures" / "auc_vs_size.csv").find("# note: the mean ROC AUCs"),
            std::string::npos);
  EXPECT_NE(read_text(folder / "index.html").find("class=\"warning\">Note: the mean ROC AUCs"),
            std::string::npos);
}

TEST_F(ReportTest, StaleStagingIsRemovedAndUserFilesInFiguresKept) {
  const fs::path folder = fresh_copy("stale");
  const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
  write_report(folder, {});
  // A pid that surely is gone: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);
  const fs::path dead = folder / fmt::format(".report.partial.{}", child);
  const fs::path alive = folder / fmt::format(".report.partial.{}", ::getppid());
  fs::create_directories(dead / "figures");
  fs::create_directories(alive);
  std::ofstream(folder / "figures" / "pr_town_paper.gp") << "# my restyled copy\n";
  std::ofstream(folder / "figures" / "pr_town.gp") << "# edited in place: overwritten\n";
  write_report(folder, {});
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(alive));  // another report may be writing it
  EXPECT_EQ(read_text(folder / "figures" / "pr_town_paper.gp"), "# my restyled copy\n");
  EXPECT_NE(read_text(folder / "figures" / "pr_town.gp"), "# edited in place: overwritten\n");
  fs::remove_all(alive);
}

}  // namespace
}  // namespace radarpr
