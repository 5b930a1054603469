#include "datasets/real/text_table.hpp"

#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::expect_error;
using test::TempTree;

TEST(UnixTime, TellsMicrosecondsNanosecondsAndSecondsApart) {
  EXPECT_EQ(parse_unix_time_ns("1547131046353776"), 1'547'131'046'353'776'000);     // µs
  EXPECT_EQ(parse_unix_time_ns("1628184886551599081"), 1'628'184'886'551'599'081);  // ns
  // Oxford gps.csv pads its µs with zeros.
  EXPECT_EQ(parse_unix_time_ns("0001547131010502681"), 1'547'131'010'502'681'000);
  // Seconds with a fraction, digit by digit (a double would round the last digits).
  EXPECT_EQ(parse_unix_time_ns("1574859771.744660272"), 1'574'859'771'744'660'272);
  EXPECT_EQ(parse_unix_time_ns("1574859771.5"), 1'574'859'771'500'000'000);
  for (const char* bad : {"", "abc", "12", "1574859771.", "1574859771.5x", "-1547131046353776"}) {
    EXPECT_FALSE(parse_unix_time_ns(bad).has_value()) << bad;
  }
}

TEST(TextTable, ReadsCsvWithHeaderAndSkipsBlankLines) {
  TempTree tree;
  const auto path = tree.write("poses.csv", "timestamp, x ,y\n\n1600000000.25,1.5,-2\n");
  TextTable table(path, TextTable::Separator::comma, "poses");
  table.read_header();
  EXPECT_EQ(table.column({"x"}), 1u);  // spaces around names are trimmed
  ASSERT_TRUE(table.next());
  EXPECT_EQ(table.line_number(), 3u);
  EXPECT_EQ(table.unix_time_ns(0), 1'600'000'000'250'000'000);
  EXPECT_DOUBLE_EQ(table.number(1), 1.5);
  EXPECT_DOUBLE_EQ(table.number(2), -2.0);
  EXPECT_FALSE(table.next());
}

// Spreadsheets save "CSV UTF-8" with a byte order mark: the first column is still "timestamp"
// (it used to be "\ufefftimestamp", and the poses were refused for a missing column).
TEST(TextTable, AcceptsAUtf8ByteOrderMark) {
  TempTree tree;
  const auto path =
      tree.write("poses.csv", "\xEF\xBB\xBFtimestamp,x,y,yaw\n1700000000.000,0.0,0.0,0.00\n");
  TextTable table(path, TextTable::Separator::comma, "poses");
  table.read_header();
  EXPECT_EQ(table.column({"timestamp"}), 0u);
  ASSERT_TRUE(table.next());
  EXPECT_EQ(table.unix_time_ns(0), 1'700'000'000'000'000'000);
  // Only at the start of the file: elsewhere the bytes are data, and refused as a number.
  const auto later = tree.write("later.csv", "t,x\n\xEF\xBB\xBF" "1,2\n");
  TextTable second(later, TextTable::Separator::comma, "poses");
  second.read_header();
  ASSERT_TRUE(second.next());
  expect_error<std::runtime_error>([&] { second.number(0); }, {later.string() + ":2:"});
}

TEST(TextTable, ErrorsNameFileLineAndColumn) {
  TempTree tree;
  const auto path = tree.write("gps.csv",
                               "timestamp,northing,easting\n1600000000000000,1,2\n"
                               "1600000000100000,abc,2\n1600000000200000,1\n");
  const std::string file = path.string();
  TextTable table(path, TextTable::Separator::comma, "GPS");
  table.read_header();
  ASSERT_TRUE(table.next());
  EXPECT_DOUBLE_EQ(table.number(1), 1.0);
  ASSERT_TRUE(table.next());
  expect_error<std::runtime_error>([&] { table.number(1); },
                                   {file + ":3:", "column 2 (northing)", "'abc'"});
  ASSERT_TRUE(table.next());
  expect_error<std::runtime_error>([&] { table.number(2); },
                                   {file + ":4:", "at least 3 fields", "got 2"});
  expect_error<std::runtime_error>(
      [&] {
        table.column({"utm_easting", "east"});
      },
      {file, "utm_easting or east", "timestamp, northing, easting"});
}

TEST(TextTable, MissingAndEmptyFilesAreNamed) {
  TempTree tree;
  expect_error<std::runtime_error>(
      [&] { TextTable(tree.path("nope.csv"), TextTable::Separator::comma, "the poses"); },
      {tree.path("nope.csv").string(), "file not found", "the poses"});
  const auto empty = tree.write("empty.csv", "");
  TextTable table(empty, TextTable::Separator::comma, "the poses");
  expect_error<std::runtime_error>([&] { table.read_header(); }, {empty.string(), "empty"});
}

TEST(TextTable, SplitsOnRunsOfWhitespace) {
  TempTree tree;
  const auto path = tree.write("radar.timestamps", "1547131046353776 1\n1547131046606586\t 0\n");
  TextTable table(path, TextTable::Separator::whitespace, "timestamps");
  ASSERT_TRUE(table.next());
  EXPECT_EQ(table.integer(1), 1);
  ASSERT_TRUE(table.next());
  EXPECT_EQ(table.field_count(), 2u);
  EXPECT_EQ(table.unix_time_ns(0), 1'547'131'046'606'586'000);
  EXPECT_EQ(table.integer(1), 0);
}

}  // namespace
}  // namespace radarpr
