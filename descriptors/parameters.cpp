#include "descriptors/parameters.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace radarpr {
namespace {

std::string describe_kind(const ParameterSpec& spec) {
  if (spec.kind == ParameterKind::choice) {
    return fmt::format("one of {}", fmt::join(spec.choices, ", "));
  }
  if (spec.kind == ParameterKind::text) return "a text without ',', ':', '=' or control characters";
  return fmt::format("a {}", to_string(spec.kind));
}

[[noreturn]] void reject(const ParameterSpec& spec, std::string_view got) {
  throw ParameterError(spec.name, fmt::format("parameter '{}' must be {}, got {}", spec.name,
                                              describe_kind(spec), got));
}

void check_bounds(const ParameterSpec& spec, double value) {
  if (!std::isfinite(value) || (spec.minimum && value < *spec.minimum) ||
      (spec.maximum && value > *spec.maximum)) {
    throw ParameterError(
        spec.name, fmt::format("parameter '{}' must lie in [{}, {}], got {}", spec.name,
                               spec.minimum ? fmt::format("{}", *spec.minimum) : "-inf",
                               spec.maximum ? fmt::format("{}", *spec.maximum) : "inf", value));
  }
}

}  // namespace

std::string_view to_string(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::number:
      return "number";
    case ParameterKind::integer:
      return "integer";
    case ParameterKind::boolean:
      return "boolean";
    case ParameterKind::choice:
      return "choice";
    case ParameterKind::text:
      return "text";
  }
  return "unknown";
}

std::string format_parameter_value(const ParameterValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else {
          return fmt::format("{}", v);  // shortest round-trip form: 3.0 -> "3", 0.5 -> "0.5"
        }
      },
      value);
}

ParameterValue check_parameter_value(const ParameterSpec& spec, const ParameterValue& value) {
  switch (spec.kind) {
    case ParameterKind::number: {
      double number = 0.0;
      if (const auto* d = std::get_if<double>(&value)) {
        number = *d;
      } else if (const auto* i = std::get_if<std::int64_t>(&value)) {
        number = static_cast<double>(*i);
      } else {
        reject(spec, format_parameter_value(value));
      }
      check_bounds(spec, number);
      return number;
    }
    case ParameterKind::integer: {
      std::int64_t integer = 0;
      if (const auto* i = std::get_if<std::int64_t>(&value)) {
        integer = *i;
      } else if (const auto* d = std::get_if<double>(&value);
                 d && std::isfinite(*d) && std::trunc(*d) == *d && std::abs(*d) < 9e15) {
        integer = static_cast<std::int64_t>(*d);
      } else {
        reject(spec, format_parameter_value(value));
      }
      check_bounds(spec, static_cast<double>(integer));
      return integer;
    }
    case ParameterKind::boolean:
      if (!std::holds_alternative<bool>(value)) reject(spec, format_parameter_value(value));
      return value;
    case ParameterKind::choice: {
      const auto* text = std::get_if<std::string>(&value);
      if (text == nullptr) reject(spec, format_parameter_value(value));
      for (const auto& choice : spec.choices) {
        if (choice == *text) return value;
      }
      reject(spec, fmt::format("'{}'", *text));
    }
    case ParameterKind::text: {
      const auto* text = std::get_if<std::string>(&value);
      if (text == nullptr) reject(spec, format_parameter_value(value));
      for (const char c : *text) {
        if (c == ',' || c == ':' || c == '=' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          reject(spec, fmt::format("'{}'", *text));
        }
      }
      return value;
    }
  }
  reject(spec, format_parameter_value(value));
}

ParameterValue parse_parameter_value(const ParameterSpec& spec, std::string_view text) {
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  switch (spec.kind) {
    case ParameterKind::number: {
      double number = 0.0;
      auto [ptr, ec] = std::from_chars(begin, end, number);
      if (ec != std::errc() || ptr != end) reject(spec, fmt::format("'{}'", text));
      return check_parameter_value(spec, number);
    }
    case ParameterKind::integer: {
      std::int64_t integer = 0;
      auto [ptr, ec] = std::from_chars(begin, end, integer);
      if (ec != std::errc() || ptr != end) reject(spec, fmt::format("'{}'", text));
      return check_parameter_value(spec, integer);
    }
    case ParameterKind::boolean:
      if (text == "true") return true;
      if (text == "false") return false;
      reject(spec, fmt::format("'{}' (write true or false)", text));
    case ParameterKind::choice:
    case ParameterKind::text:
      return check_parameter_value(spec, std::string(text));
  }
  reject(spec, fmt::format("'{}'", text));
}

const ParameterValue& ParameterValues::at(std::string_view name) const {
  auto it = values_.find(std::string(name));
  if (it == values_.end()) {
    throw std::logic_error(fmt::format("no parameter named '{}' was resolved", name));
  }
  return it->second;
}

double ParameterValues::number(std::string_view name) const {
  const auto& value = at(name);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return static_cast<double>(*i);
  return std::get<double>(value);
}

std::int64_t ParameterValues::integer(std::string_view name) const {
  return std::get<std::int64_t>(at(name));
}

bool ParameterValues::boolean(std::string_view name) const {
  return std::get<bool>(at(name));
}

const std::string& ParameterValues::choice(std::string_view name) const {
  return std::get<std::string>(at(name));
}

const std::string& ParameterValues::text(std::string_view name) const {
  return std::get<std::string>(at(name));
}

}  // namespace radarpr
