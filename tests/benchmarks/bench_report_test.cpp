// The report of `radarpr bench` from hand-made measurements: the tables' arithmetic, the
// targets, and the files.
#include "benchmarks/bench_report.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "benchmarks/speed_targets.hpp"

namespace radarpr::bench {
namespace {

CaseResult scan_result(CaseKind kind, const std::string& descriptor, double cpu_seconds) {
  CaseResult result;
  result.bench.name = std::string(to_string(kind)) + "/" + descriptor + "/400x3360";
  result.bench.kind = kind;
  result.bench.scan = "400x3360";
  result.bench.descriptor = descriptor;
  result.measurement.cpu_seconds = cpu_seconds;
  result.measurement.real_seconds = cpu_seconds;
  result.measurement.repetitions = 3;
  return result;
}

CaseResult stage_result(const std::string& descriptor, Stage stage, double cpu_seconds) {
  CaseResult result = scan_result(CaseKind::stage, descriptor, cpu_seconds);
  result.bench.name.append("/").append(to_string(stage));
  result.bench.stage = stage;
  result.bench.what = "what it does";
  return result;
}

CaseResult search_result(CaseKind kind, const std::string& strategy, const std::string& descriptor,
                         std::size_t n, const std::string& session, double real_seconds) {
  CaseResult result;
  result.bench.name = std::string(to_string(kind)) + "/" + descriptor + "/" + session;
  result.bench.kind = kind;
  result.bench.strategy = strategy;
  result.bench.descriptor = descriptor;
  result.bench.database_size = n;
  result.bench.session = session;
  result.bench.queries_timed = n;
  result.bench.queries_total = n;
  result.measurement.real_seconds = real_seconds;
  result.measurement.repetitions = 3;
  return result;
}

// Plain pass 0.2 ms, PNG decode 2 ms on the scan; referee 1 ms (features 0.95 ms, descriptor
// 0.002 ms), raplace 30 ms with a 3 ms preparation, radar_scan_context 0.25 ms in one piece.
// kdtree referee N = 10^5: index 0.5 s, single session 4 s, multi session 6 s. raplace N = 10^4
// multi: 200 of 10^4 queries timed in 2.1 s (index 0.1 s). open_radvlad N = 10^3 multi: 3 s
// against a 2 s product of the same 10^6 pairs. Appended last: R-ReFeree with the journal
// parameters 0.5 ms; open_radvlad N = 10^3 single session, 0.8 s for its 475,000 pairs.
BenchRun hand_made_run() {
  BenchRun run;
  run.machine.cpu_model = "Test CPU";
  run.machine.logical_cores = 2;
  run.machine.build_type = "Release";
  run.machine.optimised = true;
  run.length = {0.5, 3};
  run.scans.push_back({"400x3360", "Navtech CIR204-H (MulRan)", "synthetic", false, 400, 3360, 1});
  run.results = {
      scan_result(CaseKind::floor, "", 0.2e-3),
      scan_result(CaseKind::png_decode, "", 2e-3),
      scan_result(CaseKind::extraction, "referee", 1e-3),
      stage_result("referee", Stage::features, 0.95e-3),
      stage_result("referee", Stage::descriptor, 0.002e-3),
      scan_result(CaseKind::extraction, "raplace", 30e-3),
      stage_result("raplace", Stage::preparation, 3e-3),
      scan_result(CaseKind::extraction, "radar_scan_context", 0.25e-3),
      search_result(CaseKind::index_build, "kdtree", "referee", 100'000, "", 0.5),
      search_result(CaseKind::retrieval, "kdtree", "referee", 100'000, "single", 4.0),
      search_result(CaseKind::retrieval, "kdtree", "referee", 100'000, "multi", 6.0),
      search_result(CaseKind::index_build, "exhaustive", "raplace", 10'000, "", 0.1),
      search_result(CaseKind::retrieval, "exhaustive", "raplace", 10'000, "multi", 2.1),
      search_result(CaseKind::retrieval, "exhaustive_l2", "open_radvlad", 1'000, "multi", 3.0),
      search_result(CaseKind::matrix_product, "exhaustive_l2", "open_radvlad", 1'000, "multi", 2.0),
      scan_result(CaseKind::extraction, "referee_r:kernel=box,z_q=3", 0.5e-3),
      search_result(CaseKind::retrieval, "exhaustive_l2", "open_radvlad", 1'000, "single", 0.8),
  };
  run.results[2].measurement.counters = {{"payload_bytes", 200.0}, {"paper_bytes", 528.0}};
  BenchCase& sampled = run.results[12].bench;
  sampled.queries_timed = 200;
  sampled.pairs_timed = 200 * 10'000;
  sampled.pairs_total = 10'000 * 10'000;
  run.results[13].bench.pairs_timed = 1'000'000;
  run.results[14].bench.pairs_timed = 1'000'000;
  run.results[16].bench.pairs_timed = 475'000;
  run.skipped.push_back({"retrieval/exhaustive_l2/open_radvlad/100000/single",
                         "100000 x 32768 floats per session exceed the memory budget"});
  return run;
}

const TargetCheck& target_saying(const std::vector<TargetCheck>& targets, const char* fragment) {
  for (const TargetCheck& target : targets) {
    if (target.target.find(fragment) != std::string::npos) return target;
  }
  throw std::logic_error(std::string("no target says ") + fragment);
}

TEST(BenchReport, ExtractionRowsSplitTheTimeAndDeriveWhatIsNotTimed) {
  const std::vector<ExtractionRow> rows = extraction_rows(hand_made_run());
  ASSERT_EQ(rows.size(), 4u);
  const ExtractionRow& referee = rows[0];
  EXPECT_EQ(referee.descriptor, "referee");
  EXPECT_DOUBLE_EQ(*referee.png_decode, 2e-3);
  EXPECT_FALSE(referee.preparation.has_value());
  EXPECT_DOUBLE_EQ(*referee.features, 0.95e-3);
  EXPECT_DOUBLE_EQ(referee.descriptor_stage, 0.002e-3);
  EXPECT_FALSE(referee.descriptor_derived);
  EXPECT_DOUBLE_EQ(*referee.floor_multiple, 5.0);  // 1 ms / 0.2 ms
  EXPECT_EQ(referee.payload_bytes, 200.0);
  EXPECT_EQ(referee.paper_bytes, 528.0);

  const ExtractionRow& raplace = rows[1];  // 30 ms - 3 ms preparation = 27 ms, derived
  EXPECT_DOUBLE_EQ(*raplace.preparation, 3e-3);
  EXPECT_NEAR(raplace.descriptor_stage, 27e-3, 1e-12);
  EXPECT_TRUE(raplace.descriptor_derived);
  EXPECT_DOUBLE_EQ(*raplace.floor_multiple, 150.0);

  const ExtractionRow& context = rows[2];  // no stages: all of it is the descriptor
  EXPECT_FALSE(context.preparation.has_value());
  EXPECT_FALSE(context.features.has_value());
  EXPECT_DOUBLE_EQ(context.descriptor_stage, 0.25e-3);
  EXPECT_FALSE(context.descriptor_derived);
}

TEST(BenchReport, RetrievalRowsExtrapolateSampledQueriesAndCompareWithTheProduct) {
  const std::vector<RetrievalRow> rows = retrieval_rows(hand_made_run());
  ASSERT_EQ(rows.size(), 5u);
  const RetrievalRow& single = rows[0];
  EXPECT_EQ(single.session, "single");
  EXPECT_DOUBLE_EQ(*single.index_build, 0.5);
  EXPECT_DOUBLE_EQ(single.total, 4.0);
  EXPECT_DOUBLE_EQ(single.per_query, 3.5 / 100'000);  // (4 - 0.5) s over 10^5 queries
  EXPECT_FALSE(single.extrapolated);

  // 0.1 s index + (2.1 - 0.1) s for 2e6 of 1e8 pairs: 0.1 + 2 * 50 = 100.1 s; per query
  // 100 s / 10^4.
  const RetrievalRow& sampled = rows[2];
  EXPECT_TRUE(sampled.extrapolated);
  EXPECT_NEAR(sampled.total, 100.1, 1e-9);
  EXPECT_NEAR(sampled.per_query, 0.01, 1e-12);

  const RetrievalRow& l2 = rows[3];
  EXPECT_FALSE(l2.index_build.has_value());
  EXPECT_DOUBLE_EQ(*l2.over_matrix_product, 1.5);  // 3 s / 2 s

  // Per pair: 0.8 s / 475,000 pairs against 2 s / 10^6 pairs.
  const RetrievalRow& single_l2 = rows[4];
  EXPECT_EQ(single_l2.session, "single");
  EXPECT_NEAR(*single_l2.over_matrix_product, (0.8 / 475'000) / (2.0 / 1e6), 1e-12);
}

// A single-session product (the queries against their prefixes) is the single session's
// reference when measured: 0.8 s against 0.5 s for the same 475,000 pairs.
TEST(BenchReport, SingleSessionSearchComparesWithTheProductOfItsOwnShapes) {
  BenchRun run = hand_made_run();
  CaseResult product = search_result(CaseKind::matrix_product, "exhaustive_l2", "open_radvlad",
                                     1'000, "single", 0.5);
  product.bench.pairs_timed = 475'000;
  run.results.push_back(product);
  const std::vector<RetrievalRow> rows = retrieval_rows(run);
  EXPECT_DOUBLE_EQ(*rows[3].over_matrix_product, 1.5);  // multi: still 3 s / 2 s
  EXPECT_EQ(rows[4].session, "single");
  EXPECT_NEAR(*rows[4].over_matrix_product, 1.6, 1e-12);
}

TEST(BenchReport, TargetsAreMetOrNotFromTheMeasurements) {
  const std::vector<TargetCheck> targets = check_targets(hand_made_run());
  ASSERT_EQ(targets.size(), speed_targets().size());

  const TargetCheck& journal = target_saying(targets, "R-ReFeree, journal parameters");
  EXPECT_EQ(journal.part, "extraction");
  EXPECT_EQ(journal.met, true);  // 0.5 ms <= 3 x 0.2 ms
  EXPECT_NE(journal.measured.find("0.500 ms vs 0.200 ms plain pass (2.50x)"), std::string::npos)
      << journal.measured;
  EXPECT_EQ(target_saying(targets, "ReFeree, defaults").met, false);  // 1 ms = 5x
  EXPECT_FALSE(target_saying(targets, "workshop parameters").met.has_value());

  const TargetCheck& decode = target_saying(targets, "no slower than decoding");
  EXPECT_EQ(decode.met, true);
  EXPECT_NE(decode.measured.find("1.00 ms vs 2.00 ms"), std::string::npos) << decode.measured;
  EXPECT_EQ(target_saying(targets, "RaPlace extraction").met, false);  // 30 ms > 3 ms

  const TargetCheck& single = target_saying(targets, "ReFeree search, 10^5 scans, single");
  EXPECT_EQ(single.part, "retrieval");
  EXPECT_EQ(single.met, false);  // 4 s
  EXPECT_EQ(single.measured, "4.00 s");
  EXPECT_EQ(target_saying(targets, "ReFeree search, 10^5 scans, multi").met, false);  // 6 s

  const TargetCheck& product = target_saying(targets, "multi session: within 1.2x");
  EXPECT_EQ(product.met, false);  // 1.5x
  const TargetCheck& single_product = target_saying(targets, "single session: within 1.2x");
  EXPECT_EQ(single_product.met, true);  // 0.84x per pair
  EXPECT_NE(single_product.measured.find("open_radvlad: 0.84x at N = 10^3"), std::string::npos)
      << single_product.measured;

  const TargetCheck& runs = target_saying(targets, "32,768-D");
  EXPECT_EQ(runs.met, false);
  EXPECT_NE(runs.measured.find("left out: 100000 x 32768"), std::string::npos) << runs.measured;
}

// The 32,768-D search at 10^5 from memory-mapped values: met when it ran within 8 GB of peak
// memory, its time marked as extrapolated from the sampled queries; a failure is reported.
TEST(BenchReport, MappedSearchTargetNeedsItsPeakMemory) {
  BenchRun run = hand_made_run();
  run.skipped.clear();
  CaseResult mapped =
      search_result(CaseKind::retrieval, "exhaustive_l2", "open_radvlad", 100'000, "single", 20.0);
  mapped.bench.name = "retrieval/exhaustive_l2/open_radvlad/100000/single";
  mapped.bench.queries_timed = 256;
  mapped.bench.pairs_timed = 256 * 50'000;
  mapped.bench.pairs_total = 5'000'000'000;
  mapped.measurement.counters = {{"peak_rss_bytes", 0.3e9}, {"values_bytes", 13.1e9}};
  run.results.push_back(mapped);
  const TargetCheck within = target_saying(check_targets(run), "32,768-D");
  EXPECT_EQ(within.met, true);
  EXPECT_NE(within.measured.find("extrapolated from 256 of 100000 queries"), std::string::npos)
      << within.measured;
  EXPECT_NE(within.measured.find("peak memory 0.30 GB (13.1 GB of values memory-mapped)"),
            std::string::npos)
      << within.measured;
  EXPECT_NE(report_markdown(run).find("Peak resident memory of the process during the search: "
                                      "0.30 GB"),
            std::string::npos);

  run.results.back().measurement.counters["peak_rss_bytes"] = 9e9;
  EXPECT_EQ(target_saying(check_targets(run), "32,768-D").met, false);

  run.results.back().measurement.error = "the values (13.1 GB) need 14.2 GB free in /tmp";
  const TargetCheck failed = target_saying(check_targets(run), "32,768-D");
  EXPECT_EQ(failed.met, false);
  EXPECT_NE(failed.measured.find("failed: the values"), std::string::npos) << failed.measured;
}

// A second open_radvlad configuration at 2.5x its product: the target holds for every
// configuration or not at all.
TEST(BenchReport, ProductTargetCoversEveryOpenRadvladConfiguration) {
  BenchRun run = hand_made_run();
  const std::string ds = "open_radvlad:bin_dim=10";
  run.results.push_back(
      search_result(CaseKind::retrieval, "exhaustive_l2", ds, 1'000, "multi", 5.0));
  run.results.push_back(
      search_result(CaseKind::matrix_product, "exhaustive_l2", ds, 1'000, "multi", 2.0));
  const TargetCheck product =
      target_saying(check_targets(run), "Open-RadVLAD search, multi session");
  EXPECT_EQ(product.met, false);
  EXPECT_NE(product.measured.find("open_radvlad: 1.50x at N = 10^3"), std::string::npos)
      << product.measured;
  EXPECT_NE(product.measured.find("open_radvlad:bin_dim=10: 2.50x at N = 10^3"), std::string::npos)
      << product.measured;
}

TEST(BenchReport, UnmeasuredTargetsSayNothingWasMeasured) {
  BenchRun run = hand_made_run();
  run.results.resize(2);  // floor and decode only
  run.skipped.clear();
  for (const TargetCheck& target : check_targets(run)) {
    EXPECT_TRUE(target.measured.empty()) << target.target;
    EXPECT_FALSE(target.met.has_value()) << target.target;
  }
}

// `radarpr --version` 4 ms; `radarpr extract referee` 5 ms of wall clock (4.5 ms of CPU)
// against 2 ms decode + 1 ms extraction in a running process: 1.67x; a failed run has no row.
BenchRun with_startup(double version_seconds) {
  BenchRun run = hand_made_run();
  CaseResult version;
  version.bench.name = "startup/version";
  version.bench.kind = CaseKind::startup;
  version.measurement.real_seconds = version_seconds;
  version.measurement.counters["process_cpu_seconds"] = 3e-3;
  run.results.push_back(version);
  CaseResult extract = scan_result(CaseKind::startup, "referee", 4.5e-3);
  extract.measurement.real_seconds = 5e-3;
  extract.measurement.counters["process_cpu_seconds"] = 4.5e-3;
  run.results.push_back(extract);
  CaseResult failed = scan_result(CaseKind::startup, "raplace", 0.0);
  failed.measurement.error = "`radarpr extract raplace` failed";
  run.results.push_back(failed);
  return run;
}

TEST(BenchReport, StartupRowsCompareTheWholeProcessWithTheWorkInARunningProcess) {
  const std::vector<StartupRow> rows = startup_rows(with_startup(4e-3));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].command, "radarpr --version");
  EXPECT_DOUBLE_EQ(rows[0].wall, 4e-3);
  EXPECT_DOUBLE_EQ(rows[0].process_cpu, 3e-3);
  EXPECT_FALSE(rows[0].over_in_process.has_value());
  EXPECT_EQ(rows[1].command, "radarpr extract referee 400x3360.png");
  EXPECT_DOUBLE_EQ(*rows[1].in_process, 3e-3);
  EXPECT_NEAR(*rows[1].over_in_process, 5.0 / 3.0, 1e-12);

  const std::vector<TargetCheck> targets = check_targets(with_startup(4e-3));
  const TargetCheck& version = target_saying(targets, "radarpr --version");
  EXPECT_EQ(version.part, "start-up");
  EXPECT_EQ(version.met, true);
  EXPECT_EQ(version.measured, "4.00 ms (3.00 ms of CPU)");
  const TargetCheck& extract = target_saying(targets, "radarpr extract referee");
  EXPECT_EQ(extract.met, true);
  EXPECT_EQ(extract.measured, "5.00 ms vs 3.00 ms in a running process (1.67x)");
  EXPECT_EQ(target_saying(check_targets(with_startup(25e-3)), "radarpr --version").met, false);

  const std::string md = report_markdown(with_startup(4e-3));
  EXPECT_NE(md.find("| `radarpr extract referee 400x3360.png` | 5.00 | 4.50 | 3.00 | 1.67x |"),
            std::string::npos)
      << md;
}

// The minimal program beside radarpr: 0.5 ms started with nothing to do, 4 ms decoding the PNG
// (against the 2 ms decode in a running process). It sets the floor, it is not a radarpr target.
TEST(BenchReport, TheMinimalProgramIsTheStartupFloorAndNoTarget) {
  BenchRun run = with_startup(4e-3);
  CaseResult empty;
  empty.bench.name = "startup/floor/empty";
  empty.bench.kind = CaseKind::process_floor;
  empty.measurement.real_seconds = 0.5e-3;
  run.results.push_back(empty);
  CaseResult decode = scan_result(CaseKind::process_floor, "", 1e-3);
  decode.bench.name = "startup/floor/png_decode/400x3360";
  decode.measurement.real_seconds = 4e-3;
  run.results.push_back(decode);

  const std::vector<StartupRow> rows = startup_rows(run);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_TRUE(rows[2].floor);
  EXPECT_EQ(rows[2].command, "radarpr_png_decode_floor");
  EXPECT_FALSE(rows[2].in_process.has_value());
  EXPECT_EQ(rows[3].command, "radarpr_png_decode_floor 400x3360.png");
  EXPECT_DOUBLE_EQ(*rows[3].in_process, 2e-3);  // the decode alone
  EXPECT_NEAR(*rows[3].over_in_process, 2.0, 1e-12);

  const std::vector<TargetCheck> targets = check_targets(run);
  const TargetCheck& extract = target_saying(targets, "radarpr extract referee");
  EXPECT_EQ(extract.met, true);  // judged on radarpr's own row, not the floor's
  EXPECT_EQ(extract.measured,
            "5.00 ms vs 3.00 ms in a running process (1.67x); the minimal program that only "
            "decodes the same PNG: 4.00 ms (1.33x)");
  EXPECT_NE(report_markdown(run).find("| `radarpr_png_decode_floor 400x3360.png` | 4.00 |"),
            std::string::npos);
}

TEST(BenchReport, MarkdownHoldsTheTablesAndWarnsAboutSlowBuilds) {
  const std::string md = report_markdown(hand_made_run());
  EXPECT_NE(md.find("Test CPU (2 logical cores"), std::string::npos);
  // Descriptor, scan, decode, preparation, features, descriptor, extraction, x floor, scans/s.
  EXPECT_NE(md.find("| referee | 400x3360 | 2.00 | - | 0.950 | 0.00200 | 1.00 | 5.00 | 1000 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| raplace | 400x3360 | 2.00 | 3.00 | - | ~27.0 | 30.0 | 150 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| exhaustive | raplace | 0 | 10^4 | multi | 0.100 | 100* | 10.0 | 200 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| retrieval | ReFeree search, 10^5 scans, multi session"), std::string::npos)
      << md;
  EXPECT_NE(md.find("**not met**"), std::string::npos);
  EXPECT_EQ(md.find("WARNING"), std::string::npos);

  BenchRun debug = hand_made_run();
  debug.machine.optimised = false;
  debug.machine.build_type = "Debug";
  EXPECT_NE(report_markdown(debug).find("**WARNING: not an optimised build (Debug).**"),
            std::string::npos);
}

TEST(BenchReport, WritesJsonAndMarkdownFiles) {
  const std::filesystem::path folder =
      std::filesystem::path(::testing::TempDir()) / "radarpr_bench_report_test";
  std::filesystem::remove_all(folder);
  write_report(hand_made_run(), folder / "nested");
  std::ifstream json_file(folder / "nested" / "bench.json");
  const nlohmann::json json = nlohmann::json::parse(json_file);
  EXPECT_EQ(json["machine"]["cpu_model"], "Test CPU");
  EXPECT_EQ(json["results"].size(), 17u);
  EXPECT_EQ(json["extraction"].size(), 4u);
  EXPECT_EQ(json["retrieval"].size(), 5u);
  ASSERT_EQ(json["targets"].size(), speed_targets().size());
  EXPECT_EQ(json["targets"][0]["part"], "extraction");
  EXPECT_TRUE(json["targets"][0]["met"].get<bool>());  // the journal parameters, 2.5x
  EXPECT_DOUBLE_EQ(json["retrieval"][2]["total_seconds"].get<double>(), 100.1);
  std::ifstream md_file(folder / "nested" / "bench.md");
  std::stringstream md;
  md << md_file.rdbuf();
  EXPECT_EQ(md.str(), report_markdown(hand_made_run()));
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace radarpr::bench
