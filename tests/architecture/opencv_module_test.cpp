// The `radarpr` program loads the descriptors that need OpenCV from a shared module, on first use
// (descriptors/opencv_module/opencv_module.hpp): a ReFeree extraction must not load it, a RaPlace
// extraction must, and a missing or foreign module must give an error naming the path expected
// and the descriptor asked for, never a crash. Which libraries a process loads is read from the
// dynamic loader's own trace (LD_DEBUG=files), written to a file.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/opencv_module/opencv_module.hpp"
#include "tests/architecture/source_tree.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/scratch_directory.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleFile = "radarpr_opencv_descriptors.so";

using ProcessRun = testing::CommandResult;

// A shell command line's stdout and stderr, and its exit code.
ProcessRun run(const std::string& command) {
  return testing::run_command_line(command + " 2>&1");
}

class OpenCvModuleTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::fresh_test_directory("radarpr_opencv_module_test");
    // A scan in MulRan's native layout (range x azimuth, 3360 bins: the resolution is known).
    cv::Mat scan(3360, 400, CV_8U);
    cv::RNG random(7);
    random.fill(scan, cv::RNG::UNIFORM, 0, 256);
    png_ = dir_ / "scan.png";
    ASSERT_TRUE(cv::imwrite(png_.string(), scan));
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `program extract ID scan.png`, and the files the loader opened (its LD_DEBUG=files trace).
  ProcessRun extract(const fs::path& program, const std::string& id, std::string& loaded) const {
    const fs::path trace = dir_ / "trace";
    const ProcessRun result = run(fmt::format("LD_DEBUG=files LD_DEBUG_OUTPUT={} {} extract {} {}",
                                              trace.string(), program.string(), id, png_.string()));
    loaded.clear();
    for (const auto& entry : fs::directory_iterator(dir_)) {
      // The loader appends the process id: trace.<pid>.
      if (entry.path().filename().string().rfind("trace.", 0) == 0) {
        loaded += test::read_text(entry.path());
        fs::remove(entry.path());
      }
    }
    return result;
  }

  // A copy of the program alone in a folder of its own: it finds no module beside it.
  fs::path lone_program() const { return testing::lone_program_copy(dir_ / "bin"); }

  fs::path dir_;
  fs::path png_;
};

TEST_F(OpenCvModuleTest, RefereeExtractionDoesNotLoadTheModuleAndRaplaceDoes) {
  std::string loaded;
  const ProcessRun referee = extract(RADARPR_CLI_PATH, "referee", loaded);
  ASSERT_EQ(referee.exit_code, 0) << referee.output;
  EXPECT_NE(referee.output.find("\"id\":\"referee\""), std::string::npos) << referee.output;
  // The trace is really there: it names the program's own libraries.
  ASSERT_NE(loaded.find("libstdc++"), std::string::npos) << loaded;
  EXPECT_EQ(loaded.find(kModuleFile), std::string::npos) << loaded;
  EXPECT_EQ(loaded.find("libopencv_"), std::string::npos) << loaded;

  const ProcessRun raplace = extract(RADARPR_CLI_PATH, "raplace", loaded);
  ASSERT_EQ(raplace.exit_code, 0) << raplace.output;
  EXPECT_NE(raplace.output.find("\"id\":\"raplace\""), std::string::npos) << raplace.output;
  EXPECT_NE(loaded.find(kModuleFile), std::string::npos) << loaded;
  EXPECT_NE(loaded.find("libopencv_imgproc"), std::string::npos) << loaded;
}

// Without its module the program still runs everything that does not need it, and names the
// paths it looked at and the descriptor asked for otherwise.
TEST_F(OpenCvModuleTest, AMissingModuleIsAnErrorNamingThePathAndTheDescriptor) {
  const fs::path program = lone_program();
  std::string loaded;
  const ProcessRun referee = extract(program, "referee", loaded);
  EXPECT_EQ(referee.exit_code, 0) << referee.output;

  const ProcessRun raplace = extract(program, "raplace", loaded);
  EXPECT_EQ(raplace.exit_code, 1) << raplace.output;
  EXPECT_NE(raplace.output.find("radarpr: error: descriptor 'raplace' needs radarpr's OpenCV "
                                "module, which is missing: expected " +
                                (program.parent_path() / kModuleFile).string()),
            std::string::npos)
      << raplace.output;
  const fs::path installed = (program.parent_path() / ".." / "lib" / "radarpr" / kModuleFile);
  EXPECT_NE(raplace.output.find(installed.lexically_normal().string()), std::string::npos)
      << raplace.output;

  // Listing every descriptor needs the module too.
  const ProcessRun list = run(program.string() + " list");
  EXPECT_EQ(list.exit_code, 1) << list.output;
  EXPECT_NE(list.output.find("listing every descriptor needs radarpr's OpenCV module"),
            std::string::npos)
      << list.output;
  // An unknown name is still told apart, with the module's descriptors among the known ones.
  const ProcessRun unknown = run(program.string() + " extract raplaec " + png_.string());
  EXPECT_EQ(unknown.exit_code, 1) << unknown.output;
  EXPECT_NE(unknown.output.find("unknown descriptor 'raplaec'"), std::string::npos)
      << unknown.output;
  EXPECT_NE(unknown.output.find("raplace"), std::string::npos) << unknown.output;
}

// A file in the module's place that is not radarpr's module: another shared library (a descriptor
// plugin, which exports a plugin's entry point but not the module's), and not a library at all.
TEST_F(OpenCvModuleTest, AForeignModuleIsAnErrorNamingThePath) {
  const fs::path program = lone_program();
  const fs::path module = program.parent_path() / kModuleFile;
  fs::copy_file(RADARPR_PROBE_PLUGIN_PATH, module);
  std::string loaded;
  const ProcessRun plugin = extract(program, "open_radvlad", loaded);
  EXPECT_EQ(plugin.exit_code, 1) << plugin.output;
  EXPECT_NE(plugin.output.find(fmt::format(
                "radarpr: error: descriptor 'open_radvlad' needs radarpr's OpenCV module {}, "
                "which exports no 'radarpr_opencv_module_abi': not radarpr's OpenCV module",
                module.string())),
            std::string::npos)
      << plugin.output;

  fs::remove(module);
  std::ofstream(module) << "not a shared library\n";
  const ProcessRun text = extract(program, "radar_scan_context", loaded);
  EXPECT_EQ(text.exit_code, 1) << text.output;
  EXPECT_NE(text.output.find(fmt::format("descriptor 'radar_scan_context' needs radarpr's OpenCV "
                                         "module {}, which cannot be loaded",
                                         module.string())),
            std::string::npos)
      << text.output;
}

// The program knows the module's descriptors by name before loading it: the names the build
// collected must be exactly those the module's registrations give (here linked in).
TEST(OpenCvModuleNames, AreTheNamesTheModuleRegisters) {
  DescriptorRegistry registered;
  register_opencv_module_descriptors(registered);
  std::vector<std::string> names;
  for (const DescriptorInfo* info : registered.all()) names.push_back(info->name);
  const auto expected = opencv_module_descriptor_names();
  EXPECT_EQ(names, std::vector<std::string>(expected.begin(), expected.end()));
  EXPECT_FALSE(names.empty());
  for (const std::string& name : names) {
    EXPECT_TRUE(DescriptorRegistry::global().contains(name)) << name;
  }
}

}  // namespace
}  // namespace radarpr
