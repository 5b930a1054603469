#include "evaluation/text_escaping.hpp"

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

namespace radarpr {
namespace {

bool is_control(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return byte < 0x20 || byte == 0x7f;
}

// The length of the UTF-8 sequence starting at text[at], or 0 when it is not a valid one
// (overlong forms, surrogates and code points beyond U+10FFFF included).
std::size_t utf8_length(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned low = 0x80, high = 0xbf;  // the allowed range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) low = 0xa0;
    if (lead == 0xed) high = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) low = 0x90;
    if (lead == 0xf4) high = 0x8f;
  } else {
    return 0;
  }
  if (at + length > text.size()) return 0;
  if (byte(at + 1) < low || byte(at + 1) > high) return 0;
  for (std::size_t i = 2; i < length; ++i) {
    if (byte(at + i) < 0x80 || byte(at + i) > 0xbf) return 0;
  }
  return length;
}

bool looks_like_number(std::string_view text) {
  if (text.empty()) return false;
  const std::string copy(text);
  char* end = nullptr;
  std::strtod(copy.c_str(), &end);
  return end == copy.c_str() + copy.size();
}

}  // namespace

std::string gnuplot_string(std::string_view text) {
  std::string result = "'";
  for (char c : text) {
    if (c == '\'') {
      result += "''";
    } else {
      result += is_control(c) ? ' ' : c;
    }
  }
  return result + "'";
}

std::string html_escape(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&#39;";
        break;
      case '\n':
      case '\t':
        escaped += c;
        break;
      default:
        escaped += is_control(c) ? ' ' : c;
    }
  }
  return escaped;
}

std::string latex_escape(std::string_view text) {
  std::string escaped;
  for (char c : text) {
    switch (c) {
      case '&':
      case '%':
      case '$':
      case '#':
      case '_':
      case '{':
      case '}':
        escaped += '\\';
        escaped += c;
        break;
      case '~':
        escaped += "\\textasciitilde{}";
        break;
      case '^':
        escaped += "\\textasciicircum{}";
        break;
      case '\\':
        escaped += "\\textbackslash{}";
        break;
      case '<':
        escaped += "\\textless{}";
        break;
      case '>':
        escaped += "\\textgreater{}";
        break;
      case '"':
        escaped += "\\textquotedbl{}";
        break;
      default:
        escaped += is_control(c) ? ' ' : c;
    }
  }
  return escaped;
}

std::string markdown_cell(std::string_view text) {
  std::string escaped;
  for (char c : text) {
    if (c == '\\' || c == '|' || c == '`' || c == '*' || c == '[' || c == ']' || c == '<') {
      escaped += '\\';
      escaped += c;
    } else {
      escaped += is_control(c) ? ' ' : c;
    }
  }
  return escaped;
}

std::string markdown_code_cell(std::string_view text) {
  std::string content;
  std::size_t run = 0, longest = 0;  // the longest backtick run, for the fence
  for (char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
    if (c == '|') {
      content += "\\|";
    } else {
      content += is_control(c) ? ' ' : c;
    }
  }
  const std::string fence(longest + 1, '`');
  // "`` `a ``": a space keeps the fence off content that starts or ends with a backtick.
  const bool pad = longest > 0;
  return fence + (pad ? " " : "") + content + (pad ? " " : "") + fence;
}

std::string csv_field(std::string_view text, CsvQuoting quoting) {
  std::string field(text);
  const bool formula =
      !text.empty() &&
      (text[0] == '=' || text[0] == '+' || text[0] == '-' || text[0] == '@' || text[0] == '\t') &&
      !looks_like_number(text);
  if (formula) field = "'" + field;
  const bool quote = quoting == CsvQuoting::always ||
                     field.find_first_of(",\"\n\r") != std::string::npos ||
                     (!field.empty() && (field.front() == ' ' || field.back() == ' '));
  if (!quote) return field;
  std::string quoted = "\"";
  for (char c : field) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string printable(std::string_view text, bool keep_newlines) {
  std::string shown;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const std::size_t length = utf8_length(text, i);
    if (length > 1) {
      shown.append(text.substr(i, length));
      i += length;
      continue;
    }
    if (c == '\n') {
      shown += keep_newlines ? "\n" : "\\n";
    } else if (c == '\t') {
      shown += "\\t";
    } else if (c == '\r') {
      shown += "\\r";
    } else if (c == '\\' && !keep_newlines) {
      shown += "\\\\";
    } else if (length == 0 || is_control(c)) {
      shown += fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
    } else {
      shown += c;
    }
    ++i;
  }
  return shown;
}

bool is_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = utf8_length(text, i);
    if (length == 0) return false;
    i += length;
  }
  return true;
}

std::string json_string(std::string_view text) {
  return is_utf8(text) ? std::string(text) : printable(text);
}

void make_json_utf8(nlohmann::json& value) {
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    if (!is_utf8(text)) value = printable(text);
  } else if (value.is_array()) {
    for (auto& element : value) make_json_utf8(element);
  } else if (value.is_object()) {
    nlohmann::json fixed = nlohmann::json::object();
    for (auto& [key, element] : value.items()) {
      make_json_utf8(element);
      fixed[json_string(key)] = std::move(element);
    }
    value = std::move(fixed);
  }
}

}  // namespace radarpr
