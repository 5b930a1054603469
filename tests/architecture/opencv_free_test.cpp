// Reading a scan must not load OpenCV: a program linked to it pays for loading it (and LAPACK,
// BLAS, TBB with it) on every start. So scans are radarpr's own ByteImage, and the code that reads
// and writes them - datasets/, the Python bindings and the interface a descriptor plugin compiles
// against - includes no OpenCV header, and radarpr_datasets links no OpenCV library. The
// descriptors that use OpenCV reach a scan's pixels through descriptors/opencv_image.hpp.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "source_tree.hpp"

namespace radarpr::test {
namespace {

// "file:line: includes <header>" for each OpenCV header `file` includes.
std::vector<std::string> opencv_includes(const std::filesystem::path& file) {
  static const std::regex include(R"(^\s*#\s*include\s*[<"](opencv2/[^>"]+)[>"])");
  std::vector<std::string> found;
  std::istringstream lines(read_text(file));
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::smatch match;
    if (std::regex_search(line, match, include)) {
      found.push_back(file.lexically_relative(source_root()).string() + ":" +
                      std::to_string(number) + ": includes " + match[1].str());
    }
  }
  return found;
}

// The files that handle scans without needing an image library: datasets/, the Python bindings,
// the plugin loader and every header a plugin compiles against.
std::vector<std::filesystem::path> opencv_free_files() {
  std::vector<std::filesystem::path> files;
  for (const std::string folder : {"datasets", "python", "descriptors/plugins"}) {
    for (auto& file : files_under(source_root(), folder, {".cpp", ".hpp", ".h", ".in"})) {
      files.push_back(std::move(file));
    }
  }
  // The headers installed for plugins (cmake/RadarprInstall.cmake): radarpr::plugin_api links
  // no OpenCV, so none of them may need it.
  const std::string install = read_text(source_root() / "cmake" / "RadarprInstall.cmake");
  static const std::regex list(R"(set\(radarpr_plugin_headers\n([\s\S]*?)\n\))");
  static const std::regex header(R"(^\s*([\w/]+\.hpp)\s*$)");
  std::smatch listed;
  std::size_t installed = 0;
  if (std::regex_search(install, listed, list)) {
    std::istringstream lines(listed[1].str());
    std::string line;
    std::smatch name;
    while (std::getline(lines, line)) {
      if (!std::regex_match(line, name, header)) continue;
      files.push_back(source_root() / name[1].str());
      ++installed;
    }
  }
  EXPECT_GE(installed, 10u) << "cmake/RadarprInstall.cmake's radarpr_plugin_headers not read";
  return files;
}

TEST(OpenCvFree, ScansAreReadWithoutOpenCv) {
  const auto files = opencv_free_files();
  EXPECT_GT(files.size(), 50u) << "the source tree was not found at " << source_root();
  std::string report;
  for (const auto& file : files) {
    for (const auto& found : opencv_includes(file)) report += "\n  " + found;
  }
  EXPECT_TRUE(report.empty()) << "OpenCV headers where scans are read (use ByteImage):" << report;
  const std::string cmake = read_text(source_root() / "datasets" / "CMakeLists.txt");
  static const std::regex links_opencv(
      R"(target_link_libraries\s*\([^)]*\b(opencv_\w+|\$\{OpenCV))");
  std::smatch match;
  EXPECT_FALSE(std::regex_search(cmake, match, links_opencv))
      << "datasets/CMakeLists.txt links " << match.str(1);
  const std::string descriptors = read_text(source_root() / "descriptors" / "CMakeLists.txt");
  static const std::regex api_links_opencv(
      R"(target_link_libraries\s*\(\s*radarpr_plugin_api[^)]*\b(opencv_\w+|\$\{OpenCV))");
  EXPECT_FALSE(std::regex_search(descriptors, match, api_links_opencv))
      << "radarpr_plugin_api links " << match.str(1);
}

// The check itself: an OpenCV include is reported with its line, other includes are not.
TEST(OpenCvFree, ReportsAnOpenCvIncludeAndOnlyThat) {
  const std::filesystem::path file =
      std::filesystem::path(testing::TempDir()) / "radarpr_opencv_probe.cpp";
  {
    std::ofstream out(file);
    out << "#include <vector>\n#include \"datasets/byte_image.hpp\"\n"
           "  #  include <opencv2/core/mat.hpp>\n// opencv2/core.hpp in a comment\n";
  }
  const auto found = opencv_includes(file);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].find(":3: includes opencv2/core/mat.hpp"), std::string::npos) << found[0];
}

}  // namespace
}  // namespace radarpr::test
