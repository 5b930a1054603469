// Which libraries the dynamic loader loads with the `radarpr` program, with its OpenCV module
// (descriptors/opencv_module/opencv_module.hpp) and with its benchmark module
// (benchmarks/bench_module.hpp), read from their ELF dynamic sections.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "elf_needed.hpp"

namespace radarpr::test {
namespace {

bool is_opencv(const std::string& library) {
  return library.rfind("libopencv_", 0) == 0;
}

// The module exists to carry OpenCV: if it needed none, its descriptors belong in the program.
TEST(ProgramLibraries, TheOpenCvModuleNeedsOpenCv) {
  const std::vector<std::string> needed = elf_needed_libraries(RADARPR_OPENCV_MODULE_PATH);
  bool opencv = false;
  for (const std::string& library : needed) opencv = opencv || is_opencv(library);
  EXPECT_TRUE(opencv) << RADARPR_OPENCV_MODULE_PATH << " needs no libopencv_* library";
}

// Loading Debian's OpenCV (with LAPACK, BLAS, the Fortran runtime, TBB, GLX and X11) costs about
// 2 ms at every start: only the module, loaded when one of its descriptors is needed, may need it.
TEST(ProgramLibraries, TheProgramNeedsNoOpenCv) {
  for (const std::string& library : elf_needed_libraries(RADARPR_CLI_PATH)) {
    EXPECT_FALSE(is_opencv(library))
        << RADARPR_CLI_PATH << " needs " << library
        << ": code linked into the program uses OpenCV; move it into the OpenCV module "
           "(descriptors/CMakeLists.txt) or off OpenCV";
  }
}

// Google Benchmark (and its start-up work) is loaded by `radarpr bench` alone, with the benchmark
// module (benchmarks/bench_module.hpp): about 0.15 ms and 25 page faults at every other start.
TEST(ProgramLibraries, OnlyTheBenchmarkModuleNeedsGoogleBenchmark) {
  for (const std::string& library : elf_needed_libraries(RADARPR_CLI_PATH)) {
    EXPECT_NE(library.rfind("libbenchmark", 0), 0u)
        << RADARPR_CLI_PATH << " needs " << library
        << ": code linked into the program uses Google Benchmark; it belongs in the benchmark "
           "module (benchmarks/CMakeLists.txt)";
  }
#ifdef RADARPR_BENCH_MODULE_PATH
  bool benchmark = false;
  for (const std::string& library : elf_needed_libraries(RADARPR_BENCH_MODULE_PATH)) {
    benchmark = benchmark || library.rfind("libbenchmark", 0) == 0;
  }
  EXPECT_TRUE(benchmark) << RADARPR_BENCH_MODULE_PATH << " needs no libbenchmark";
#endif
}

TEST(ProgramLibraries, TheProgramIsReadable) {
  const std::vector<std::string> needed = elf_needed_libraries(RADARPR_CLI_PATH);
  bool libc = false;
  for (const std::string& library : needed) libc = libc || library.rfind("libc.so", 0) == 0;
  EXPECT_TRUE(libc) << RADARPR_CLI_PATH << ": no libc.so among its DT_NEEDED entries";
}

TEST(ProgramLibraries, ANonElfFileIsAnErrorNamingIt) {
  EXPECT_THROW(elf_needed_libraries(__FILE__), std::runtime_error);
}

}  // namespace
}  // namespace radarpr::test
