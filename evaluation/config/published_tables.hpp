#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace radarpr {

// A paper's published numbers (configs/paper/published/*.json), read so that a run can show them
// beside its own (docs/paper-table.md). A value the file leaves null is unknown, never 0.
struct PublishedTables {
  std::filesystem::path file;
  std::string source;                 // the paper and its tables
  std::string table_1_status;         // why values are missing, when the file says so
  std::vector<std::string> datasets;  // Table I's columns, in order
  std::vector<std::string> descriptors;
  struct Scores {
    std::optional<double> auc;
    std::optional<double> f1_max;
  };
  // [descriptor][dataset]
  std::map<std::string, std::map<std::string, Scores>> table_1;
  struct SizeRow {
    std::string descriptor;
    std::vector<int> shape;
    std::optional<long long> bytes;
    std::string convention;  // what the bytes count, when the file says
  };
  std::vector<SizeRow> table_2;
};

// Reads a published-tables file; a missing, unreadable or malformed file is a
// std::runtime_error naming the file and the key that was expected.
PublishedTables read_published_tables(const std::filesystem::path& file);

// What a config's "published" object asks for: the tables and which run dataset stands for which
// published column (several run datasets may stand for one; their values are averaged).
struct PublishedComparisonConfig {
  PublishedTables tables;
  std::vector<std::pair<std::string, std::string>> datasets;  // (run dataset, published dataset)
};

}  // namespace radarpr
