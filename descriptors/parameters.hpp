#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace radarpr {

// text: free text such as a file path; it becomes part of the descriptor's id, so it may not
// contain the id's separators ',', ':' and '=' (nor control characters).
enum class ParameterKind { number, integer, boolean, choice, text };

using ParameterValue = std::variant<bool, std::int64_t, double, std::string>;

// One tunable parameter of a descriptor, with its default and its valid range.
struct ParameterSpec {
  std::string name;
  ParameterKind kind = ParameterKind::number;
  ParameterValue default_value;
  std::string description;
  std::vector<std::string> choices;  // the allowed values of a `choice` parameter
  std::optional<double> minimum;     // inclusive bounds of `number` and `integer` parameters
  std::optional<double> maximum;
};

// A parameter given a value it cannot take; `parameter` names it so callers can point at the
// config key.
class ParameterError : public std::invalid_argument {
 public:
  ParameterError(std::string parameter, const std::string& message)
      : std::invalid_argument(message), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

// The resolved parameters of one descriptor configuration: every spec'd parameter has a value.
class ParameterValues {
 public:
  ParameterValues() = default;
  explicit ParameterValues(std::map<std::string, ParameterValue> values)
      : values_(std::move(values)) {}

  double number(std::string_view name) const;
  std::int64_t integer(std::string_view name) const;
  bool boolean(std::string_view name) const;
  const std::string& choice(std::string_view name) const;
  const std::string& text(std::string_view name) const;

  const std::map<std::string, ParameterValue>& all() const { return values_; }

 private:
  const ParameterValue& at(std::string_view name) const;
  std::map<std::string, ParameterValue> values_;
};

// The enum a `choice` parameter stands for, looked up in `table` ((text, value) pairs); throws
// ParameterError when the resolved text is missing from the table (a spec/table mismatch).
template <typename Enum>
Enum choice_value(const ParameterValues& values, std::string_view name,
                  std::initializer_list<std::pair<std::string_view, Enum>> table) {
  const std::string& text = values.choice(name);
  for (const auto& [option, value] : table) {
    if (text == option) return value;
  }
  throw ParameterError(std::string(name),
                       "parameter '" + std::string(name) + "' has no meaning for '" + text + "'");
}

std::string_view to_string(ParameterKind kind);
// Canonical text of a value: shortest round-trip numbers ("3", "0.5"), true/false, raw strings.
std::string format_parameter_value(const ParameterValue& value);
// Parses `text` as a value of `spec` and checks it (kind, choices, bounds); throws ParameterError.
ParameterValue parse_parameter_value(const ParameterSpec& spec, std::string_view text);
// Checks a typed value against `spec`, converting integral numbers for `integer` and integers
// for `number` parameters; throws ParameterError.
ParameterValue check_parameter_value(const ParameterSpec& spec, const ParameterValue& value);

}  // namespace radarpr
