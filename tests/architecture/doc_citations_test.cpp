// Every documentation file the project cites exists: README.md, the docs/ pages, the configs'
// and results' notes, code comments and messages, and the committed HTML reports name pages such
// as `docs/cli.md` or `protocols.md`; each must be a file of the checkout.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "source_tree.hpp"

namespace radarpr::test {
namespace {

namespace fs = std::filesystem;

// Names of files radarpr writes into a results folder (and the real samples' notes outside the
// checkout): mentioned as outputs, not cited as documentation.
bool names_an_output(const std::string& name) {
  static const std::set<std::string> outputs = {"summary.md", "table1.md", "table2.md",
                                                "table3.md",  "table4.md", "compare.md",
                                                "bench.md",   "SOURCE.md"};
  return outputs.contains(name);
}

// A citation resolves when it names a file relative to the checkout or to the citing file, or,
// given as a bare name, a page of docs/.
bool resolves(const fs::path& root, const fs::path& citing_file, const std::string& cited) {
  const fs::path path(cited);
  if (fs::exists(root / path) || fs::exists(citing_file.parent_path() / path)) return true;
  return !path.has_parent_path() && fs::exists(root / "docs" / path);
}

// "file:line: cites X, which does not exist" for each unresolved citation in `file`.
std::vector<std::string> missing_citations(const fs::path& root, const fs::path& file) {
  static const std::regex citation(R"(([A-Za-z0-9_./-]*?)([A-Za-z0-9_-]+\.md)(?![A-Za-z0-9_]))");
  std::vector<std::string> missing;
  std::istringstream lines(read_text(file));
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (line.find(".md") == std::string::npos)
      continue;  // std::regex is slow: most lines cite nothing
    for (auto it = std::sregex_iterator(line.begin(), line.end(), citation);
         it != std::sregex_iterator(); ++it) {
      std::string cited = (*it)[1].str() + (*it)[2].str();
      if (names_an_output((*it)[2].str()) || cited.starts_with("../shared/")) continue;
      if (cited.starts_with("/")) cited.erase(0, 1);
      if (!resolves(root, file, cited)) {
        missing.push_back(file.lexically_relative(root).string() + ":" + std::to_string(number) +
                          ": cites " + cited + ", which does not exist");
      }
    }
  }
  return missing;
}

// The files that cite documentation: prose, code (comments, messages, the report page's text),
// scripts, the CI's files and the committed report pages.
std::vector<fs::path> citing_files(const fs::path& root) {
  std::vector<fs::path> files = {root / "README.md", root / "CMakeLists.txt",
                                 root / "pyproject.toml"};
  const std::vector<std::string> code = {".cpp", ".hpp", ".h",     ".in",
                                         ".py",  ".sh",  ".cmake", "CMakeLists.txt"};
  for (const std::string folder :
       {"datasets", "descriptors", "evaluation", "benchmarks", "cli", "python", "tests", "cmake"}) {
    for (auto& file : files_under(root, folder, code)) {
      // This test's own probes cite missing pages on purpose.
      if (file.filename() != "doc_citations_test.cpp") files.push_back(file);
    }
  }
  for (auto& file : files_under(root, "examples", code)) files.push_back(file);
  // .ci/: the CI script (no suffix) and the package lists.
  for (auto& file : files_under(root, ".ci", {""})) files.push_back(file);
  for (auto& file : files_under(root, "docs", {".md"})) files.push_back(file);
  for (auto& file : files_under(root, "configs", {".md", ".json"})) files.push_back(file);
  for (auto& file : files_under(root, "results", {"README.md", "index.html"})) {
    files.push_back(file);
  }
  return files;
}

TEST(DocCitations, EveryCitedDocumentExists) {
  const fs::path root = source_root();
  const auto files = citing_files(root);
  EXPECT_GT(files.size(), 100u) << "the source tree was not found at " << root;
  std::string report;
  for (const auto& file : files) {
    for (const auto& missing : missing_citations(root, file)) report += "\n  " + missing;
  }
  EXPECT_TRUE(report.empty()) << "documents cited but not in the checkout:" << report;
}

// The check itself, on a file of its own: a missing page is reported with its line, pages that
// exist (by path, relative to the citing file, or bare in docs/) and output names are not.
TEST(DocCitations, ReportsAMissingPageAndOnlyThat) {
  const fs::path root = source_root();
  const fs::path file = fs::path(testing::TempDir()) / "radarpr_citation_probe.md";
  // The missing page's name is assembled here so that this source itself cites no missing file.
  const std::string missing_page = std::string("docs/") + "no_such_page" + ".md";
  {
    std::ofstream out(file);
    out << "See docs/cli.md and `protocols.md` (results/<experiment>/summary.md).\n"
           "The [layout](README.md) is fine, "
        << missing_page
        << " is not,\n"
           "and neither is `nowhere.md`; table1.{md,csv} is an output.\n";
  }
  const auto missing = missing_citations(root, file);
  ASSERT_EQ(missing.size(), 2u) << (missing.empty() ? "" : missing[0]);
  EXPECT_NE(missing[0].find(":2: cites " + missing_page + ", which does not exist"),
            std::string::npos)
      << missing[0];
  EXPECT_NE(missing[1].find(":3: cites nowhere.md"), std::string::npos) << missing[1];
  fs::remove(file);
}

}  // namespace
}  // namespace radarpr::test
