#include "evaluation/results/csv_file.hpp"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "evaluation/results/results_error.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(fields[i]);
  }
  return line + "\n";
}

CsvFile::CsvFile(const std::filesystem::path& path) : path_(path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw ResultsError(fmt::format("{}: missing or unreadable (a CSV file)", path.string()));
  std::string line;
  std::size_t number = 0;
  while (std::getline(file, line)) {
    ++number;
    if (line.empty() || (header_.empty() && line.starts_with('#'))) continue;
    std::vector<std::string> fields = split_csv_line(line);
    if (header_.empty()) {
      header_ = std::move(fields);
      continue;
    }
    if (fields.size() != header_.size()) {
      throw ResultsError(fmt::format("{}: line {} has {} fields, the header has {}", path.string(),
                                     number, fields.size(), header_.size()));
    }
    rows_.push_back(std::move(fields));
    line_numbers_.push_back(number);
  }
  if (header_.empty()) {
    throw ResultsError(fmt::format("{}: empty; a CSV header line was expected", path.string()));
  }
}

std::size_t CsvFile::column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return i;
  }
  throw ResultsError(fmt::format("{}: the header has no column '{}'", path_.string(), name));
}

void CsvFile::fail(std::size_t row, const std::string& what) const {
  throw ResultsError(fmt::format("{}: line {}: {}", path_.string(), line_numbers_[row], what));
}

const std::string& CsvFile::text(std::size_t row, std::size_t column) const {
  return rows_.at(row).at(column);
}

double CsvFile::number(std::size_t row, std::size_t column) const {
  double value = 0.0;
  if (!optional_number(row, column, value)) {
    fail(row, fmt::format("column '{}' is empty; a number was expected", header_[column]));
  }
  return value;
}

bool CsvFile::optional_number(std::size_t row, std::size_t column, double& value) const {
  const std::string& field = text(row, column);
  if (field.empty()) return false;
  std::size_t used = 0;
  try {
    value = std::stod(field, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != field.size() || !std::isfinite(value)) {
    fail(row, fmt::format("column '{}' holds '{}'; a finite number was expected", header_[column],
                          field));
  }
  return true;
}

std::size_t CsvFile::index(std::size_t row, std::size_t column) const {
  const double value = number(row, column);
  // 2^53: every whole double below it is exact, and far beyond any sequence length.
  if (value < 0.0 || value != std::floor(value) || value > 9007199254740992.0) {
    fail(row, fmt::format("column '{}' holds '{}'; a whole number >= 0 was expected",
                          header_[column], text(row, column)));
  }
  return static_cast<std::size_t>(value);
}

std::size_t CsvFile::index(std::size_t row, std::size_t column, std::size_t limit,
                           const std::string& what) const {
  const std::size_t value = index(row, column);
  if (value >= limit) {
    fail(row, fmt::format("column '{}' holds {}; beyond {} (< {} expected)", header_[column], value,
                          what, limit));
  }
  return value;
}

}  // namespace radarpr
