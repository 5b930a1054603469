// `radarpr bench` loads the benchmarks and Google Benchmark from a shared module when it runs
// (benchmarks/bench_module.hpp), so that no other start loads them: `radarpr --version` must not
// load libbenchmark, `radarpr bench` must, and a missing or foreign module must give an error
// naming the path expected, never a crash. Which libraries a process loads is read from the
// dynamic loader's own trace (LD_DEBUG=files), written to a file.
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "tests/architecture/source_tree.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/scratch_directory.hpp"

#ifdef RADARPR_BENCH_MODULE_PATH

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using ProcessRun = testing::CommandResult;

class BenchModuleTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::fresh_test_directory("radarpr_bench_module_test"); }
  void TearDown() override { fs::remove_all(dir_); }

  // `program ARGUMENTS` (stdout and stderr), and the files the loader opened.
  ProcessRun run(const fs::path& program, const std::string& arguments, std::string& loaded) const {
    const fs::path trace = dir_ / "trace";
    const ProcessRun result =
        testing::run_command_line(fmt::format("LD_DEBUG=files LD_DEBUG_OUTPUT={} {} {} 2>&1",
                                              trace.string(), program.string(), arguments));
    loaded.clear();
    for (const auto& entry : fs::directory_iterator(dir_)) {
      if (entry.path().filename().string().rfind("trace.", 0) == 0) {  // trace.<pid>
        loaded += test::read_text(entry.path());
        fs::remove(entry.path());
      }
    }
    return result;
  }

  // The cheapest benchmarks, written into the test's folder.
  std::string floor_bench() const {
    return "bench --quick --force --filter '^floor/400x3360' --data /nonexistent --threads 1 "
           "--out " +
           (dir_ / "report").string();
  }

  // A copy of the program alone in a folder of its own: it finds no module beside it.
  fs::path lone_program() const { return testing::lone_program_copy(dir_ / "bin"); }

  fs::path dir_;
};

TEST_F(BenchModuleTest, OnlyBenchLoadsGoogleBenchmark) {
  std::string loaded;
  const ProcessRun version = run(RADARPR_CLI_PATH, "--version", loaded);
  ASSERT_EQ(version.exit_code, 0) << version.output;
  EXPECT_NE(loaded.find("libc.so"), std::string::npos) << "no loader trace: " << loaded;
  EXPECT_EQ(loaded.find("libbenchmark"), std::string::npos) << loaded;
  EXPECT_EQ(loaded.find("radarpr_bench.so"), std::string::npos) << loaded;

  const ProcessRun bench = run(RADARPR_CLI_PATH, floor_bench(), loaded);
  ASSERT_EQ(bench.exit_code, 0) << bench.output;
  EXPECT_TRUE(fs::exists(dir_ / "report" / "bench.json"));
  EXPECT_NE(loaded.find("radarpr_bench.so"), std::string::npos) << loaded;
  EXPECT_NE(loaded.find("libbenchmark"), std::string::npos) << loaded;
}

TEST_F(BenchModuleTest, AMissingModuleIsAnErrorNamingWhereItWasExpected) {
  const fs::path program = lone_program();
  std::string loaded;
  const ProcessRun bench = run(program, floor_bench(), loaded);
  EXPECT_EQ(bench.exit_code, 1) << bench.output;
  EXPECT_NE(bench.output.find("radarpr: error: radarpr bench needs radarpr's benchmark module, "
                              "which is missing: expected " +
                              (program.parent_path() / "radarpr_bench.so").string()),
            std::string::npos)
      << bench.output;
  // Every other verb works without it.
  EXPECT_EQ(run(program, "--version", loaded).exit_code, 0);
}

TEST_F(BenchModuleTest, AForeignLibraryInItsPlaceIsAnErrorNamingIt) {
  const fs::path program = lone_program();
  const fs::path module = program.parent_path() / "radarpr_bench.so";
  fs::copy_file(RADARPR_PROBE_PLUGIN_PATH, module);
  std::string loaded;
  const ProcessRun bench = run(program, floor_bench(), loaded);
  EXPECT_EQ(bench.exit_code, 1) << bench.output;
  EXPECT_NE(bench.output.find(module.string() + ", which exports no 'radarpr_bench_module_abi'"),
            std::string::npos)
      << bench.output;
}

}  // namespace
}  // namespace radarpr

#endif
