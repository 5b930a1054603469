// Runs the radarpr program itself: exit codes, one-line errors, and output equal to the library's.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "datasets/synthetic/synthetic_sequence.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/opencv_image.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/scratch_directory.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using testing::CommandResult;
using testing::run_cli;

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_test_directory("radarpr_cli_test"); }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write_config(const std::string& text) const {
    const fs::path path = dir_ / "config.json";
    std::ofstream(path) << text;
    return path;
  }

  fs::path dir_;
};

constexpr const char* kTinyConfig = R"({
  "experiment": "cli_test",
  "datasets": [{"name": "town", "query": {"type": "synthetic", "seed": 5, "scans": 80,
                "range_bins": 420, "range_resolution_m": 0.238, "route_blocks_x": 1}}],
  "descriptors": ["referee_r:kernel=box,z_q=3"],
  "protocol": {"exclude_recent_frames": 20}
})";

TEST_F(CliTest, VersionHelpAndList) {
  EXPECT_EQ(run_cli("--version").exit_code, 0);
  const auto help = run_cli("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("radarpr run CONFIG"), std::string::npos);
  for (const char* command : {"run --help", "list --help", "extract --help"}) {
    EXPECT_EQ(run_cli(command).exit_code, 0) << command;
  }
  const auto list = run_cli("list --json");
  ASSERT_EQ(list.exit_code, 0);
  const auto document = nlohmann::json::parse(list.output);
  std::vector<std::string> names;
  for (const auto& entry : document) names.push_back(entry["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"open_radvlad", "precomputed", "radar_scan_context",
                                             "raplace", "referee", "referee_a", "referee_r"}));
  // Every entry carries its size facts (descriptors.md section 7).
  for (const auto& entry : document) {
    EXPECT_EQ(entry["element_type"], "float32") << entry["name"];
    ASSERT_EQ(entry["sizes"].size(), 2u) << entry["name"];
  }
  const auto ds =
      run_cli("list --json radar_scan_context:rings=5,sectors=10 open_radvlad:bin_dim=10");
  ASSERT_EQ(ds.exit_code, 0) << ds.output;
  const auto ds_document = nlohmann::json::parse(ds.output);
  EXPECT_EQ(ds_document[0]["sizes"][0]["shape"], nlohmann::json::parse("[5, 10]"));
  EXPECT_EQ(ds_document[0]["sizes"][0]["paper_bytes"], 528);
  EXPECT_EQ(ds_document[1]["sizes"][0]["shape"], nlohmann::json::parse("[640, 1]"));
  EXPECT_EQ(ds_document[1]["trainable"], true);
}

TEST_F(CliTest, UsageErrorsExitWithTwo) {
  EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
  EXPECT_EQ(run_cli("run").exit_code, 2);
  EXPECT_EQ(run_cli("run a.json --bogus").exit_code, 2);
  EXPECT_EQ(run_cli("extract referee").exit_code, 2);
}

// A typo in the file names the file; the same typo in a --set names the --set (and is a command
// line radarpr cannot use: exit code 2).
TEST_F(CliTest, ConfigTypoGivesOneLineNamingFileAndKey) {
  std::string text = kTinyConfig;
  text.replace(text.find("\"protocol\": {"), 13, "\"protocol\": {\"lables\": \"standard\", ");
  const fs::path config = write_config(text);
  const auto typo = run_cli("run " + config.string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(typo.exit_code, 1);
  EXPECT_EQ(std::count(typo.output.begin(), typo.output.end(), '\n'), 1) << typo.output;
  EXPECT_NE(typo.output.find(config.string() + ": protocol.lables: unknown key"), std::string::npos)
      << typo.output;

  const fs::path clean = write_config(kTinyConfig);
  const auto set_typo = run_cli("run " + clean.string() + " --set protocol.lables=standard --out " +
                                (dir_ / "out").string());
  EXPECT_EQ(set_typo.exit_code, 2);
  EXPECT_EQ(std::count(set_typo.output.begin(), set_typo.output.end(), '\n'), 1) << set_typo.output;
  EXPECT_NE(set_typo.output.find(
                "radarpr run: --set protocol.lables=standard: protocol.lables: unknown key"),
            std::string::npos)
      << set_typo.output;
  EXPECT_EQ(set_typo.output.find(clean.string()), std::string::npos) << set_typo.output;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(CliTest, RunWritesResultsAndAFailedRunKeepsTheOldOnes) {
  const fs::path config = write_config(kTinyConfig);
  const fs::path out = dir_ / "out";
  const auto ok = run_cli("run " + config.string() + " --quiet --out " + out.string());
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("| referee_r:kernel=box,z_q=3 | 5x1 |"), std::string::npos) << ok.output;
  ASSERT_TRUE(fs::exists(out / "summary.json"));
  const auto before = fs::last_write_time(out / "summary.json");

  // 40 azimuths cannot be split into referee's 50 blocks: extraction fails mid-run.
  const auto failed = run_cli("run " + config.string() +
                              " --quiet --set datasets.0.query.azimuths=40 --set "
                              "descriptors.0=referee --out " +
                              out.string());
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_NE(failed.output.find("scan 0"), std::string::npos) << failed.output;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_EQ(fs::last_write_time(out / "summary.json"), before);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 2u);  // config.json and out/: nothing half-written beside them
}

// `extract` decodes a native-layout PNG and prints what the library computes for the same pixels.
TEST_F(CliTest, ExtractPrintsTheLibrarysValues) {
  SyntheticConfig synthetic;
  synthetic.scan_count = 1;
  synthetic.radar.range_bin_count = 3360;  // MulRan's width: the resolution is then known
  const PolarImage image = SyntheticSequence(synthetic).load_image(0);
  const ByteImage native = transposed(image.power);  // MulRan's own layout: range x azimuth
  const fs::path png = dir_ / "scan.png";
  ASSERT_TRUE(cv::imwrite(png.string(), opencv_view(native)));

  const std::string id = "referee_r:kernel=box,z_q=3";
  const auto result = run_cli("extract " + id + " " + png.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto line = nlohmann::json::parse(result.output);
  EXPECT_EQ(line["layout"], "mulran_native");
  EXPECT_EQ(line["id"], id);
  EXPECT_EQ(line["shape"], nlohmann::json::array({42, 1}));
  const auto expected = DescriptorRegistry::global().create_from_id(id).descriptor->extract(image);
  EXPECT_EQ(line["values"].get<std::vector<float>>(), expected.values);
}

TEST_F(CliTest, ExtractOnACorruptPngNamesTheFile) {
  const fs::path png = dir_ / "corrupt.png";
  std::ofstream(png, std::ios::binary) << "\x89PNG\r\n\x1a\n-not-really-a-png";
  const auto result = run_cli("extract referee " + png.string());
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("radarpr: error: " + png.string()), std::string::npos)
      << result.output;
}

// Scans of an earlier, longer simulation would join the new sequence through the folder loader.
TEST_F(CliTest, SimulateRefusesAFolderHoldingOtherScans) {
  auto config_for = [&](int scans) {
    return write_config(fmt::format(
        R"({{"experiment": "sim", "datasets": [{{"name": "drive", "query": {{"type": "synthetic",
        "radar": "tiny", "seed": 5, "scans": {}}}}}], "descriptors": ["referee"], "protocol": {{}}}})",
        scans));
  };
  const fs::path out = dir_ / "out";
  const std::string six = config_for(6).string();
  ASSERT_EQ(
      run_cli(fmt::format("simulate \"{}\" --out \"{}\" --quiet", six, out.string())).exit_code, 0);
  // The same sequence again overwrites its own files.
  EXPECT_EQ(
      run_cli(fmt::format("simulate \"{}\" --out \"{}\" --quiet", six, out.string())).exit_code, 0);
  const std::string four = config_for(4).string();
  const auto refused =
      run_cli(fmt::format("simulate \"{}\" --out \"{}\" --quiet", four, out.string()));
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.output.find("not a scan of this sequence"), std::string::npos)
      << refused.output;
  std::size_t pngs = 0;
  for (const auto& entry : fs::directory_iterator(out / "drive" / "query" / "scans")) {
    pngs += entry.path().extension() == ".png" ? 1 : 0;
  }
  EXPECT_EQ(pngs, 6u);  // nothing written, nothing removed
}

}  // namespace
}  // namespace radarpr
