// The one CSV format of radarpr's results: csv_line writes it, CsvFile reads it back.
#include "evaluation/results/csv_file.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evaluation/results/results_error.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path path = fs::path(testing::TempDir()) / ("radarpr_csv_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(CsvFormat, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csv_field("referee"), "referee");
  EXPECT_EQ(csv_field("referee_r:kernel=box,z_q=3"), "\"referee_r:kernel=box,z_q=3\"");
  EXPECT_EQ(csv_field("a \"quoted\" label"), "\"a \"\"quoted\"\" label\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field(""), "");
  EXPECT_EQ(csv_line({"a", "b,c", ""}), "a,\"b,c\",\n");
}

TEST(CsvFormat, WhatIsWrittenReadsBack) {
  const std::vector<std::string> header = {"descriptor", "label", "roc_auc"};
  const std::vector<std::string> row = {"referee_r:kernel=box,z_q=3", "R \"box\", z=3", "0.5"};
  const fs::path path = write_temp("round_trip.csv", csv_line(header) + csv_line(row));
  const CsvFile csv(path);
  ASSERT_EQ(csv.row_count(), 1u);
  for (std::size_t c = 0; c < header.size(); ++c)
    EXPECT_EQ(csv.text(0, csv.column(header[c])), row[c]);
  EXPECT_EQ(split_csv_line(csv_line(row).substr(0, csv_line(row).size() - 1)), row);
}

TEST(CsvFormat, TheHeaderIsTheFirstLine) {
  // Plain CSV: a '#' line after the header is a row like any other, and a bad one.
  const fs::path path = write_temp("comment.csv", "a,b\n1,2\n# note\n");
  try {
    CsvFile csv(path);
    ADD_FAILURE() << "a comment line among the rows was accepted";
  } catch (const ResultsError& error) {
    EXPECT_NE(std::string(error.what()).find("line 3 has 1 fields, the header has 2"),
              std::string::npos)
        << error.what();
  }
  // Files of radarpr 0.1.0 began with '#' lines: those before the header are skipped.
  const CsvFile old(write_temp("old.csv", "# radarpr 0.1.0\n# experiment: x\na,b\n1,2\n"));
  ASSERT_EQ(old.row_count(), 1u);
  EXPECT_EQ(old.text(0, old.column("b")), "2");
}

}  // namespace
}  // namespace radarpr
