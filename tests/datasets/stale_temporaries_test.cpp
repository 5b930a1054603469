// Temporary files of writers killed before their rename are removed; those of a live process
// and every other file are kept.
#include "datasets/stale_temporaries.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace radarpr {
namespace {

namespace fs = std::filesystem;

TEST(StaleTemporaries, OnlyThoseOfEndedProcessesAreRemoved) {
  const fs::path folder =
      fs::temp_directory_path() / fmt::format("radarpr_stale_tmp_{}", ::getpid());
  fs::remove_all(folder);
  fs::create_directories(folder / "sub");
  const long self = ::getpid();
  // 999999999 is beyond any process id: an ended writer.
  const std::vector<std::string> stale = {
      ".1700000000000000.png.tmp-999999999-9f3a",  // a rendered scan
      "ab12cd34.bin.tmp-999999999-9f3a-0",         // a descriptor cache entry
      "values.npy.tmp.999999999.3",                // an exported file
  };
  const std::vector<std::string> kept = {
      fmt::format(".1700000000000000.png.tmp-{}-9f3a", self),  // being written now
      fmt::format("ab12cd34.bin.tmp-{}-9f3a-0", self),
      "1700000000000000.png",
      "notes.tmp",
      "x.tmp-abc",
      "x.tmp-12ab",
      "x.tmp-1234567890123-1",  // no process id
  };
  for (const auto& name : stale) std::ofstream(folder / name) << "half";
  for (const auto& name : kept) std::ofstream(folder / name) << "whole";
  std::ofstream(folder / "sub" / stale[0]) << "below: not this folder's";

  remove_stale_temporary_files(folder);
  for (const auto& name : stale) EXPECT_FALSE(fs::exists(folder / name)) << name;
  for (const auto& name : kept) EXPECT_TRUE(fs::exists(folder / name)) << name;
  EXPECT_TRUE(fs::exists(folder / "sub" / stale[0]));
  remove_stale_temporary_files(folder / "missing");  // no folder: nothing to do, no error
  fs::remove_all(folder);
}

TEST(StaleTemporaries, ALiveProcessHasNotEnded) {
  EXPECT_FALSE(process_has_ended(::getpid()));
  EXPECT_TRUE(process_has_ended(999999999));
}

}  // namespace
}  // namespace radarpr
