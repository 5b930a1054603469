// `radarpr inspect` and the checks `radarpr run` makes before any work, on temporary dataset
// trees filled with the real samples: reports, revisit counts, refusals, and broken inputs that
// never produce a results file.
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::real_data;
using test::TempTree;
namespace fs = std::filesystem;

constexpr const char* kOxford = "oxford_radar_robotcar_tiny_radarslampy";
constexpr const char* kRadiate = "radiate_tiny_foggy";

using testing::CommandResult;
using testing::run_cli;

bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

// An Oxford run folder "run/" from the tiny sample (11 scans, gps.csv, odometry).
void make_oxford_run(const TempTree& tree, const std::string& run = "run") {
  const fs::path sample = real_data(kOxford);
  for (const auto& entry : fs::directory_iterator(sample / "radar")) {
    tree.copy(entry.path(), run + "/radar/" + entry.path().filename().string());
  }
  tree.copy(sample / "gps" / "gps.csv", run + "/gps/gps.csv");
  tree.copy(sample / "gt" / "radar_odometry.csv", run + "/gt/radar_odometry.csv");
}

// A single-session config on the Oxford run, excluding the 5 most recent frames.
std::string oxford_config(const std::string& root, const std::string& extra = "") {
  return fmt::format(R"({{
    "experiment": "inspect_test",
    "datasets": [{{"name": "oxford_tiny", "query": {{"type": "oxford", "root": "{}",
                   "sequence": "run"{}}}}}],
    "descriptors": ["referee"],
    "protocol": {{"exclude_recent_frames": 5}}
  }})",
                     root, extra);
}

TEST(InspectCli, HelpAndUsageErrors) {
  const auto help = run_cli("inspect --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_TRUE(contains(help.output, "--dataset TYPE ROOT")) << help.output;
  EXPECT_TRUE(contains(run_cli("--help").output, "radarpr inspect CONFIG"));
  EXPECT_EQ(run_cli("inspect").exit_code, 2);
  EXPECT_EQ(run_cli("inspect a.json --dataset oxford /x").exit_code, 2);
  EXPECT_EQ(run_cli("inspect --dataset oxford").exit_code, 2);
  EXPECT_EQ(run_cli("inspect --dataset oxford /x sequence").exit_code, 2);  // not key=value
}

TEST(InspectCli, ReportsAnOxfordRunAndCountsRevisits) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const fs::path config = tree.write("config.json", oxford_config("${RADARPR_TEST_OXFORD_ROOT}"));
  const std::string environment = "RADARPR_TEST_OXFORD_ROOT=" + tree.root().string();
  const auto result = run_cli("inspect " + config.string(), environment);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (const char* fragment :
       {"dataset oxford_tiny (single session)", "400 azimuths x 3768 range bins, 0.0432 m/bin",
        "11 found, window all: 11 selected", "2019-01-10 14:37:26.353 UTC",
        "global frame, from gps/gps.csv", "11 of 11 (0 without a pose)", "0 of 400",
        // 11 scans, 5 excluded: query q may match j <= q - 5, so queries 5..10 (6), each with
        // an eligible frame 5 scans (~9 m) back.
        "revisits      6 of 6 queries at 20 m, the 5 most recent frames excluded",
        "scan moment   a scan's time and pose refer to the first azimuth of the sweep (Oxford "
        "names files by it)"}) {
    EXPECT_TRUE(contains(result.output, fragment)) << fragment << "\n" << result.output;
  }
  EXPECT_FALSE(contains(result.output, "warning")) << result.output;

  // At 5 m nothing eligible is near enough (eligible frames lie >= 5 scans, ~9 m, back).
  const auto narrow =
      run_cli("inspect " + config.string() + " --set protocol.revisit_radius_m=5", environment);
  EXPECT_EQ(narrow.exit_code, 0);
  EXPECT_TRUE(contains(narrow.output, "0 of 6 queries at 5 m")) << narrow.output;
  EXPECT_TRUE(contains(narrow.output, "warning: no revisit")) << narrow.output;
}

// The quickstart's synthetic town: the counts equal the revisits and queries of the committed
// reference results (results/quickstart/summary.md: 388 of 550, and 90 of 200 multi session).
TEST(InspectCli, CountsTheQuickstartsRevisitsLikeTheEvaluation) {
  const auto result =
      run_cli("inspect " + (fs::path(RADARPR_SOURCE_DIR) / "configs/quickstart.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "revisits      388 of 550 queries at 20 m")) << result.output;
  EXPECT_TRUE(contains(result.output, "revisits      90 of 200 queries at 20 m")) << result.output;
}

TEST(InspectCli, ADatasetOnTheCommandLine) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const auto result = run_cli("inspect --dataset oxford " + tree.root().string() +
                              " sequence=run poses=odometry every_nth=2 --set "
                              "protocol.exclude_recent_frames=2");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "dataset oxford (single session)")) << result.output;
  EXPECT_TRUE(contains(result.output, "local frame, from integrated gt/radar_odometry.csv"));
  EXPECT_TRUE(contains(result.output, "window [0, end) every 2nd: 6 selected")) << result.output;
  // 6 scans ~4 m apart, 2 excluded: queries 2..5 (4), each with an eligible frame ~8 m back.
  EXPECT_TRUE(contains(result.output, "revisits      4 of 4 queries at 20 m")) << result.output;
}

TEST(InspectCli, RadiateClockMismatchIsReportedAndEvaluationRefused) {
  RADARPR_SKIP_WITHOUT(real_data(kRadiate), "RADIATE tiny_foggy sample");
  TempTree tree;
  const fs::path sample = real_data(kRadiate);
  for (const auto& entry : fs::directory_iterator(sample / "Navtech_Polar")) {
    tree.copy(entry.path(), "fog_6_0/Navtech_Polar/" + entry.path().filename().string());
  }
  tree.copy(sample / "Navtech_Polar.txt", "fog_6_0/Navtech_Polar.txt");
  tree.copy(sample / "GPS_IMU_Twist.txt", "fog_6_0/GPS_IMU_Twist.txt");

  const auto inspect =
      run_cli("inspect --dataset radiate " + tree.root().string() + " sequence=fog_6_0");
  EXPECT_EQ(inspect.exit_code, 1);
  EXPECT_TRUE(contains(inspect.output, "400 azimuths x 576 range bins")) << inspect.output;
  EXPECT_TRUE(contains(inspect.output, "warning: query: the GPS clock of GPS_IMU_Twist.txt"))
      << inspect.output;
  EXPECT_TRUE(contains(inspect.output, "does not overlap the radar clock")) << inspect.output;
  EXPECT_TRUE(contains(inspect.output, "error: query radiate(fog_6_0) has no poses"))
      << inspect.output;

  const fs::path config = tree.write(
      "config.json", fmt::format(R"({{"experiment": "radiate", "descriptors": ["referee"],
                      "datasets": [{{"name": "fog", "query": {{"type": "radiate", "root": "{}",
                                     "sequence": "fog_6_0"}}}}]}})",
                                 tree.root().string()));
  const auto run =
      run_cli("run " + config.string() + " --quiet --out " + tree.path("out").string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(contains(run.output,
                       "radarpr: error: dataset 'fog': query radiate(fog_6_0) has "
                       "no poses"))
      << run.output;
  EXPECT_FALSE(fs::exists(tree.path("out")));
}

// RADIATE has no poses but its images can train a descriptor: as a training sequence it passes.
TEST(InspectCli, ASequenceWithoutPosesCanStillTrain) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  RADARPR_SKIP_WITHOUT(real_data(kRadiate), "RADIATE tiny_foggy sample");
  TempTree tree;
  make_oxford_run(tree);
  for (const auto& entry : fs::directory_iterator(real_data(kRadiate) / "Navtech_Polar")) {
    tree.copy(entry.path(), "fog_6_0/Navtech_Polar/" + entry.path().filename().string());
  }
  tree.copy(real_data(kRadiate) / "Navtech_Polar.txt", "fog_6_0/Navtech_Polar.txt");
  const fs::path config = tree.write("config.json", fmt::format(R"({{
    "experiment": "train_on_radiate",
    "datasets": [{{"name": "oxford_tiny",
      "query": {{"type": "oxford", "root": "{0}", "sequence": "run"}},
      "training": {{"type": "radiate", "root": "{0}", "sequence": "fog_6_0"}}}}],
    "descriptors": ["referee"],
    "protocol": {{"exclude_recent_frames": 5, "train_on": "training_sequence"}}}})",
                                                                tree.root().string()));
  const auto result = run_cli("inspect " + config.string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "  training\n    type          radiate")) << result.output;
  EXPECT_TRUE(contains(result.output, "revisits      6 of 6 queries")) << result.output;
  EXPECT_FALSE(contains(result.output, "error")) << result.output;
}

TEST(InspectCli, MultiSessionWithLocalPositionsIsRefusedBeforeAnyWork) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const fs::path config = tree.write("config.json", fmt::format(R"({{
    "experiment": "multi",
    "datasets": [{{"name": "two_runs",
      "query": {{"type": "oxford", "root": "{0}", "sequence": "run", "poses": "odometry"}},
      "database": {{"type": "oxford", "root": "{0}", "sequence": "run", "poses": "gps"}}}}],
    "descriptors": ["referee"]}})",
                                                                tree.root().string()));
  const auto inspect = run_cli("inspect " + config.string());
  EXPECT_EQ(inspect.exit_code, 1);
  EXPECT_TRUE(contains(inspect.output,
                       "error: multi session needs the query and database "
                       "positions in one world frame, but the query"))
      << inspect.output;
  EXPECT_FALSE(contains(inspect.output, "revisits "));  // not counted across frames

  const auto run = run_cli("run " + config.string() + " --out " + tree.path("out").string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(contains(run.output, "has local positions")) << run.output;
  EXPECT_FALSE(contains(run.output, "extracting")) << run.output;  // stopped before any work
  EXPECT_FALSE(fs::exists(tree.path("out")));
}

TEST(InspectCli, AnUnsetRootVariableSaysHowToSetIt) {
  TempTree tree;
  const fs::path config = tree.write("config.json", oxford_config("${RADARPR_TEST_UNSET_ROOT}"));
  const auto result = run_cli("run " + config.string() + " --out " + tree.path("out").string(),
                              "env -u RADARPR_TEST_UNSET_ROOT");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  EXPECT_TRUE(contains(result.output, config.string() + ": datasets[0].query.root: environment "
                                                        "variable RADARPR_TEST_UNSET_ROOT is not "
                                                        "set"))
      << result.output;
  EXPECT_TRUE(contains(result.output, "--set datasets.0.query.root=")) << result.output;
  EXPECT_FALSE(fs::exists(tree.path("out")));
}

TEST(InspectCli, ARunOnTheRealSampleWritesResults) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const fs::path config = tree.write("config.json", oxford_config("${RADARPR_TEST_UNSET_ROOT}"));
  // The root given with --set instead of the variable.
  const auto result = run_cli("run " + config.string() + " --quiet --set datasets.0.query.root=" +
                              tree.root().string() + " --out " + tree.path("out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "| referee | 50x1 |")) << result.output;
  EXPECT_TRUE(fs::exists(tree.path("out/summary.json")));
}

// Each broken tree makes `run` fail with one error naming the file, and leaves no results.
TEST(InspectCli, BrokenInputsNeverProduceAResultsFile) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  RADARPR_SKIP_WITHOUT(real_data("referee_mulran_kaist03"), "MulRan KAIST03 sample");
  struct Case {
    std::string name;
    std::function<std::string(const TempTree&)> break_tree;  // returns the file to be named
  };
  const std::vector<Case> cases = {
      {"truncated png",
       [](const TempTree& tree) {
         const fs::path png = tree.path("run/radar/1547131047852128.png");  // the 7th scan
         const auto size = fs::file_size(png);
         fs::resize_file(png, size / 2);
         return png.string();
       }},
      {"png of the wrong width",
       [](const TempTree& tree) {
         return tree
             .copy(real_data("referee_mulran_kaist03/oxford_form/000000.png"),
                   "run/radar/1547131047000000.png")
             .string();
       }},
      {"pose file with a bad row",
       [](const TempTree& tree) {
         const fs::path gps = tree.path("run/gps/gps.csv");
         std::ifstream in(gps);
         std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
         in.close();
         const auto row = text.find("\n0001547131046");  // a row among the scans' times
         text[row + 1] = 'x';                            // its timestamp is no number
         std::ofstream(gps) << text;
         return gps.string() + ":";
       }},
      {"empty folder",
       [](const TempTree& tree) {
         for (const auto& entry : fs::directory_iterator(tree.path("run/radar"))) {
           fs::remove(entry.path());
         }
         return tree.path("run/radar").string() + ": no .png file";
       }},
      {"missing root",
       [](const TempTree& tree) {
         fs::remove_all(tree.path("run"));
         return tree.path("run").string() + ": sequence folder not found";
       }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    TempTree tree;
    make_oxford_run(tree);
    const std::string named = c.break_tree(tree);
    const fs::path config = tree.write("config.json", oxford_config(tree.root().string()));
    const auto result =
        run_cli("run " + config.string() + " --quiet --out " + tree.path("out").string());
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_TRUE(contains(result.output, "radarpr: error: ")) << result.output;
    EXPECT_TRUE(contains(result.output, named)) << named << "\n" << result.output;
    EXPECT_FALSE(fs::exists(tree.path("out")));
  }
}

// With 11 scans and the 20 most recent excluded, no query has anything to match: inspect says
// so as an error (exit 1, its help promises 0 only when the dataset can be evaluated), and run
// stops before any extraction instead of blaming the radius afterwards.
TEST(InspectCli, NoEligibleQueryIsAnErrorBeforeAnyWork) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const fs::path config = tree.write("config.json", oxford_config(tree.root().string()));
  const std::string exclude_all = " --set protocol.exclude_recent_frames=20";
  const auto inspect = run_cli("inspect " + config.string() + exclude_all);
  EXPECT_EQ(inspect.exit_code, 1) << inspect.output;
  EXPECT_TRUE(contains(inspect.output,
                       "error: no query has an eligible database frame (11 scans, the 20 most "
                       "recent frames excluded): nothing to evaluate"))
      << inspect.output;

  const auto run =
      run_cli("run " + config.string() + exclude_all + " --out " + tree.path("out").string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_TRUE(contains(run.output,
                       "radarpr: error: dataset 'oxford_tiny': no query has an "
                       "eligible database frame"))
      << run.output;
  EXPECT_FALSE(contains(run.output, "extracting")) << run.output;
  EXPECT_FALSE(contains(run.output, " m)")) << run.output;  // the radius is not the cause
  EXPECT_FALSE(fs::exists(tree.path("out")));
}

// No revisit at 5 m is a warning the run prints before extraction, once, and the run goes on.
TEST(InspectCli, NoRevisitIsWarnedBeforeTheRun) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const fs::path config = tree.write("config.json", oxford_config(tree.root().string()));
  const auto run = run_cli("run " + config.string() + " --set protocol.revisit_radius_m=5 --out " +
                           tree.path("out").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  const auto warning = run.output.find("warning: dataset 'oxford_tiny': no revisit");
  ASSERT_NE(warning, std::string::npos) << run.output;
  EXPECT_LT(warning, run.output.find("extracting")) << run.output;
  EXPECT_EQ(run.output.find("no revisit", run.output.find('\n', warning)), std::string::npos)
      << run.output;
}

// A multi-session pair over the same scans scores 1.000 by matching every scan with itself.
TEST(InspectCli, AMultiSessionPairSharingScanFilesIsRefused) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  const auto pair_config = [&](const std::string& query_extra, const std::string& database_root,
                               const std::string& database_extra) {
    return tree.write("config.json", fmt::format(R"({{
    "experiment": "multi",
    "datasets": [{{"name": "one_run",
      "query": {{"type": "oxford", "root": "{0}", "sequence": "run"{1}}},
      "database": {{"type": "oxford", "root": "{2}", "sequence": "run"{3}}}}}],
    "descriptors": ["referee"]}})",
                                                 tree.root().string(), query_extra, database_root,
                                                 database_extra));
  };
  // The same sequence, its root spelled differently on the database side.
  const fs::path same = pair_config("", tree.root().string() + "/./", "");
  const auto inspect = run_cli("inspect " + same.string());
  EXPECT_EQ(inspect.exit_code, 1) << inspect.output;
  EXPECT_TRUE(contains(inspect.output,
                       "error: the query and database share 11 of the query's 11 "
                       "scans"))
      << inspect.output;
  const auto run = run_cli("run " + same.string() + " --out " + tree.path("out").string());
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_TRUE(contains(run.output, "must be two different recordings")) << run.output;
  EXPECT_FALSE(fs::exists(tree.path("out")));

  // Overlapping windows: scans [0, 7) against [5, 11) share scans 5 and 6.
  const fs::path overlapping =
      pair_config(R"(, "end": 7)", tree.root().string(), R"(, "start": 5)");
  const auto windows = run_cli("inspect " + overlapping.string());
  EXPECT_EQ(windows.exit_code, 1) << windows.output;
  EXPECT_TRUE(contains(windows.output, "share 2 of the query's 7 scans")) << windows.output;

  // Disjoint windows of one sequence are two different sets of scans: accepted.
  const fs::path disjoint = pair_config(R"(, "end": 5)", tree.root().string(), R"(, "start": 5)");
  const auto apart = run_cli("inspect " + disjoint.string());
  EXPECT_FALSE(contains(apart.output, "error")) << apart.output;
}

// A folder dataset holding the Oxford scans at another resolution against the Oxford run: two
// warnings, and the pair is still evaluated.
TEST(InspectCli, AMultiSessionPairOfDifferentTypesOrGeometryIsWarned) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree);
  for (const auto& entry : fs::directory_iterator(real_data(kOxford) / "radar")) {
    tree.copy(entry.path(), "mine/scans/" + entry.path().filename().string());
  }
  // gps.csv's rows as timestamp,x,y (easting, northing), for the folder dataset.
  tree.write("mine/poses.csv",
             "timestamp,x,y\n1547131046000000,620000.0,5735000.0\n"
             "1547131049000000,620030.0,5735000.0\n");
  const fs::path config = tree.write("config.json", fmt::format(R"({{
    "experiment": "mixed",
    "datasets": [{{"name": "mixed",
      "query": {{"type": "folder", "root": "{0}", "sequence": "mine", "range_resolution_m": 0.0438}},
      "database": {{"type": "oxford", "root": "{0}", "sequence": "run"}}}}],
    "descriptors": ["referee"]}})",
                                                                tree.root().string()));
  const auto inspect = run_cli("inspect " + config.string());
  EXPECT_TRUE(contains(inspect.output,
                       "warning: the query is a folder sequence and the database a oxford one"))
      << inspect.output;
  EXPECT_TRUE(contains(inspect.output,
                       "warning: the query has 3768 range bins at 0.0438 m/bin and the database "
                       "3768 at 0.0432 m/bin"))
      << inspect.output;
  EXPECT_FALSE(contains(inspect.output, "error:")) << inspect.output;
}

// String-valued keys stay strings on the command line: a sequence folder named 10.
TEST(InspectCli, ASequenceNamedByANumberOnTheCommandLine) {
  RADARPR_SKIP_WITHOUT(real_data(kOxford), "Oxford tiny sample");
  TempTree tree;
  make_oxford_run(tree, "10");
  const auto result = run_cli("inspect --dataset oxford " + tree.root().string() +
                              " sequence=10 poses=gps every_nth=1 --set "
                              "protocol.exclude_recent_frames=5");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, (tree.root() / "10").string() + "\n")) << result.output;
  EXPECT_TRUE(contains(result.output, "revisits      6 of 6 queries")) << result.output;
}

}  // namespace
}  // namespace radarpr
