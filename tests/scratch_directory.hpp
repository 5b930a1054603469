#pragma once

// A test's own empty folder, for the tests that run programs on files.
#include <unistd.h>

#include <filesystem>
#include <string_view>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace radarpr::testing {

// PREFIX_TEST_PID under the system's temporary folder, emptied and created: named after the
// running test and the process, so that tests run in parallel (ctest -j) never share one.
inline std::filesystem::path fresh_test_directory(std::string_view prefix) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      fmt::format("{}_{}_{}", prefix,
                  ::testing::UnitTest::GetInstance()->current_test_info()->name(), ::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace radarpr::testing
