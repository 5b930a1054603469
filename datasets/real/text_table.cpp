#include "datasets/real/text_table.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "datasets/polar_png.hpp"

namespace radarpr {
namespace {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line, TextTable::Separator separator) {
  std::vector<std::string_view> fields;
  if (separator == TextTable::Separator::comma) {
    std::size_t start = 0;
    while (true) {
      const auto comma = line.find(',', start);
      fields.push_back(trim(line.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    return fields;
  }
  std::size_t position = 0;
  while (true) {
    const auto start = line.find_first_not_of(" \t\r", position);
    if (start == std::string_view::npos) break;
    const auto end = line.find_first_of(" \t\r", start);
    fields.push_back(line.substr(start, end - start));
    if (end == std::string_view::npos) break;
    position = end;
  }
  return fields;
}

constexpr std::int64_t kEarliestUnixS = 946'684'800;  // 2000-01-01
constexpr std::int64_t kLatestUnixS = 4'102'444'800;  // 2100-01-01

std::optional<std::int64_t> parse_int64(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

std::optional<std::int64_t> parse_unix_time_ns(std::string_view text) {
  const auto dot = text.find('.');
  if (dot == std::string_view::npos) {
    const auto stamp = parse_int64(text);
    return stamp ? unix_stamp_to_ns(*stamp) : std::nullopt;
  }
  // Seconds with a fraction, parsed digit by digit: a double would lose the nanoseconds.
  const auto seconds = parse_int64(text.substr(0, dot));
  const std::string_view fraction = text.substr(dot + 1);
  if (!seconds || *seconds < kEarliestUnixS || *seconds >= kLatestUnixS || fraction.empty()) {
    return std::nullopt;
  }
  std::int64_t nanoseconds = 0;
  for (std::size_t i = 0; i < fraction.size(); ++i) {
    const char digit = fraction[i];
    if (digit < '0' || digit > '9') return std::nullopt;
    if (i < 9) nanoseconds = nanoseconds * 10 + (digit - '0');
  }
  for (std::size_t i = fraction.size(); i < 9; ++i) nanoseconds *= 10;
  return *seconds * 1'000'000'000 + nanoseconds;
}

TextTable::TextTable(const std::filesystem::path& path, Separator separator,
                     const std::string& what)
    : path_(path), separator_(separator) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path_, error)) {
    throw std::runtime_error(fmt::format(
        "{}: {}, expected {}", path_.string(),
        std::filesystem::exists(path_, error) ? "not a regular file" : "file not found", what));
  }
  file_.open(path_);
  if (!file_) {
    throw std::runtime_error(
        fmt::format("{}: cannot be opened, expected {}", path_.string(), what));
  }
}

void TextTable::fail(const std::string& message) const {
  throw std::runtime_error(fmt::format("{}:{}: {}", path_.string(), line_number_, message));
}

bool TextTable::next() {
  while (std::getline(file_, line_)) {
    ++line_number_;
    // A UTF-8 byte order mark (spreadsheets save CSVs with one) is not part of the first field.
    if (line_number_ == 1 && line_.starts_with("\xEF\xBB\xBF")) line_.erase(0, 3);
    if (trim(line_).empty()) continue;
    fields_ = split(line_, separator_);
    return true;
  }
  fields_.clear();
  return false;
}

void TextTable::read_header() {
  if (!next()) {
    throw std::runtime_error(
        fmt::format("{}: the file is empty, expected a header line", path_.string()));
  }
  header_.assign(fields_.begin(), fields_.end());
}

std::optional<std::size_t> TextTable::find_column(
    std::initializer_list<std::string_view> names) const {
  for (const std::string_view name : names) {
    for (std::size_t i = 0; i < header_.size(); ++i) {
      if (header_[i] == name) return i;
    }
  }
  return std::nullopt;
}

std::size_t TextTable::column(std::initializer_list<std::string_view> names) const {
  if (const auto found = find_column(names)) return *found;
  throw std::runtime_error(fmt::format("{}: the header has no column {} (columns: {})",
                                       path_.string(), fmt::join(names, " or "),
                                       fmt::join(header_, ", ")));
}

std::string TextTable::describe_column(std::size_t column) const {
  if (column < header_.size()) return fmt::format("column {} ({})", column + 1, header_[column]);
  return fmt::format("column {}", column + 1);
}

void TextTable::require_fields(std::size_t count) const {
  if (fields_.size() < count) {
    fail(fmt::format("expected at least {} fields separated by {}, got {}", count,
                     separator_ == Separator::comma ? "commas" : "spaces", fields_.size()));
  }
}

std::string_view TextTable::text(std::size_t column) const {
  require_fields(column + 1);
  return fields_[column];
}

double TextTable::number(std::size_t column) const {
  const std::string_view field = text(column);
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size() ||
      !std::isfinite(value)) {
    fail(fmt::format("{}: expected a finite number, got '{}'", describe_column(column), field));
  }
  return value;
}

std::int64_t TextTable::integer(std::size_t column) const {
  const std::string_view field = text(column);
  const auto value = parse_int64(field);
  if (!value)
    fail(fmt::format("{}: expected an integer, got '{}'", describe_column(column), field));
  return *value;
}

std::int64_t TextTable::unix_time_ns(std::size_t column) const {
  const std::string_view field = text(column);
  const auto value = parse_unix_time_ns(field);
  if (!value) {
    fail(fmt::format(
        "{}: expected a Unix time between 2000 and 2100 (an integer in µs or ns, or seconds with "
        "a decimal point), got '{}'",
        describe_column(column), field));
  }
  return *value;
}

}  // namespace radarpr
