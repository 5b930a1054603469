// How the program reads its command line: guesses for a mistyped verb, option or choice; numbers
// as whole, finite tokens in range; --set errors that blame the --set; a folder given as CONFIG;
// --layout for images whose shape cannot tell it; --threads, which changes no result file.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "datasets/synthetic/scan_export.hpp"
#include "datasets/synthetic/synthetic_sequence.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/scratch_directory.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using testing::CommandResult;
using testing::run_cli;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

class CommandLine : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_test_directory("radarpr_command_line"); }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string config() const { return write("config.json", kConfig); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  static constexpr const char* kConfig = R"({
    "experiment": "command_line",
    "datasets": [{"name": "town", "query": {"type": "synthetic", "seed": 5, "scans": 80,
                  "range_bins": 420, "range_resolution_m": 0.238, "route_blocks_x": 1}}],
    "descriptors": ["referee_r:kernel=box,z_q=3"],
    "protocol": {"exclude_recent_frames": 20}
  })";

  fs::path dir_;
};

// One line on stderr, exit code 2, naming the verb and pointing at its help.
void expect_usage_error(const CommandResult& result, const std::string& message,
                        const std::string& verb) {
  const std::string where = verb.empty() ? "radarpr" : "radarpr " + verb;
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_EQ(result.output, fmt::format("{}: {} (see {} --help)\n", where, message, where));
}

TEST_F(CommandLine, AMistypedVerbOptionOrChoiceGetsAGuess) {
  expect_usage_error(run_cli("rn"), "unknown verb 'rn'; did you mean 'run'?", "");
  expect_usage_error(run_cli("reprot x"), "unknown verb 'reprot'; did you mean 'report'?", "");
  expect_usage_error(run_cli("help simulat"), "unknown verb 'simulat'; did you mean 'simulate'?",
                     "");
  expect_usage_error(run_cli("frobnicate"), "unknown verb 'frobnicate'", "");
  expect_usage_error(run_cli("--verison"), "unknown option '--verison'; did you mean '--version'?",
                     "");
  expect_usage_error(run_cli("run " + config() + " --ot x"),
                     "unknown option '--ot'; did you mean '--out'?", "run");
  expect_usage_error(run_cli("run " + config() + " --treads=2"),
                     "unknown option '--treads'; did you mean '--threads'?", "run");
  expect_usage_error(run_cli("list --jsn"), "unknown option '--jsn'; did you mean '--json'?",
                     "list");
  expect_usage_error(run_cli("extract referee a.png --layout oxfrod"),
                     "--layout: 'oxfrod' is not one of auto, oxford, mulran_native; did you mean "
                     "'oxford'?",
                     "extract");
  // The unknown option is the mistake to show, not the CONFIG it pushed out.
  expect_usage_error(run_cli("run --bogus"), "unknown option '--bogus'", "run");
  expect_usage_error(run_cli("run " + config() + " extra"), "unexpected argument 'extra'", "run");
}

TEST_F(CommandLine, NumbersAreWholeFiniteTokensInRange) {
  for (const std::string value : {"inf", "nan", "-inf", "1e999", "0.2abc", "0x1p-4", "''"}) {
    const auto result = run_cli("extract referee a.png --range-resolution " + value);
    EXPECT_EQ(result.exit_code, 2) << value << ": " << result.output;
    EXPECT_CONTAINS(result.output, "is not a finite number");
  }
  for (const std::string value : {"0", "-0.05"}) {
    expect_usage_error(
        run_cli("extract referee a.png --range-resolution " + value),
        fmt::format("--range-resolution: '{}' is out of range, expected a value > 0", value),
        "extract");
  }
  const std::string bench_guard = " --quick --force --filter '^none$' --out " + path("bench");
  const std::vector<std::string> verbs = {"run " + config(),
                                          "simulate " + config() + " --out x",
                                          "extract referee a.png",
                                          "report x",
                                          "compare x",
                                          "bench" + bench_guard};
  for (const std::string& verb : verbs) {
    for (const std::string value : {"0x10", "2000", "-1", "1.5", "two", "1e2"}) {
      const auto result = run_cli(verb + " --threads " + value);
      EXPECT_EQ(result.exit_code, 2) << verb << " --threads " << value << ": " << result.output;
      EXPECT_CONTAINS(result.output, "--threads: '" + value + "' is");
    }
  }
  expect_usage_error(run_cli("bench --repetitions 0" + bench_guard),
                     "--repetitions: '0' is out of range, expected a value in 1..1000", "bench");
  for (const std::string sizes : {"1000,,10", "1000,", ",1", "10,x", "1e3"}) {
    const auto result = run_cli("bench --sizes " + sizes + bench_guard);
    EXPECT_EQ(result.exit_code, 2) << sizes << ": " << result.output;
    EXPECT_CONTAINS(result.output, "--sizes: '");
  }
  EXPECT_FALSE(fs::exists(path("bench")));  // refused before any work
}

TEST_F(CommandLine, SetErrorsBlameTheSet) {
  const std::string file = config();
  const std::string out = " --out " + path("out");
  expect_usage_error(run_cli("run " + file + " --set protocol.revisit_radius_m=-5" + out),
                     "--set protocol.revisit_radius_m=-5: protocol.revisit_radius_m: must be > 0, "
                     "got -5",
                     "run");
  const auto typo = run_cli("run " + file + " --set protocol.lables=standard" + out);
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_CONTAINS(typo.output,
                  "radarpr run: --set protocol.lables=standard: protocol.lables: unknown key");
  expect_usage_error(run_cli("run " + file + " --set datasets.3.query.scans=5" + out),
                     "--set datasets.3.query.scans=5: datasets.3: no element '3' in an array of 1",
                     "run");
  expect_usage_error(run_cli("run " + file + " --set scans" + out),
                     "--set scans: expected KEY.PATH=VALUE", "run");
  // A value inside the replaced object is the --set's too.
  const auto inside = run_cli(
      "run " + file + " --set 'datasets.0.query={\"type\": \"synthetic\", \"sceans\": 3}'" + out);
  EXPECT_EQ(inside.exit_code, 2) << inside.output;
  EXPECT_CONTAINS(inside.output, "radarpr run: --set datasets.0.query=");
  EXPECT_CONTAINS(inside.output, "datasets[0].query.sceans: unknown key");
  for (const std::string verb : {"inspect", "simulate"}) {
    const auto result = run_cli(verb + " " + file + " --set protocol.revisit_radius_m=0" +
                                (verb == "simulate" ? out : ""));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_CONTAINS(result.output, "radarpr " + verb + ": --set protocol.revisit_radius_m=0: ");
  }
  // A mistake in the file still names the file.
  std::string broken = kConfig;
  broken.replace(broken.find("\"exclude_recent_frames\""), 23, "\"exclude_recent_frame\"");
  const auto in_file =
      run_cli("run " + write("broken.json", broken) + " --set protocol.revisit_radius_m=5" + out);
  EXPECT_EQ(in_file.exit_code, 1);
  EXPECT_EQ(in_file.output.rfind(fmt::format("radarpr: error: {}: protocol.exclude_recent_frame: "
                                             "unknown key",
                                             path("broken.json")),
                                 0),
            0u)
      << in_file.output;
  EXPECT_EQ(std::count(in_file.output.begin(), in_file.output.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(CommandLine, AFolderGivenAsConfigIsNamed) {
  for (const std::string verb : {"run", "inspect", "simulate"}) {
    const auto result =
        run_cli(verb + " " + dir_.string() + (verb == "inspect" ? "" : " --out " + path("out")));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_EQ(result.output,
              fmt::format("radarpr: error: {}: is a folder, expected a JSON config file (see "
                          "configs/)\n",
                          dir_.string()));
  }
}

// A polar PNG as wide as high is either layout: --layout says which.
TEST_F(CommandLine, ExtractTakesTheLayoutOfASquareImage) {
  SyntheticConfig synthetic;
  synthetic.scan_count = 1;
  synthetic.radar.azimuth_count = 400;
  synthetic.radar.range_bin_count = 500;
  PolarImage image = SyntheticSequence(synthetic).load_image(0);
  image.power = image.power.column_range(0, 389);  // + 11 metadata columns: 400 x 400
  const std::string oxford = path("oxford.png");
  synthetic::write_oxford_png(oxford, image);
  ASSERT_EQ(cv::imread(oxford, cv::IMREAD_UNCHANGED).cols, 400);

  const auto guessed = run_cli("extract referee_r " + oxford + " --range-resolution 0.2");
  EXPECT_EQ(guessed.exit_code, 1);
  EXPECT_CONTAINS(guessed.output, oxford + ": cannot tell the polar layout of a square 400x400");
  EXPECT_CONTAINS(guessed.output, "radarpr extract --layout oxford|mulran_native");
  EXPECT_EQ(guessed.output.find("PolarPngOptions"), std::string::npos);

  const auto named =
      run_cli("extract referee_r " + oxford + " --range-resolution 0.2 --layout oxford");
  ASSERT_EQ(named.exit_code, 0) << named.output;
  const auto line = nlohmann::json::parse(named.output);
  EXPECT_EQ(line["layout"], "oxford");
  EXPECT_EQ(line["azimuths"], 400);
  EXPECT_EQ(line["range_bins"], 389);

  cv::Mat native(400, 400, CV_8UC1, cv::Scalar(7));  // 400 range rows x 400 azimuths
  const std::string square = path("native.png");
  ASSERT_TRUE(cv::imwrite(square, native));
  const auto as_native =
      run_cli("extract referee_r " + square + " --range-resolution 0.2 --layout mulran_native");
  ASSERT_EQ(as_native.exit_code, 0) << as_native.output;
  EXPECT_EQ(nlohmann::json::parse(as_native.output)["layout"], "mulran_native");

  // A named layout still refuses an image of the other orientation.
  cv::Mat tall(500, 400, CV_8UC1, cv::Scalar(7));
  ASSERT_TRUE(cv::imwrite(path("tall.png"), tall));
  const auto refused =
      run_cli("extract referee_r " + path("tall.png") + " --range-resolution 0.2 --layout oxford");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_CONTAINS(refused.output, "400 wide x 500 high, expected the Oxford layout");
}

// Files are extracted in parallel and printed in their order; an error comes after the lines of
// the files before it, and nothing after.
TEST_F(CommandLine, ExtractPrintsInFileOrderWhateverTheThreads) {
  std::vector<std::string> files;
  for (int bins : {3360, 3768, 3360, 3768, 3360}) {
    SyntheticConfig synthetic;
    synthetic.scan_count = 1;
    synthetic.seed = static_cast<std::uint64_t>(files.size() + 1);
    synthetic.radar.range_bin_count = bins;
    const std::string file = path(fmt::format("scan{}.png", files.size()));
    synthetic::write_oxford_png(file, SyntheticSequence(synthetic).load_image(0));
    files.push_back(file);
  }
  std::string list;
  for (const auto& file : files) list += " " + file;
  const auto one = run_cli("extract referee_r" + list + " --threads 1");
  const auto two = run_cli("extract referee_r" + list + " --threads 2");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_EQ(two.output, one.output);
  std::istringstream lines(two.output);
  std::string line;
  for (const auto& file : files) {
    ASSERT_TRUE(std::getline(lines, line));
    EXPECT_EQ(nlohmann::json::parse(line)["file"], file);
  }

  std::ofstream(path("corrupt.png"), std::ios::binary) << "\x89PNG\r\n\x1a\n-not-really-a-png";
  const auto failed = run_cli(fmt::format("extract referee_r {} {} {} --threads 2", files[0],
                                          path("corrupt.png"), files[1]));
  EXPECT_EQ(failed.exit_code, 1);
  // What libpng says on stderr aside, the first file's line, then the error, then nothing.
  std::vector<std::string> said;
  std::istringstream failed_lines(failed.output);
  while (std::getline(failed_lines, line)) {
    if (line.starts_with("{") || line.starts_with("radarpr:")) said.push_back(line);
  }
  ASSERT_EQ(said.size(), 2u) << failed.output;
  EXPECT_EQ(nlohmann::json::parse(said[0])["file"], files[0]);
  EXPECT_CONTAINS(said[1], "radarpr: error: " + path("corrupt.png"));
}

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// Every file of a results folder but timing.json (run time, machine, extraction times), by its
// path relative to `folder`.
std::map<std::string, std::string> results_files(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().filename() == "timing.json") continue;
    files[fs::relative(entry.path(), folder).string()] = read_file(entry.path());
  }
  return files;
}

// Every result is written by index, and no measured time reaches a results file but
// timing.json: one thread or several, and run after run, the same bytes in every other file
// (summary.csv used to differ in its extraction-time column, index.html in its run time and
// machine). Values are extracted each time (--no-cache), a trainable descriptor included.
TEST_F(CommandLine, TheThreadCountChangesNoResult) {
  const std::string file = write("config.json", R"({
    "experiment": "threads",
    "datasets": [
      {"name": "town", "query": {"type": "synthetic", "seed": 5, "scans": 80, "range_bins": 420,
                                 "range_resolution_m": 0.238, "route_blocks_x": 1}},
      {"name": "two_sessions",
       "query": {"type": "synthetic", "seed": 5, "session": 1, "scans": 60, "range_bins": 420,
                 "range_resolution_m": 0.238, "route_blocks_x": 1, "route_origin_block_x": 1},
       "database": {"type": "synthetic", "seed": 5, "scans": 80, "range_bins": 420,
                    "range_resolution_m": 0.238, "route_blocks_x": 1}}
    ],
    "descriptors": ["referee_r:kernel=box,z_q=3", "open_radvlad:bin_dim=10", "radar_scan_context"],
    "protocol": {"exclude_recent_frames": 20}
  })");
  for (const char* run : {"1", "2", "4", "1_again"}) {
    const std::string threads = std::string(run).substr(0, 1);
    const auto result = run_cli(fmt::format("run {} --quiet --no-cache --threads {} --out {}", file,
                                            threads, path(std::string("run") + run)));
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
  const auto reference = results_files(path("run1"));
  EXPECT_GT(reference.size(), 20u);
  EXPECT_TRUE(reference.contains("summary.csv"));
  EXPECT_TRUE(reference.contains("index.html"));
  EXPECT_TRUE(reference.contains("two_sessions/open_radvlad__bin_dim=10/matches.csv"));
  EXPECT_TRUE(fs::exists(fs::path(path("run1")) / "timing.json"));
  for (const char* run : {"2", "4", "1_again"}) {
    const auto files = results_files(path(std::string("run") + run));
    for (const auto& [name, bytes] : reference) {
      ASSERT_TRUE(files.contains(name)) << name << " missing from run" << run;
      EXPECT_TRUE(files.at(name) == bytes) << name << " differs in run" << run;
    }
    EXPECT_EQ(files.size(), reference.size()) << "run" << run;
  }
}

}  // namespace
}  // namespace radarpr
