#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace radarpr {

// A CSV file as radarpr writes it: '#' comment lines, one header line, then rows. Fields may be
// double-quoted (descriptor ids hold commas). Every accessor throws ResultsError naming the file
// and line, so a truncated or edited file is reported, not half-read.
class CsvFile {
 public:
  // Throws ResultsError when the file is missing, unreadable or has no header.
  explicit CsvFile(const std::filesystem::path& path);

  std::size_t row_count() const { return rows_.size(); }
  // Throws ResultsError when the header has no such column.
  std::size_t column(const std::string& name) const;
  const std::string& text(std::size_t row, std::size_t column) const;
  double number(std::size_t row, std::size_t column) const;
  // An empty field (an undefined metric) is "no value": returns false.
  bool optional_number(std::size_t row, std::size_t column, double& value) const;
  // A frame index: a whole number >= 0 and, when `limit` is given, < limit ("what" names the
  // limit in the message, e.g. "the 160 frames of trajectory.csv").
  std::size_t index(std::size_t row, std::size_t column) const;
  std::size_t index(std::size_t row, std::size_t column, std::size_t limit,
                    const std::string& what) const;
  const std::filesystem::path& path() const { return path_; }
  // Throws ResultsError "<path>: line <n>: <what>" for the file line of `row`.
  [[noreturn]] void fail(std::size_t row, const std::string& what) const;

 private:
  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> line_numbers_;  // the file line of each row, for messages
};

// Splits one CSV line; "a,\"b,c\"" -> {a, b,c}. Doubled quotes inside quotes are one quote.
std::vector<std::string> split_csv_line(const std::string& line);

}  // namespace radarpr
