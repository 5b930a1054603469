// "did you mean": a typo finds the word meant, a different word finds nothing.
#include "cli/suggestion.hpp"

#include <gtest/gtest.h>

namespace radarpr::cli {
namespace {

const std::vector<std::string> kVerbs = {"run",  "report",  "compare",  "inspect",
                                         "list", "extract", "simulate", "bench"};

TEST(Suggestion, ATypoFindsTheWordMeant) {
  EXPECT_EQ(closest_match("rn", kVerbs), "run");
  EXPECT_EQ(closest_match("reprot", kVerbs), "report");  // two letters swapped: one edit
  EXPECT_EQ(closest_match("lsit", kVerbs), "list");
  EXPECT_EQ(closest_match("simulat", kVerbs), "simulate");
  EXPECT_EQ(closest_match("benhc", kVerbs), "bench");
  EXPECT_EQ(closest_match("--ot", {"--out", "--set", "--quiet"}), "--out");
  EXPECT_EQ(closest_match("--treads", {"--threads", "--quiet"}), "--threads");
  EXPECT_EQ(closest_match("--range-resolutoin", {"--range-resolution", "--layout"}),
            "--range-resolution");
}

TEST(Suggestion, TheBeginningOfOneWordFindsIt) {
  EXPECT_EQ(closest_match("sim", kVerbs), "simulate");
  EXPECT_EQ(closest_match("--no", {"--no-cache", "--out"}), "--no-cache");
  EXPECT_EQ(closest_match("r", kVerbs), std::nullopt);  // run? report? no guess
}

TEST(Suggestion, AnotherWordFindsNothing) {
  EXPECT_EQ(closest_match("frobnicate", kVerbs), std::nullopt);
  EXPECT_EQ(closest_match("--bogus", {"--out", "--set", "--quiet"}), std::nullopt);
  EXPECT_EQ(closest_match("--", {"--out"}), std::nullopt);
  EXPECT_EQ(closest_match("x", {}), std::nullopt);
}

}  // namespace
}  // namespace radarpr::cli
