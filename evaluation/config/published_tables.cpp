#include "evaluation/config/published_tables.hpp"

#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace radarpr {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error(fmt::format("{}: {}", file.string(), what));
}

const nlohmann::json& member(const std::filesystem::path& file, const nlohmann::json& object,
                             const std::string& key, const std::string& path) {
  if (!object.is_object() || !object.contains(key)) {
    fail(file, fmt::format("expected the key '{}{}'", path, key));
  }
  return object.at(key);
}

std::vector<std::string> string_list(const std::filesystem::path& file, const nlohmann::json& value,
                                     const std::string& path) {
  if (!value.is_array()) fail(file, fmt::format("'{}' must be an array of names", path));
  std::vector<std::string> names;
  for (const auto& name : value) {
    if (!name.is_string() || name.get<std::string>().empty()) {
      fail(file, fmt::format("'{}' must hold non-empty names, found {}", path, name.dump()));
    }
    names.push_back(name.get<std::string>());
  }
  return names;
}

// null = unknown; otherwise a number in [0, 1] (AUC and F1 are shares).
std::optional<double> share(const std::filesystem::path& file, const nlohmann::json& value,
                            const std::string& path) {
  if (value.is_null()) return std::nullopt;
  if (!value.is_number() || value.get<double>() < 0.0 || value.get<double>() > 1.0) {
    fail(file, fmt::format("'{}' must be null (unknown) or a number in [0, 1], found {}", path,
                           value.dump()));
  }
  return value.get<double>();
}

}  // namespace

PublishedTables read_published_tables(const std::filesystem::path& file) {
  std::ifstream stream(file);
  if (!stream || std::filesystem::is_directory(file)) fail(file, "cannot read the file");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(stream);
  } catch (const nlohmann::json::parse_error& error) {
    fail(file, fmt::format("not valid JSON: {}", error.what()));
  }
  PublishedTables tables;
  tables.file = file;
  const auto& source = member(file, json, "source", "");
  if (!source.is_string()) fail(file, "'source' must be a string naming the paper and its tables");
  tables.source = source.get<std::string>();

  const auto& table_1 = member(file, json, "table_1", "");
  tables.datasets =
      string_list(file, member(file, table_1, "datasets", "table_1."), "table_1.datasets");
  tables.descriptors =
      string_list(file, member(file, table_1, "descriptors", "table_1."), "table_1.descriptors");
  if (table_1.contains("status") && table_1.at("status").is_string()) {
    tables.table_1_status = table_1.at("status").get<std::string>();
  }
  const auto& values = member(file, table_1, "values", "table_1.");
  for (const auto& descriptor : tables.descriptors) {
    const std::string row_path = "table_1.values." + descriptor;
    const auto& row = member(file, values, descriptor, "table_1.values.");
    for (const auto& dataset : tables.datasets) {
      const std::string cell_path = row_path + "." + dataset;
      const auto& cell = member(file, row, dataset, row_path + ".");
      PublishedTables::Scores scores;
      scores.auc = share(file, member(file, cell, "auc", cell_path + "."), cell_path + ".auc");
      scores.f1_max =
          share(file, member(file, cell, "f1_max", cell_path + "."), cell_path + ".f1_max");
      tables.table_1[descriptor][dataset] = scores;
    }
  }

  const auto& table_2 = member(file, json, "table_2", "");
  const auto& rows = member(file, table_2, "rows", "table_2.");
  if (!rows.is_array()) fail(file, "'table_2.rows' must be an array");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string path = fmt::format("table_2.rows.{}.", i);
    PublishedTables::SizeRow row;
    const auto& name = member(file, rows[i], "descriptor", path);
    if (!name.is_string()) fail(file, fmt::format("'{}descriptor' must be a name", path));
    row.descriptor = name.get<std::string>();
    const auto& shape = member(file, rows[i], "shape", path);
    if (!shape.is_array()) fail(file, fmt::format("'{}shape' must be an array", path));
    for (const auto& extent : shape) {
      if (!extent.is_number_integer() || extent.get<long long>() < 1) {
        fail(file, fmt::format("'{}shape' must hold positive integers", path));
      }
      row.shape.push_back(extent.get<int>());
    }
    const auto& bytes = member(file, rows[i], "bytes", path);
    if (!bytes.is_null()) {
      if (!bytes.is_number_integer() || bytes.get<long long>() < 1) {
        fail(file, fmt::format("'{}bytes' must be null (unknown) or a positive integer", path));
      }
      row.bytes = bytes.get<long long>();
    }
    if (rows[i].contains("convention") && rows[i].at("convention").is_string()) {
      row.convention = rows[i].at("convention").get<std::string>();
    }
    tables.table_2.push_back(std::move(row));
  }
  return tables;
}

}  // namespace radarpr
