// Strings from a config or a shared results folder must never run as code. Each test puts gnuplot
// command payloads (a newline then system(...), backquotes, string concatenation, a line
// continuation) into the texts a figure, table or page shows, runs the verb a user would run, and
// checks that no marker file was created and that the text is shown as written.
#include <gtest/gtest.h>

#include "evaluation/report/gnuplot_runner.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// Payloads that each create `marker_folder`/<n> if gnuplot (or a shell behind it) ran them.
std::vector<std::string> payloads(const fs::path& marker_folder) {
  const auto touch = [&](int n) { return (marker_folder / std::to_string(n)).string(); };
  return {
      fmt::format("a\nsystem('touch {}')\n#", touch(1)),
      fmt::format("b'\nsystem(\"touch {}\")\nprint '", touch(2)),
      fmt::format("c`touch {}`", touch(3)),
      fmt::format("d'.system('touch {}').'", touch(4)),
      fmt::format("e\\\nsystem('touch {}')", touch(5)),
      fmt::format("f\r\n! touch {}\n", touch(6)),
  };
}

std::vector<std::string> markers_created(const fs::path& marker_folder) {
  std::vector<std::string> created;
  for (const auto& entry : fs::directory_iterator(marker_folder)) {
    created.push_back(entry.path().filename().string());
  }
  return created;
}

std::string all_scripts(const fs::path& figures) {
  std::string text;
  for (const auto& entry : fs::directory_iterator(figures)) {
    if (entry.path().extension() == ".gp") text += testing::read_text(entry.path());
  }
  return text;
}

// The gnuplot scripts hold no line that starts with a payload's command.
void expect_no_command_line(const std::string& scripts) {
  for (const char* command : {"\nsystem", "\n! ", "\nprint"}) {
    EXPECT_EQ(scripts.find(command), std::string::npos) << command;
  }
}

class InjectionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!find_gnuplot()) GTEST_SKIP() << "gnuplot absent: no script is run, nothing to inject";
    root_ =
        testing::scratch_folder(std::string("injection_") +
                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
    markers_ = root_ / "markers";
    fs::create_directories(markers_);
  }
  void TearDown() override {
    if (!root_.empty()) fs::remove_all(root_);
  }
  fs::path root_, markers_;
};

TEST_F(InjectionTest, ConfigLabelsDuringRunRunNothing) {
  nlohmann::json config = testing::small_report_experiment("injection_run");
  config["datasets"].erase(1);  // one dataset is enough, and faster
  config["descriptors"] = nlohmann::json::array();
  const auto texts = payloads(markers_);
  // Two payloads per label: three descriptors carry all six.
  for (const char* name : {"referee", "referee_r", "referee_a"}) {
    const std::size_t i = config["descriptors"].size() * 2;
    config["descriptors"].push_back({{"name", name}, {"label", texts[i] + texts[i + 1]}});
  }
  std::ofstream(root_ / "config.json") << config.dump(2);
  const fs::path out = root_ / "out";
  const auto result = testing::run_cli(
      fmt::format("run {} --out {} --quiet", (root_ / "config.json").string(), out.string()));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(markers_created(markers_), std::vector<std::string>{});
  const std::string scripts = all_scripts(out / "figures");
  expect_no_command_line(scripts);
  // Shown as written (control characters as spaces), quotes doubled inside gnuplot's quotes.
  EXPECT_NE(scripts.find(fmt::format("d''.system(''touch {}'').''", (markers_ / "4").string())),
            std::string::npos);
  EXPECT_NE(scripts.find(fmt::format("c`touch {}`", (markers_ / "3").string())), std::string::npos);
}

// A shared results folder whose summary.json was edited: labels and the experiment name carry
// the payloads into `report`.
TEST_F(InjectionTest, ReportOnATamperedSummaryRunsNothing) {
  testing::write_small_results(root_ / "run");
  const fs::path run = root_ / "run";
  auto summary = nlohmann::json::parse(testing::read_text(run / "summary.json"));
  const auto texts = payloads(markers_);
  for (std::size_t i = 0; i < summary["rows"].size(); ++i) {
    summary["rows"][i]["label"] = texts[i % texts.size()];
  }
  summary["experiment"] = texts[0];
  std::ofstream(run / "summary.json") << summary.dump(2);
  const auto result = testing::run_cli("report " + run.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(markers_created(markers_), std::vector<std::string>{});
  expect_no_command_line(all_scripts(run / "figures"));

  // A descriptor id can carry a payload into a figure's file name: refused before any script.
  summary["rows"][0]["descriptor"] = texts[0];
  std::ofstream(run / "summary.json") << summary.dump(2);
  const auto refused = testing::run_cli("report " + run.string());
  EXPECT_NE(refused.exit_code, 0) << refused.output;
  EXPECT_NE(refused.output.find("rows[0].descriptor gives the folder name"), std::string::npos)
      << refused.output;
  EXPECT_EQ(markers_created(markers_), std::vector<std::string>{});
}

// `compare` puts each run's experiment name and labels in the keys of its overlaid curves.
TEST_F(InjectionTest, CompareOfTamperedRunsRunsNothing) {
  testing::write_small_results(root_ / "run");
  const auto texts = payloads(markers_);
  std::vector<fs::path> runs;
  for (int r = 0; r < 2; ++r) {
    runs.push_back(testing::copy_of_run(root_, fmt::format("run{}", r)));
    auto summary = nlohmann::json::parse(testing::read_text(runs.back() / "summary.json"));
    summary["experiment"] = texts[static_cast<std::size_t>(r)];
    for (std::size_t i = 0; i < summary["rows"].size(); ++i) {
      summary["rows"][i]["label"] = texts[(i + 2) % texts.size()];
    }
    std::ofstream(runs.back() / "summary.json") << summary.dump(2);
  }
  const fs::path out = root_ / "comparison";
  const auto result = testing::run_cli(
      fmt::format("compare {} {} --out {}", runs[0].string(), runs[1].string(), out.string()));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(markers_created(markers_), std::vector<std::string>{});
  expect_no_command_line(all_scripts(out / "figures"));
}

// Tables: LaTeX specials and Markdown cell breakers in labels stay text.
TEST_F(InjectionTest, TablesShowSpecialsAsText) {
  testing::write_small_results(root_ / "run");
  const fs::path run = root_ / "run";
  auto summary = nlohmann::json::parse(testing::read_text(run / "summary.json"));
  // rows: town/referee, town/referee_r, town_2_sessions/referee, town_2_sessions/referee_r.
  const std::string specials =
      "=HYPERLINK(\"http://x\") \\input{/etc/passwd}\\write18{touch x} 100% $a_b$ #1 ~ ^";
  const std::string breaker = "p|q\n| injected | row |\\";
  for (std::size_t i = 0; i < summary["rows"].size(); ++i) {
    summary["rows"][i]["label"] = i % 2 == 0 ? specials : breaker;
  }
  std::ofstream(run / "summary.json") << summary.dump(2);
  ASSERT_EQ(testing::run_cli("report " + run.string()).exit_code, 0);
  const std::string tex = testing::read_text(run / "table1.tex");
  EXPECT_NE(tex.find("\\textbackslash{}input\\{/etc/passwd\\}\\textbackslash{}write18\\{touch "
                     "x\\} 100\\% \\$a\\_b\\$ \\#1 \\textasciitilde{} \\textasciicircum{}"),
            std::string::npos)
      << tex;
  EXPECT_EQ(tex.find("\\input"), std::string::npos);
  EXPECT_EQ(tex.find("\\write18"), std::string::npos);
  // Markdown: the header rule, then one line per descriptor; nothing split a row.
  const std::string md = testing::read_text(run / "table1.md");
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), 4) << md;
  EXPECT_NE(md.find("p\\|q \\| injected \\| row \\|\\\\ |"), std::string::npos) << md;
  EXPECT_EQ(md.find("\n| injected"), std::string::npos) << md;
  const std::string csv = testing::read_text(run / "table1.csv");
  EXPECT_NE(csv.find("\"'=HYPERLINK(\"\"http://x\"\") "), std::string::npos) << csv;
}

// A config's dataset name naming a folder outside --out is refused before anything is written.
TEST(NameInjection, DatasetNameLeavingOutIsRefused) {
  const fs::path root = testing::scratch_folder("dataset_escape");
  for (const char* name : {"../escaped", "/tmp/escaped", "a/b", "..", ".hidden", "-rf",
                           "long_name_0123456789012345678901234567890123456789012345678901234567"
                           "8901234567890123456789012345678901234567890123456789"}) {
    nlohmann::json config = testing::small_report_experiment("escape");
    config["datasets"].erase(1);
    config["datasets"][0]["name"] = name;
    std::ofstream(root / "config.json") << config.dump(2);
    const auto result = testing::run_cli(fmt::format(
        "run {} --out {} --quiet", (root / "config.json").string(), (root / "out").string()));
    EXPECT_NE(result.exit_code, 0) << name;
    EXPECT_NE(result.output.find("datasets[0].name"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("ASCII letters, digits and _ - . = +"), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(root / "escaped"));
    EXPECT_FALSE(fs::exists(root / "out"));
  }
  nlohmann::json config = testing::small_report_experiment("escape");
  config["experiment"] = "../escaped";
  std::ofstream(root / "config.json") << config.dump(2);
  const auto result = testing::run_cli("run " + (root / "config.json").string() + " --quiet");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find("experiment"), std::string::npos) << result.output;
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
