#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace radarpr {

// A CSV file as radarpr writes it (csv_line below): the header on the first line, then one row a
// line; fields may be double-quoted (descriptor ids hold commas). What a file describes (the
// radarpr version, experiment, dataset, descriptor, protocol) is in the JSON beside it, so the file
// is plain CSV that any reader takes as it is. '#' lines before the header, which radarpr 0.1.0
// wrote, are skipped. Every accessor throws ResultsError naming the file and line, so a
// truncated or edited file is reported, not half-read.
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

// One CSV line: the fields through csv_field (evaluation/text_escaping.hpp: quoted when they
// need it), separated by commas, ending in '\n'.
std::string csv_line(const std::vector<std::string>& fields);

}  // namespace radarpr
