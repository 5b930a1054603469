#include "cli/number_options.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

namespace radarpr::cli {
namespace {

// from_chars reads no leading '+' and no spaces; it does read "inf" and "nan", refused below.
template <typename Number>
std::optional<Number> parse_whole_token(std::string_view text) {
  Number value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

std::string describe(const NumberRange& range, const std::string& value_name) {
  const bool low = range.minimum > -std::numeric_limits<double>::max();
  const bool high = range.maximum < std::numeric_limits<double>::max();
  if (low && high) {
    return fmt::format("{} in {}{}, {}]", value_name, range.minimum_excluded ? "(" : "[",
                       range.minimum, range.maximum);
  }
  if (low)
    return fmt::format("{} {} {}", value_name, range.minimum_excluded ? ">" : ">=", range.minimum);
  if (high) return fmt::format("{} <= {}", value_name, range.maximum);
  return value_name + " finite";
}

std::string describe(const WholeNumberRange& range, const std::string& value_name) {
  const bool low = range.minimum > std::numeric_limits<long long>::min();
  const bool high = range.maximum < std::numeric_limits<long long>::max();
  if (low && high) return fmt::format("{} in {}..{}", value_name, range.minimum, range.maximum);
  if (low) return fmt::format("{} >= {}", value_name, range.minimum);
  if (high) return fmt::format("{} <= {}", value_name, range.maximum);
  return value_name + " whole";
}

}  // namespace

std::optional<double> parse_number(std::string_view text) {
  const auto value = parse_whole_token<double>(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_whole_number(std::string_view text) {
  return parse_whole_token<long long>(text);
}

std::string number_problem(std::string_view text, const NumberRange& range) {
  const auto value = parse_number(text);
  if (!value) return fmt::format("'{}' is not a finite number", text);
  const bool below = range.minimum_excluded ? *value <= range.minimum : *value < range.minimum;
  if (below || *value > range.maximum) {
    return fmt::format("'{}' is out of range, expected {}", text, describe(range, "a value"));
  }
  return "";
}

std::string whole_number_problem(std::string_view text, const WholeNumberRange& range) {
  const auto value = parse_whole_number(text);
  if (!value) return fmt::format("'{}' is not a whole number", text);
  if (*value < range.minimum || *value > range.maximum) {
    return fmt::format("'{}' is out of range, expected {}", text, describe(range, "a value"));
  }
  return "";
}

CLI::Option* add_number_option(CLI::App& verb, const std::string& name,
                               std::optional<double>& target, const NumberRange& range,
                               const std::string& value_name, const std::string& help) {
  return verb
      .add_option_function<std::string>(
          name, [&target](const std::string& text) { target = parse_number(text); }, help)
      ->check(CLI::Validator([range](std::string& text) { return number_problem(text, range); }, "",
                             "number"))
      ->type_name(value_name)
      ->option_text(describe(range, value_name));
}

CLI::Option* add_whole_number_option(CLI::App& verb, const std::string& name,
                                     std::optional<long long>& target,
                                     const WholeNumberRange& range, const std::string& value_name,
                                     const std::string& help) {
  return verb
      .add_option_function<std::string>(
          name, [&target](const std::string& text) { target = parse_whole_number(text); }, help)
      ->check(
          CLI::Validator([range](std::string& text) { return whole_number_problem(text, range); },
                         "", "whole number"))
      ->type_name(value_name)
      ->option_text(describe(range, value_name));
}

CLI::Option* add_whole_numbers_option(CLI::App& verb, const std::string& name,
                                      std::vector<long long>& target, const WholeNumberRange& range,
                                      const std::string& value_name, const std::string& help) {
  // Split here rather than by CLI11, which drops empty elements: "1000,,10" is a mistake.
  auto split = [](const std::string& text) {
    std::vector<std::string> parts;
    std::size_t begin = 0;
    while (true) {
      const std::size_t comma = text.find(',', begin);
      parts.push_back(text.substr(begin, comma - begin));
      if (comma == std::string::npos) return parts;
      begin = comma + 1;
    }
  };
  auto check = [range, split](std::string& text) -> std::string {
    for (const std::string& part : split(text)) {
      if (auto problem = whole_number_problem(part, range); !problem.empty()) return problem;
    }
    return "";
  };
  return verb
      .add_option_function<std::vector<std::string>>(
          name,
          [&target, split](const std::vector<std::string>& texts) {
            target.clear();
            for (const auto& text : texts) {
              for (const auto& part : split(text)) target.push_back(*parse_whole_number(part));
            }
          },
          help)
      ->check(CLI::Validator(check, "", "whole numbers"))
      ->allow_extra_args(false)
      ->type_name(fmt::format("{0},{0},...", value_name))
      ->option_text(describe(range, "each " + value_name));
}

}  // namespace radarpr::cli
