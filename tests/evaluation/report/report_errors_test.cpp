#include <gtest/gtest.h>

#include <sstream>

#include "evaluation/report/report.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/results_error.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

class ResultsErrorTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(testing::scratch_folder("errors"));
    testing::write_small_results(*root_ / "run");
    // A report already there: a failed report must leave it as it was.
    const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "off");
    write_report(*root_ / "run", {});
  }
  static void TearDownTestSuite() {
    fs::remove_all(*root_);
    delete root_;
  }
  static fs::path fresh_copy(const std::string& name) { return testing::copy_of_run(*root_, name); }
  // The report of `folder` fails with a message starting with `path`: and nothing changed.
  static void expect_refused(const fs::path& folder, const fs::path& path,
                             const std::string& expected) {
    const std::string page_before = read_text(folder / "index.html");
    const std::string table_before = read_text(folder / "table1.md");
    try {
      write_report(folder, {});
      ADD_FAILURE() << "no error for " << path;
    } catch (const ResultsError& error) {
      EXPECT_EQ(std::string(error.what()).rfind(path.string() + ": ", 0), 0u) << error.what();
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
    EXPECT_EQ(read_text(folder / "index.html"), page_before);
    EXPECT_EQ(read_text(folder / "table1.md"), table_before);
    for (const auto& entry : fs::directory_iterator(folder)) {
      EXPECT_FALSE(entry.path().filename().string().starts_with(".report.partial"));
    }
  }
  static fs::path* root_;
};
fs::path* ResultsErrorTest::root_ = nullptr;

TEST_F(ResultsErrorTest, MissingSummaryIsNamed) {
  const fs::path folder = fresh_copy("no_summary");
  fs::remove(folder / "summary.json");
  expect_refused(folder, folder / "summary.json", "missing");
}

TEST_F(ResultsErrorTest, TruncatedSummaryIsNamed) {
  const fs::path folder = fresh_copy("bad_summary");
  const std::string json = read_text(folder / "summary.json");
  std::ofstream(folder / "summary.json") << json.substr(0, json.size() / 2);
  expect_refused(folder, folder / "summary.json", "not valid JSON");
}

TEST_F(ResultsErrorTest, SummaryRowWithoutAucIsNamed) {
  const fs::path folder = fresh_copy("row");
  auto json = nlohmann::json::parse(read_text(folder / "summary.json"));
  json["rows"][1]["roc_auc"] = "high";
  std::ofstream(folder / "summary.json") << json.dump();
  expect_refused(folder, folder / "summary.json", "rows[1].roc_auc");
}

TEST_F(ResultsErrorTest, MissingCurveIsNamed) {
  const fs::path folder = fresh_copy("no_curve");
  const fs::path curve = folder / "town_2_sessions" / "referee" / "curve.csv";
  fs::remove(curve);
  expect_refused(folder, curve, "missing");
}

TEST_F(ResultsErrorTest, CorruptCurveIsNamedWithItsLine) {
  const fs::path folder = fresh_copy("bad_curve");
  const fs::path curve = folder / "town" / "referee" / "curve.csv";
  std::ofstream(curve, std::ios::app) << "0.5,1,2\n";  // a truncated row
  expect_refused(folder, curve, "fields, the header has 10");
  std::string text = read_text(curve);
  text.replace(text.rfind("0.5,1,2\n"), 8, "x,1,0,0,0,,,,,\n");  // a threshold that is no number
  std::ofstream(curve) << text;
  expect_refused(folder, curve, "column 'threshold' holds 'x'");
}

TEST_F(ResultsErrorTest, MissingOrCorruptMatchingGraphIsNamed) {
  const fs::path folder = fresh_copy("bad_graph");
  const fs::path graph =
      folder / "town" / descriptor_folder_name("referee_r:kernel=box,z_q=3") / "matching_graph.csv";
  std::string text = read_text(graph);
  const auto at = text.find(",TP,");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 4, ",OK,");
  std::ofstream(graph) << text;
  expect_refused(folder, graph, "label 'ok'");
  fs::remove(graph);
  expect_refused(folder, graph, "missing");
}

// Replaces field `column` of the first data row of a radarpr CSV (after the header); returns that
// row's 1-based file line.
std::size_t set_first_row_field(const fs::path& csv, std::size_t column, const std::string& value) {
  std::stringstream in(read_text(csv));
  std::string out, line;
  std::size_t number = 0, changed = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.starts_with('#') && !line.empty()) {
      if (header && changed == 0) {
        auto fields = split_csv_line(line);
        fields.at(column) = value;
        line.clear();
        for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + fields[i];
        changed = number;
      }
      header = true;
    }
    out += line + "\n";
  }
  std::ofstream(csv) << out;
  return changed;
}

TEST_F(ResultsErrorTest, FrameIndicesMustBeWholeAndWithinTheTrajectory) {
  const fs::path folder = fresh_copy("frames");
  const fs::path graph = folder / "town" / "referee" / "matching_graph.csv";
  const std::string original = read_text(graph);
  // query is column 0, match column 1; the town has 160 frames (trajectory.csv).
  std::size_t line = set_first_row_field(graph, 0, "-3");
  ASSERT_GT(line, 0u);
  expect_refused(folder, graph,
                 fmt::format("line {}: column 'query' holds '-3'; a whole number >= 0", line));
  std::ofstream(graph) << original;
  line = set_first_row_field(graph, 1, "2.5");
  expect_refused(folder, graph,
                 fmt::format("line {}: column 'match' holds '2.5'; a whole number >= 0", line));
  std::ofstream(graph) << original;
  line = set_first_row_field(graph, 0, "160");
  expect_refused(folder, graph,
                 fmt::format("line {}: column 'query' holds 160; beyond the 160 query frames of "
                             "trajectory.csv (< 160 expected)",
                             line));
  // A multi session's match counts database frames (100 here).
  const fs::path multi = folder / "town_2_sessions" / "referee" / "matching_graph.csv";
  std::ofstream(graph) << original;
  line = set_first_row_field(multi, 1, "100");
  expect_refused(
      folder, multi,
      fmt::format("line {}: column 'match' holds 100; beyond the 100 database frames", line));
}

TEST_F(ResultsErrorTest, LabelErrorsNameTheFileLine) {
  const fs::path folder = fresh_copy("label_line");
  const fs::path graph = folder / "town" / "referee" / "matching_graph.csv";
  const std::size_t line = set_first_row_field(graph, 2, "XX");
  expect_refused(folder, graph, fmt::format("line {}: label 'xx'", line));
}

TEST_F(ResultsErrorTest, FolderNamesLeavingTheResultsAreRefused) {
  for (const char* name : {"../town", "..", "a/b"}) {
    const fs::path folder = fresh_copy("escape");
    auto json = nlohmann::json::parse(read_text(folder / "summary.json"));
    json["rows"][0]["dataset"] = name;
    std::ofstream(folder / "summary.json") << json.dump();
    expect_refused(folder, folder / "summary.json",
                   fmt::format("rows[0].dataset gives the folder name '{}', which ", name));
  }
  const fs::path folder = fresh_copy("escape_descriptor");
  auto json = nlohmann::json::parse(read_text(folder / "summary.json"));
  // '/' in an id becomes '_' in its folder name (a path-valued parameter), so ".." is what is left
  // to try.
  json["rows"][1]["descriptor"] = "..";
  std::ofstream(folder / "summary.json") << json.dump();
  expect_refused(folder, folder / "summary.json", "rows[1].descriptor gives the folder name");
}

// A shape of [2^40, 1] used to wrap to "0x1" (and its payload to -1) in Table II.
TEST_F(ResultsErrorTest, ShapesAndSizesBeyondRangeAreRefused) {
  const fs::path folder = fresh_copy("shape");
  auto json = nlohmann::json::parse(read_text(folder / "summary.json"));
  const nlohmann::json original = json;
  json["rows"][0]["shape"] = {1099511627776LL, 1};
  std::ofstream(folder / "summary.json") << json.dump();
  expect_refused(folder, folder / "summary.json",
                 "rows[0].shape is [1099511627776,1]; [rows, cols] expected, each a whole number "
                 "in [1, 2147483647]");
  for (const nlohmann::json& shape :
       {nlohmann::json{0, 1}, nlohmann::json{-3, 1}, nlohmann::json{1, 18446744073709551615ULL}}) {
    json["rows"][0]["shape"] = shape;
    std::ofstream(folder / "summary.json") << json.dump();
    expect_refused(folder, folder / "summary.json", "rows[0].shape is " + shape.dump());
  }
  json = original;
  json["rows"][1]["payload_bytes"] = -1;
  std::ofstream(folder / "summary.json") << json.dump();
  expect_refused(folder, folder / "summary.json",
                 "rows[1].payload_bytes is -1; a whole number of bytes >= 0 expected");
}

TEST_F(ResultsErrorTest, MissingTrajectoryWithoutMatchesIsNamed) {
  const fs::path folder = fresh_copy("no_path");
  fs::remove(folder / "town" / "trajectory.csv");
  fs::remove(folder / "town" / "referee" / "matches.csv");
  expect_refused(folder, folder / "town" / "trajectory.csv", "missing");
}

TEST_F(ResultsErrorTest, CliPrintsTheFileAndExitsWithOne) {
  const fs::path folder = fresh_copy("cli");
  const fs::path curve = folder / "town" / "referee" / "curve.csv";
  fs::remove(curve);
  const auto result = testing::run_cli("report " + folder.string());
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("radarpr: error: " + curve.string() + ": missing"),
            std::string::npos)
      << result.output;
  const auto not_results = testing::run_cli("report " + (folder / "town").string());
  EXPECT_EQ(not_results.exit_code, 1);
  EXPECT_NE(not_results.output.find((folder / "town" / "summary.json").string()), std::string::npos)
      << not_results.output;
}

}  // namespace
}  // namespace radarpr
