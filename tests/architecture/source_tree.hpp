#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace radarpr::test {

// The checkout these tests read (the source tree, not the build tree).
std::filesystem::path source_root();

// Every regular file under `root / folder` whose name ends with one of `suffixes`, sorted; the
// build trees CMake may put inside the checkout (build*/ and */build/) and .git/ are skipped.
std::vector<std::filesystem::path> files_under(const std::filesystem::path& root,
                                               const std::string& folder,
                                               const std::vector<std::string>& suffixes);

// The whole file as text. Throws std::runtime_error naming it when it cannot be read.
std::string read_text(const std::filesystem::path& path);

}  // namespace radarpr::test
