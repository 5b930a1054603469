// MappedFile: a file's bytes through a read-only memory map, and clear errors for what cannot be
// mapped.
#include "datasets/mapped_file.hpp"

#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace radarpr {
namespace {

namespace fs = std::filesystem;

class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& bytes) {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() / ("radarpr_mapped_file_test_" + std::to_string(::getpid()) +
                                         "_" + std::to_string(counter++));
    std::ofstream(path_, std::ios::binary) << bytes;
  }
  ~TemporaryFile() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string as_text(std::span<const std::byte> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

TEST(MappedFile, MapsTheWholeFileAndReadsItAgainAfterARelease) {
  std::string bytes(3 * 4096 + 17, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7 % 251);
  const TemporaryFile file(bytes);
  const MappedFile mapped(file.path());
  EXPECT_EQ(mapped.size(), bytes.size());
  EXPECT_EQ(mapped.path(), file.path());
  EXPECT_EQ(as_text(mapped.bytes()), bytes);
  mapped.release(0, mapped.size());
  mapped.release(100, 5000);
  mapped.release(mapped.size() + 10, 3);  // beyond the end: nothing
  EXPECT_EQ(as_text(mapped.bytes()), bytes);
}

TEST(MappedFile, MovesOwnershipOfTheMap) {
  const TemporaryFile file("radar");
  MappedFile first(file.path());
  MappedFile second(std::move(first));
  EXPECT_EQ(as_text(second.bytes()), "radar");
  EXPECT_EQ(first.size(), 0u);  // NOLINT(bugprone-use-after-move): moved-from is empty
  MappedFile third;
  third = std::move(second);
  EXPECT_EQ(as_text(third.bytes()), "radar");
}

TEST(MappedFile, AnEmptyFileMapsToNoBytes) {
  const TemporaryFile file("");
  const MappedFile mapped(file.path());
  EXPECT_EQ(mapped.size(), 0u);
  EXPECT_TRUE(mapped.bytes().empty());
}

TEST(MappedFile, WhatCannotBeMappedIsAnErrorNamingTheFile) {
  const fs::path missing = fs::temp_directory_path() / "radarpr_mapped_file_test_missing";
  try {
    const MappedFile mapped(missing);
    FAIL() << "mapped a missing file";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("cannot open"), std::string::npos) << error.what();
  }
  try {
    const MappedFile mapped(fs::temp_directory_path());
    FAIL() << "mapped a folder";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(fs::temp_directory_path().string()), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace radarpr
