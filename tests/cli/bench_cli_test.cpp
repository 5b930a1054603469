// `radarpr bench` end to end on the cheapest benchmarks.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.hpp"

namespace radarpr {
namespace {

using testing::run_cli;

TEST(BenchCli, HelpAndBadArguments) {
  const auto help = run_cli("bench --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("usage: radarpr bench"), std::string::npos);
  EXPECT_EQ(run_cli("bench --no-such-option").exit_code, 2);
  EXPECT_EQ(run_cli("bench --repetitions zero").exit_code, 2);
  EXPECT_EQ(run_cli("bench --sizes 1000,,10").exit_code, 2);
  const auto bad_regex = run_cli("bench --filter '('");
  EXPECT_NE(bad_regex.exit_code, 0);
  EXPECT_NE(bad_regex.output.find("not a valid regular expression"), std::string::npos)
      << bad_regex.output;
}

TEST(BenchCli, WritesTheReportOfTheSelectedBenchmarks) {
  const std::filesystem::path out =
      std::filesystem::path(::testing::TempDir()) / "radarpr_bench_cli_test";
  std::filesystem::remove_all(out);
  // The plain passes only, on synthetic scans (no data folder): about a second.
  const auto result =
      run_cli("bench --quick --force --filter '^floor/' --data /nonexistent --threads 1 --out " +
              out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream json_file(out / "bench.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  ASSERT_EQ(json["results"].size(), 2u);
  EXPECT_EQ(json["results"][0]["name"], "floor/400x3360");
  EXPECT_EQ(json["results"][1]["name"], "floor/400x3768");
  EXPECT_GT(json["results"][0]["cpu_seconds"].get<double>(), 0.0);
  EXPECT_EQ(json["scans"][0]["real"], false);
  EXPECT_EQ(json["settings"]["quick"], true);
  EXPECT_EQ(json["settings"]["threads"], 1);  // --threads, recorded with the timings
  EXPECT_TRUE(std::filesystem::exists(out / "bench.md"));
  std::filesystem::remove_all(out);
}

// The whole-process rows start this very radarpr: `--version`, then `extract referee` on the
// synthetic 400 x 3360 scan's PNG, against its decode and extraction in the running process; and
// the minimal program built beside it, as their floor.
TEST(BenchCli, TimesWholeProcessesOfThisRadarpr) {
  const std::filesystem::path out =
      std::filesystem::path(::testing::TempDir()) / "radarpr_bench_startup_test";
  std::filesystem::remove_all(out);
  const auto result = run_cli(
      "bench --quick --force --filter 'startup/|^png_decode/400x3360|^extract/referee/400x3360' "
      "--data /nonexistent --threads 1 --out " +
      out.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream json_file(out / "bench.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  ASSERT_EQ(json["startup"].size(), 4u) << json.dump(2);
  EXPECT_EQ(json["startup"][0]["command"], "radarpr --version");
  // The floor, built beside the program: the minimal program idle, then decoding the same PNG.
  EXPECT_EQ(json["startup"][1]["command"], "radarpr_png_decode_floor");
  EXPECT_EQ(json["startup"][2]["command"], "radarpr_png_decode_floor 400x3360.png");
  EXPECT_TRUE(json["startup"][2]["floor"].get<bool>());
  EXPECT_GT(json["startup"][2]["over_in_process"].get<double>(), 0.0);
  EXPECT_EQ(json["startup"][3]["command"], "radarpr extract referee 400x3360.png");
  EXPECT_FALSE(json["startup"][3]["floor"].get<bool>());
  for (const nlohmann::json& row : json["startup"]) {
    EXPECT_GT(row["wall_seconds"].get<double>(), 0.0) << row.dump();
    EXPECT_GT(row["process_cpu_seconds"].get<double>(), 0.0) << row.dump();
  }
  EXPECT_GT(json["startup"][3]["over_in_process"].get<double>(), 0.0);
  for (const nlohmann::json& entry : json["results"]) {
    EXPECT_FALSE(entry.contains("error")) << entry.dump();
  }
  std::ifstream markdown(out / "bench.md");
  const std::string md((std::istreambuf_iterator<char>(markdown)), {});
  EXPECT_NE(md.find("## Start-up: one whole radarpr process"), std::string::npos) << md;
  std::filesystem::remove_all(out);
}

TEST(BenchCli, RefusesAFilterThatMatchesNothing) {
  const auto result = run_cli(
      "bench --quick --force --filter '^nothing-matches$' --data /nonexistent "
      "--out " +
      (std::filesystem::path(::testing::TempDir()) / "radarpr_bench_none").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("no benchmark matches"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace radarpr
