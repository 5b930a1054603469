#include "descriptors/precomputed/precomputed.hpp"

#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/npy_file.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "tests/datasets/dataset_tree.hpp"

namespace radarpr {
namespace {

using test::TempTree;

std::vector<ScanRecord> scans_at(const std::vector<std::int64_t>& times) {
  std::vector<ScanRecord> scans;
  for (const std::int64_t t : times) scans.push_back({t, {}, "scan"});
  return scans;
}

std::string error_of(const auto& call) {
  try {
    call();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "no error";
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

TEST(Precomputed, MatchesNpyRowsToScansByTimeWithinTheTolerance) {
  const TempTree tree;
  const std::vector<float> values{1, 2, 3, 4, 5, 6};  // 3 rows x 2
  write_npy(tree.path("v.npy"), {3, 2}, std::span<const float>(values));
  const std::vector<std::int64_t> times{1000000, 2000000, 3000000};
  write_npy(tree.path("t.npy"), {3}, std::span<const std::int64_t>(times));
  const PrecomputedTable table =
      read_precomputed_table(tree.path("v.npy"), tree.path("t.npy"), PrecomputedTimeUnit::ns);
  EXPECT_EQ(table.dimension, 2u);
  // Scans 0.3 ms off their rows: matched with a 0.5 ms tolerance.
  const auto matched =
      match_rows_to_scans(table, scans_at({1300000, 1700000, 3000000}), 500000, "seq");
  ASSERT_EQ(matched.size(), 3u);
  EXPECT_EQ(matched[1].values, (std::vector<float>{3, 4}));
  EXPECT_EQ(matched[1].rows, 2);
  EXPECT_EQ(matched[1].cols, 1);
  // With 0.1 ms, scans 0 and 1 have no row, and rows 0 and 1 no scan.
  EXPECT_CONTAINS(
      error_of([&] {
        match_rows_to_scans(table, scans_at({1300000, 1700000, 3000000}), 100000, "seq");
      }),
      "2 of 3 scans have no row within 100000 ns: scan 0 (1300000 ns; nearest row 0 "
      "is 300000 ns away)");
}

TEST(Precomputed, ReadsCsvWithATimestampColumnAndFloat64Seconds) {
  const TempTree tree;
  std::ofstream(tree.path("v.csv")) << "a,timestamp,b\n0.5,1.25,7\n1.5,2.5,8\n";
  const PrecomputedTable table =
      read_precomputed_table(tree.path("v.csv"), {}, PrecomputedTimeUnit::s);
  EXPECT_EQ(table.timestamps_ns, (std::vector<std::int64_t>{1250000000, 2500000000}));
  EXPECT_EQ(table.values, (std::vector<float>{0.5f, 7, 1.5f, 8}));

  const std::vector<double> seconds{1.25, 2.5};
  write_npy(tree.path("t.npy"), {2}, std::span<const double>(seconds));
  const std::vector<double> values{9, 10};
  write_npy(tree.path("v.npy"), {2}, std::span<const double>(values));
  const PrecomputedTable from_npy =
      read_precomputed_table(tree.path("v.npy"), tree.path("t.npy"), PrecomputedTimeUnit::s);
  EXPECT_EQ(from_npy.timestamps_ns, table.timestamps_ns);
  EXPECT_EQ(from_npy.dimension, 1u);
}

TEST(Precomputed, RefusesMissingExtraDuplicateAndUnsortedRowsListingThem) {
  const TempTree tree;
  const std::vector<float> values(5, 1.0f);
  write_npy(tree.path("v.npy"), {5, 1}, std::span<const float>(values));
  const auto table_with = [&](const std::vector<std::int64_t>& times) {
    write_npy(tree.path("t.npy"), {times.size()}, std::span<const std::int64_t>(times));
    return read_precomputed_table(tree.path("v.npy"), tree.path("t.npy"), PrecomputedTimeUnit::ns);
  };
  EXPECT_CONTAINS(error_of([&] {
                    table_with({10, 20, 20, 30, 40});
                  }),
                  "1 rows are not: row 2 (20 ns) repeats row 1 (20 ns)");
  EXPECT_CONTAINS(error_of([&] {
                    table_with({10, 30, 20, 40, 50});
                  }),
                  "row 2 (20 ns) is before row 1 (30 ns)");
  EXPECT_CONTAINS(error_of([&] { table_with({10, 20, 30}); }), "5 rows of values but 3 times");

  const PrecomputedTable table = table_with({10, 20, 30, 40, 50});
  // A row without a scan.
  EXPECT_CONTAINS(error_of([&] {
                    match_rows_to_scans(table, scans_at({10, 20, 30, 40}), 0, "s");
                  }),
                  "1 of 5 rows match no scan within 0 ns: row 4 (50 ns)");
  // A scan without a row.
  EXPECT_CONTAINS(
      error_of([&] {
        match_rows_to_scans(table, scans_at({10, 20, 30, 40, 50, 60}), 0, "s");
      }),
      "1 of 6 scans have no row within 0 ns: scan 5 (60 ns; nearest row 4 is 10 ns away)");
  // One row claimed by two scans: the tolerance is too wide.
  EXPECT_CONTAINS(error_of([&] {
                    match_rows_to_scans(table, scans_at({10, 12, 30, 40, 50}), 5, "s");
                  }),
                  "row 0 (10 ns) is within the tolerance of both scan 0 and scan 1");
}

TEST(Precomputed, RefusesBadFilesNamingThem) {
  const TempTree tree;
  EXPECT_CONTAINS(error_of([&] {
                    read_precomputed_table(tree.path("absent.npy"), tree.path("t.npy"),
                                           PrecomputedTimeUnit::ns);
                  }),
                  "absent.npy: cannot open");
  const std::vector<std::uint8_t> bytes{1, 2};
  write_npy(tree.path("u8.npy"), {2, 1}, std::span<const std::uint8_t>(bytes));
  EXPECT_CONTAINS(error_of([&] {
                    read_precomputed_table(tree.path("u8.npy"), tree.path("t.npy"),
                                           PrecomputedTimeUnit::ns);
                  }),
                  "values must be float32 or float64, got uint8");
  const std::vector<float> nan{1.0f, std::numeric_limits<float>::quiet_NaN()};
  write_npy(tree.path("nan.npy"), {2, 1}, std::span<const float>(nan));
  EXPECT_CONTAINS(error_of([&] {
                    read_precomputed_table(tree.path("nan.npy"), tree.path("t.npy"),
                                           PrecomputedTimeUnit::ns);
                  }),
                  "row 1 column 0 is nan");
  std::ofstream(tree.path("no_time.csv")) << "a,b\n1,2\n";
  EXPECT_CONTAINS(error_of([&] {
                    read_precomputed_table(tree.path("no_time.csv"), {}, PrecomputedTimeUnit::ns);
                  }),
                  "no 'timestamp' column");
  std::ofstream(tree.path("ragged.csv")) << "a,timestamp\n1,2\n3\n";
  EXPECT_CONTAINS(error_of([&] {
                    read_precomputed_table(tree.path("ragged.csv"), {}, PrecomputedTimeUnit::ns);
                  }),
                  "ragged.csv:3");
}

TEST(Precomputed, RegisteredWithPathParametersAndPlaceholders) {
  const TempTree tree;
  const std::vector<float> values{3, 4, 0, 0};
  std::filesystem::create_directories(tree.path("town/query"));
  write_npy(tree.path("town/query/v.npy"), {2, 2}, std::span<const float>(values));
  const std::vector<std::int64_t> times{5, 6};
  write_npy(tree.path("town/query/t.npy"), {2}, std::span<const std::int64_t>(times));
  const DescriptorInstance instance = DescriptorRegistry::global().create(
      "precomputed",
      nlohmann::json{{"values", (tree.root() / "{dataset}/{role}/v.npy").string()},
                     {"timestamps", (tree.root() / "{dataset}/{role}/t.npy").string()},
                     {"distance", "cosine"}});
  EXPECT_EQ(instance.descriptor->shape({}), (DescriptorShape{0, 1}));  // unknown before reading
  const auto* external = external_values_of(*instance.descriptor);
  ASSERT_NE(external, nullptr);
  const auto records = scans_at({5, 6});
  const auto read = external->values_for({"town", "query", "seq", records});
  EXPECT_EQ(instance.descriptor->shape({}), (DescriptorShape{2, 1}));
  EXPECT_EQ(read[0].values, (std::vector<float>{3, 4}));
  // Cosine, with the zero vector's convention.
  EXPECT_DOUBLE_EQ(instance.descriptor->distance(read[0], read[0]), 0.0);
  EXPECT_DOUBLE_EQ(instance.descriptor->distance(read[0], read[1]), 0.5);
  EXPECT_THROW(instance.descriptor->extract(PolarImage{}), std::invalid_argument);
  // The id's separators are refused inside a path.
  EXPECT_THROW(
      DescriptorRegistry::global().create("precomputed", nlohmann::json{{"values", "a,b.npy"}}),
      ParameterError);
  // The defaults construct (listings, benchmarks iterate the registry).
  EXPECT_EQ(DescriptorRegistry::global().create_from_id("precomputed").descriptor->shape({}),
            (DescriptorShape{0, 1}));
}

}  // namespace
}  // namespace radarpr
