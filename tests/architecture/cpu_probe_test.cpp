// Which instruction sets the fast paths may use is asked through datasets/cpu_features.hpp, once,
// when a fast path first needs to know. __builtin_cpu_supports would link libgcc's
// __cpu_indicator_init, which probes every feature GCC knows when the program starts: in a
// virtual machine each of its cpuid instructions traps to the hypervisor, and every radarpr
// process, `radarpr --version` included, paid for them.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "datasets/cpu_features.hpp"
#include "source_tree.hpp"

namespace radarpr::test {
namespace {

TEST(CpuProbe, NoSourceFileAsksGccForCpuFeatures) {
  std::vector<std::string> found;
  std::size_t files = 0;
  for (const char* folder :
       {"datasets", "descriptors", "evaluation", "benchmarks", "cli", "python", "examples"}) {
    for (const auto& file : files_under(source_root(), folder, {".cpp", ".hpp", ".h", ".in"})) {
      ++files;
      std::istringstream lines(read_text(file));
      std::string line;
      int number = 0;
      while (std::getline(lines, line)) {
        ++number;
        const std::string code = line.substr(0, line.find("//"));  // comments may name them
        for (const char* builtin : {"__builtin_cpu_supports", "__builtin_cpu_init"}) {
          if (code.find(builtin) != std::string::npos) {
            found.push_back(file.lexically_relative(source_root()).string() + ":" +
                            std::to_string(number) + ": " + builtin);
          }
        }
      }
    }
  }
  EXPECT_GT(files, 100u) << "the source tree was not found at " << source_root();
  std::string report;
  for (const auto& line : found) report += "\n  " + line;
  EXPECT_TRUE(found.empty()) << "ask radarpr::cpu_features() (datasets/cpu_features.hpp) instead:"
                             << report;
}

// The program's symbol table names libgcc's probe when anything linked into it still uses it
// (the build tree's program is not stripped).
TEST(CpuProbe, TheProgramProbesNoCpuFeaturesAtStartUp) {
  const std::string program = read_text(RADARPR_CLI_PATH);
  ASSERT_NE(program.find(".symtab"), std::string::npos)
      << RADARPR_CLI_PATH << " has no symbol table to read";
  EXPECT_EQ(program.find("__cpu_indicator_init"), std::string::npos)
      << RADARPR_CLI_PATH << " links libgcc's __cpu_indicator_init";
}

#if defined(__x86_64__) && defined(__GNUC__)
// The same answers as GCC's own probe, which this test may use: it is no part of the program.
TEST(CpuProbe, AgreesWithGcc) {
  const CpuFeatures& features = cpu_features();
  EXPECT_EQ(features.popcnt, __builtin_cpu_supports("popcnt") != 0);
  EXPECT_EQ(features.fma, __builtin_cpu_supports("fma") != 0);
  EXPECT_EQ(features.avx2, __builtin_cpu_supports("avx2") != 0);
  EXPECT_EQ(features.avx512f, __builtin_cpu_supports("avx512f") != 0);
  EXPECT_EQ(features.avx512bw, __builtin_cpu_supports("avx512bw") != 0);
  EXPECT_EQ(features.avx512vl, __builtin_cpu_supports("avx512vl") != 0);
  EXPECT_EQ(features.avx512vnni, __builtin_cpu_supports("avx512vnni") != 0);
}
#endif

}  // namespace
}  // namespace radarpr::test
