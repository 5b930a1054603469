#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace radarpr {

// Reads the small text tables datasets ship with (CSV pose files, timestamp lists) one line at
// a time, so a long file is never held whole, and names the file and line in every error:
// "gps/gps.csv:17: column 9 (northing): expected a number, got 'abc'".
class TextTable {
 public:
  enum class Separator {
    comma,       // CSV; spaces around fields are trimmed
    whitespace,  // any run of spaces or tabs
  };

  // Opens `path`; `what` says what the file should be, for the error when it is missing.
  // Throws std::runtime_error naming the file.
  TextTable(const std::filesystem::path& path, Separator separator, const std::string& what);

  // Reads the first non-blank line as column names. Throws when the file is empty.
  void read_header();
  const std::vector<std::string>& header() const { return header_; }
  // Index of the first of `names` present in the header, or nullopt.
  std::optional<std::size_t> find_column(std::initializer_list<std::string_view> names) const;
  // The same, but throws naming the file and the columns it has.
  std::size_t column(std::initializer_list<std::string_view> names) const;

  // Advances to the next non-blank line; false at the end of the file.
  bool next();
  std::size_t line_number() const { return line_number_; }
  std::size_t field_count() const { return fields_.size(); }
  // Throws naming the line when it has fewer than `count` fields.
  void require_fields(std::size_t count) const;

  std::string_view text(std::size_t column) const;
  double number(std::size_t column) const;  // finite
  std::int64_t integer(std::size_t column) const;
  // A Unix time: an integer in µs or ns (told apart by magnitude), or seconds with a decimal
  // point ("1574859771.744660272"); returned in ns.
  std::int64_t unix_time_ns(std::size_t column) const;

  const std::filesystem::path& path() const { return path_; }
  // Throws std::runtime_error "path:line: message".
  [[noreturn]] void fail(const std::string& message) const;

 private:
  std::string describe_column(std::size_t column) const;

  std::filesystem::path path_;
  std::ifstream file_;
  Separator separator_;
  std::string line_;
  std::vector<std::string_view> fields_;
  std::vector<std::string> header_;
  std::size_t line_number_ = 0;
};

// Parses a Unix time as TextTable::unix_time_ns does; nullopt when it is not one (or not a
// plausible time between 2000 and 2100).
std::optional<std::int64_t> parse_unix_time_ns(std::string_view text);

}  // namespace radarpr
