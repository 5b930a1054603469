// Bad input, tried as a new user would: each gives one clear error naming the file or key and
// what was expected, before any work, and never a silently wrong number.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/cli/cli_runner.hpp"
#include "tests/scratch_directory.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using testing::run_cli;

// A path as radarpr stores it in JSON when it is not UTF-8: 0xff as \xff, a newline as \n.
std::string printable_path(const fs::path& path) {
  std::string shown;
  for (const char c : path.string()) {
    const auto byte = static_cast<unsigned char>(c);
    shown += byte == 0xff ? std::string("\\xff")
             : c == '\n'  ? std::string("\\n")
                          : std::string(1, c);
  }
  return shown;
}

class BadInputTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_test_directory("radarpr_bad_input"); }
  void TearDown() override { fs::remove_all(dir_); }

  // A tiny synthetic experiment, `edit`ed, written to config.json.
  fs::path config(const std::function<void(nlohmann::json&)>& edit) const {
    nlohmann::json config = nlohmann::json::parse(R"({
      "experiment": "bad_input",
      "datasets": [{"name": "town", "query": {"type": "synthetic", "seed": 5, "scans": 80,
                    "range_bins": 420, "range_resolution_m": 0.238, "route_blocks_x": 1}}],
      "descriptors": ["referee"],
      "protocol": {"exclude_recent_frames": 20}
    })");
    edit(config);
    const fs::path path = dir_ / "config.json";
    std::ofstream(path) << config.dump(2);
    return path;
  }

  // Runs `radarpr run` on `config_path` into dir_/out: refused, with every fragment in the output.
  void expect_refused(const fs::path& config_path, std::initializer_list<std::string> fragments) {
    const auto result = run_cli(
        fmt::format("run {} --out {} --quiet", config_path.string(), (dir_ / "out").string()));
    EXPECT_NE(result.exit_code, 0) << result.output;
    for (const auto& fragment : fragments) {
      EXPECT_NE(result.output.find(fragment), std::string::npos)
          << "missing '" << fragment << "' in: " << result.output;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "refused, yet results were written";
  }

  fs::path dir_;
};

// 1e10 s in nanoseconds overflows 64 bits: it used to become a negative gap limit that dropped
// half the poses, and the warning blamed the pose track.
TEST_F(BadInputTest, MaxPoseGapBeyondItsRangeIsRefused) {
  for (const double gap : {1e10, 9.3e9, 1e300}) {
    const auto path = config([&](nlohmann::json& c) {
      c["datasets"][0]["query"] = {{"type", "folder"},
                                   {"root", (dir_ / "data").string()},
                                   {"range_resolution_m", 0.0438},
                                   {"max_pose_gap_s", gap}};
    });
    expect_refused(path, {"datasets[0].query.max_pose_gap_s", "must be a number in (0, 1000000]"});
  }
}

// 2^64 - 1 used to be reported as "got -1".
TEST_F(BadInputTest, HugeExcludeRecentFramesIsShownAsWritten) {
  const auto path = config([](nlohmann::json&) {});
  // Edited as text, as a user would type it.
  std::string text;
  {
    std::ifstream file(path);
    std::stringstream buffer;
    buffer << file.rdbuf();
    text = buffer.str();
  }
  const std::string from = "\"exclude_recent_frames\": 20";
  text.replace(text.find(from), from.size(), "\"exclude_recent_frames\": 18446744073709551615");
  std::ofstream(path) << text;
  expect_refused(path, {"protocol.exclude_recent_frames", "18446744073709551615"});
  const auto result =
      run_cli(fmt::format("run {} --out {} --quiet", path.string(), (dir_ / "out").string()));
  EXPECT_EQ(result.output.find("-1"), std::string::npos) << result.output;
  // One beyond the accepted range, below 2^63: the range is named.
  text.replace(text.find("18446744073709551615"), 20, "5000000000");
  std::ofstream(path) << text;
  expect_refused(path,
                 {"protocol.exclude_recent_frames", "must be in [1, 1000000000], got 5000000000"});
}

// 1e999 does not fit a double: the error names the config file (it used to be nlohmann's bare
// "[json.exception.out_of_range.406]" text).
TEST_F(BadInputTest, JsonNumberBeyondADoubleNamesTheFile) {
  const auto path = config([](nlohmann::json&) {});
  std::ofstream(path) << R"({"experiment": "x", "protocol": {"revisit_radius_m": 1e999}})";
  expect_refused(path, {path.string() + ": a number is beyond the range of a double"});
}

// A folder dataset of `scans` range x azimuth PNGs driving back and forth along 20 m, so that it
// has revisits every 40 frames. `echoes`: noise and a wall whose width follows the position (so
// that descriptors differ between places); else blank.
void write_folder_dataset(const fs::path& root, int scans, bool echoes, int rows = 500,
                          int columns = 400) {
  fs::create_directories(root / "scans");
  std::string poses = "timestamp,x,y,yaw\n";
  cv::RNG random(7);
  for (int t = 0; t < scans; ++t) {
    const std::int64_t stamp_us = 1'700'000'000'000'000 + std::int64_t{t} * 250'000;
    cv::Mat scan = cv::Mat::zeros(rows, columns, CV_8UC1);
    const int x = t % 40 < 20 ? t % 40 : 40 - t % 40;
    if (echoes) {
      random.fill(scan, cv::RNG::UNIFORM, 0, 40);
      if (rows >= 12) {
        scan(cv::Range(rows / 3, rows / 3 + 6), cv::Range(0, std::min(columns, 8 + 9 * x))) = 255;
      }
    }
    cv::imwrite((root / "scans" / fmt::format("{}.png", stamp_us)).string(), scan);
    poses += fmt::format("{}.{:06d},{},0,0\n", stamp_us / 1'000'000, stamp_us % 1'000'000, x);
  }
  std::ofstream(root / "poses.csv") << poses;
}

// Folder names are bytes: one that is not UTF-8 used to stop the run after all the work
// (nlohmann's type_error.316 writing summary.json), and made extract refuse a valid scan.
TEST_F(BadInputTest, NonUtf8FolderNamesAreStoredReadably) {
  // Not UTF-8, and a newline: neither may break the JSON, nor a CSV's comment lines.
  const fs::path root = dir_ / "dr\xffve\nline";
  write_folder_dataset(root, 60, /*echoes=*/true);
  const auto path = config([&](nlohmann::json& c) {
    c["datasets"][0]["query"] = {
        {"type", "folder"}, {"root", "${BAD_INPUT_ROOT}"}, {"range_resolution_m", 0.1}};
    c["protocol"] = {{"exclude_recent_frames", 5}, {"revisit_radius_m", 3}};
  });
  const auto result =
      run_cli(fmt::format("run {} --out {} --quiet", path.string(), (dir_ / "out").string()),
              "BAD_INPUT_ROOT='" + root.string() + "'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream summary(dir_ / "out" / "summary.json");
  const auto json = nlohmann::json::parse(summary);
  EXPECT_EQ(json["rows"][0]["query_sequence"], "folder(dr\\xffve\\nline)");
  std::ifstream curve(dir_ / "out" / "town" / "referee" / "curve.csv");
  for (std::string row; std::getline(curve, row);) EXPECT_FALSE(row.starts_with("line")) << row;

  const fs::path scan = *fs::directory_iterator(root / "scans");
  const auto extracted =
      run_cli(fmt::format("extract referee '{}' --range-resolution 0.1", scan.string()));
  ASSERT_EQ(extracted.exit_code, 0) << extracted.output;
  const auto line = nlohmann::json::parse(extracted.output);
  EXPECT_EQ(line["file"], printable_path(scan));
  // A message names such a file readably too.
  const auto missing = run_cli(
      fmt::format("extract referee '{}' --range-resolution 0.1", (root / "missing.png").string()));
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.output.find("dr\\xffve"), std::string::npos) << missing.output;
}

// All-blank scans: every scan gets the same descriptor value, and the metrics came from
// tie-breaking alone (Recall@1 0.291). The run is refused, naming the descriptor and the cause.
TEST_F(BadInputTest, BlankScansAreRefusedNotScored) {
  write_folder_dataset(dir_ / "blank", 60, /*echoes=*/false);
  const auto path = config([&](nlohmann::json& c) {
    c["datasets"][0]["query"] = {
        {"type", "folder"}, {"root", (dir_ / "blank").string()}, {"range_resolution_m", 0.1}};
    c["protocol"] = {{"exclude_recent_frames", 5}, {"revisit_radius_m", 3}};
  });
  expect_refused(path, {"dataset 'town': descriptor 'referee' gives the same value for all 60 "
                        "scans",
                        "tie-breaking"});
}

// A 2-azimuth x 3-bin scan gave RaPlace a constant value with no warning: refused at open,
// naming the minimum.
TEST_F(BadInputTest, TinyScansAreRefusedNamingTheMinimum) {
  write_folder_dataset(dir_ / "tiny", 60, /*echoes=*/true, /*rows=*/3, /*columns=*/2);
  const auto path = config([&](nlohmann::json& c) {
    c["datasets"][0]["query"] = {
        {"type", "folder"}, {"root", (dir_ / "tiny").string()}, {"range_resolution_m", 0.1}};
    c["descriptors"] = {"raplace"};
  });
  expect_refused(path,
                 {"2 azimuths x 3 range bins", "needs at least 16 azimuths and 16 range bins"});
}

// ReFeree's min_range_bins beyond the scan gave an all-zero descriptor for every scan.
TEST_F(BadInputTest, MinimumRangeBeyondTheScanIsRefused) {
  write_folder_dataset(dir_ / "short", 60, /*echoes=*/true, /*rows=*/50, /*columns=*/40);
  const auto path = config([&](nlohmann::json& c) {
    c["datasets"][0]["query"] = {
        {"type", "folder"}, {"root", (dir_ / "short").string()}, {"range_resolution_m", 0.1}};
    c["descriptors"] = {"referee:min_range_bins=58"};
  });
  expect_refused(path, {"min_range_bins = 58 leaves no range bin of a scan with 50"});
}

// Open-RadVLAD's min_bin beyond the scan zeroed every bin: the same value for every scan, only
// found after training and extraction. Refused at the first scan it meets, naming the maximum.
TEST_F(BadInputTest, OpenRadVladMinBinBeyondTheScanIsRefused) {
  write_folder_dataset(dir_ / "short", 60, /*echoes=*/true, /*rows=*/50, /*columns=*/40);
  const auto path = config([&](nlohmann::json& c) {
    c["datasets"][0]["query"] = {
        {"type", "folder"}, {"root", (dir_ / "short").string()}, {"range_resolution_m", 0.1}};
    c["descriptors"] = {"open_radvlad:min_bin=70"};
    c["protocol"] = {{"exclude_recent_frames", 5}, {"revisit_radius_m", 3}};
  });
  expect_refused(
      path, {"open_radvlad: min_bin = 70 zeroes every range bin of a scan with 50", "at most 49"});
}

// A damaged scan (one flipped byte in its image data): the message is radarpr's, naming the
// file, with no library line before it (libpng used to print "Read Error" or "CRC error" first).
TEST_F(BadInputTest, ADamagedPngIsNamedWithoutLibraryChatter) {
  write_folder_dataset(dir_ / "damaged", 1, /*echoes=*/true);
  const fs::path scan = *fs::directory_iterator(dir_ / "damaged" / "scans");
  std::string bytes;
  {
    std::ifstream file(scan, std::ios::binary);
    std::stringstream buffer;
    buffer << file.rdbuf();
    bytes = buffer.str();
  }
  const std::size_t data = bytes.find("IDAT") + 4 + 100;
  bytes[data] = static_cast<char>(bytes[data] ^ 0x5a);
  std::ofstream(scan, std::ios::binary) << bytes;
  const auto result =
      run_cli(fmt::format("extract referee {} --range-resolution 0.1", scan.string()));
  EXPECT_NE(result.exit_code, 0);
  EXPECT_EQ(result.output.rfind("radarpr: error: " + scan.string() + ": corrupt PNG", 0), 0u)
      << result.output;
  EXPECT_NE(result.output.find("fails its CRC check"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("libpng"), std::string::npos) << result.output;
  // Cut short (the file still being copied): the same.
  std::ofstream(scan, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const auto cut = run_cli(fmt::format("extract referee {} --range-resolution 0.1", scan.string()));
  EXPECT_EQ(cut.output.rfind("radarpr: error: " + scan.string(), 0), 0u) << cut.output;
  EXPECT_EQ(cut.output.find("libpng"), std::string::npos) << cut.output;
}

// --cache-dir inside --out: the run used to do all the work, then refuse its results.
TEST_F(BadInputTest, CacheInsideOutIsRefusedBeforeAnyWork) {
  const auto path = config([](nlohmann::json&) {});
  const auto result = run_cli(fmt::format("run {} --out {} --cache-dir {} --quiet", path.string(),
                                          (dir_ / "out").string(), (dir_ / "out/cache").string()));
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find("is inside the results folder"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("dataset town"), std::string::npos) << "work was done first";
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// `run` replaces only what it writes: a user's edited figure script (which the README says is
// kept) and their own notes stay; the files of a descriptor dropped from the config go.
TEST_F(BadInputTest, RunNeverDeletesFilesItDidNotWrite) {
  const fs::path out = dir_ / "out";
  const auto both = config([](nlohmann::json& c) { c["descriptors"].push_back("referee_a"); });
  const auto first =
      run_cli(fmt::format("run {} --out {} --quiet --no-cache", both.string(), out.string()),
              "RADARPR_GNUPLOT=off");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  ASSERT_TRUE(fs::exists(out / "town" / "referee_a" / "curve.csv"));
  std::ofstream(out / "figures" / "pr_town_paper.gp") << "# my edited copy\n";
  std::ofstream(out / "notes.txt") << "mine\n";
  const auto one = config([](nlohmann::json&) {});
  const auto second =
      run_cli(fmt::format("run {} --out {} --quiet --no-cache", one.string(), out.string()),
              "RADARPR_GNUPLOT=off");
  ASSERT_EQ(second.exit_code, 0) << second.output;
  EXPECT_TRUE(fs::exists(out / "figures" / "pr_town_paper.gp"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  EXPECT_TRUE(fs::exists(out / "town" / "referee" / "curve.csv"));
  EXPECT_FALSE(fs::exists(out / "town" / "referee_a")) << "the dropped descriptor's files stay";
}

// A run killed while writing leaves <out>.partial.<pid>: the next run removes those of dead
// processes (they used to stay for good).
TEST_F(BadInputTest, StalePartialFoldersOfDeadProcessesAreRemoved) {
  const fs::path stale = dir_ / "out.partial.999999999";  // beyond any pid: a dead process
  fs::create_directories(stale / "town");
  std::ofstream(stale / "summary.json") << "{";
  const fs::path live = dir_ / fmt::format("out.partial.{}", ::getpid());  // this test: alive
  fs::create_directories(live);
  const auto path = config([](nlohmann::json&) {});
  const auto result = run_cli(
      fmt::format("run {} --out {} --quiet --no-cache", path.string(), (dir_ / "out").string()),
      "RADARPR_GNUPLOT=off");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
}

}  // namespace
}  // namespace radarpr
