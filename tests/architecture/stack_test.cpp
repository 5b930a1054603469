// The folders form a stack, cli -> benchmarks -> evaluation -> descriptors -> datasets (python
// beside cli): a source file may include headers of its own folder and of folders below it, never
// of one above, nor of one beside it (cli and python are two separate tops). This test reads
// every #include of every source file and names each that runs back up or sideways.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "source_tree.hpp"

namespace radarpr::test {
namespace {

// Height of each top-level folder in the stack.
const std::map<std::string, int>& stack_levels() {
  static const std::map<std::string, int> levels = {
      {"datasets", 0},   {"descriptors", 1}, {"evaluation", 2},
      {"benchmarks", 3}, {"cli", 4},         {"python", 4},
  };
  return levels;
}

// "file:line: includes <header> (evaluation is above descriptors)" for each include of `file`
// (which lives in `folder`) that names a header of a higher folder, or of another folder at the
// same height.
std::vector<std::string> upward_includes(const std::filesystem::path& file,
                                         const std::string& folder) {
  static const std::regex include(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  std::vector<std::string> found;
  std::istringstream lines(read_text(file));
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::smatch match;
    if (!std::regex_search(line, match, include)) continue;
    const std::string header = match[1];
    const std::string target = header.substr(0, header.find('/'));
    const auto level = stack_levels().find(target);
    if (level == stack_levels().end() || header.find('/') == std::string::npos) continue;
    const int own = stack_levels().at(folder);
    if (level->second > own || (level->second == own && target != folder)) {
      found.push_back(file.lexically_relative(source_root()).string() + ":" +
                      std::to_string(number) + ": includes " + header + " (" + target + " is " +
                      (level->second > own ? "above " : "beside ") + folder + ")");
    }
  }
  return found;
}

TEST(Stack, NoIncludeRunsBackUp) {
  std::size_t files = 0;
  std::vector<std::string> violations;
  for (const auto& [folder, level] : stack_levels()) {
    for (const auto& file : files_under(source_root(), folder, {".cpp", ".hpp", ".h", ".in"})) {
      ++files;
      for (auto& violation : upward_includes(file, folder)) violations.push_back(violation);
    }
  }
  EXPECT_GT(files, 100u) << "the source tree was not found at " << source_root();
  std::string report;
  for (const auto& violation : violations) report += "\n  " + violation;
  EXPECT_TRUE(violations.empty()) << "includes that run back up the stack "
                                     "(cli -> benchmarks -> evaluation -> descriptors -> "
                                     "datasets):"
                                  << report;
}

// The check itself: a header of a higher folder or of one beside it is reported, one of the
// same or a lower folder is not.
TEST(Stack, ReportsAnUpwardIncludeAndOnlyThat) {
  const std::filesystem::path file =
      std::filesystem::path(testing::TempDir()) / "radarpr_stack_probe.cpp";
  {
    std::ofstream out(file);
    out << "#include <vector>\n#include \"datasets/scan_sequence.hpp\"\n"
           "#include \"descriptors/descriptor.hpp\"\n  #  include <evaluation/metrics.hpp>\n"
           "#include \"cli/program.hpp\"\n";
  }
  const auto found = upward_includes(file, "descriptors");
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NE(found[0].find(":4: includes evaluation/metrics.hpp (evaluation is above descriptors)"),
            std::string::npos)
      << found[0];
  EXPECT_NE(found[1].find(":5: includes cli/program.hpp"), std::string::npos) << found[1];
  EXPECT_TRUE(upward_includes(file, "cli").empty());
  const auto beside = upward_includes(file, "python");
  ASSERT_EQ(beside.size(), 1u);
  EXPECT_NE(beside[0].find(":5: includes cli/program.hpp (cli is beside python)"),
            std::string::npos)
      << beside[0];
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace radarpr::test
