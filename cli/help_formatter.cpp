#include "cli/help_formatter.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include <CLI/CLI.hpp>

namespace radarpr::cli {
namespace {

// Breaks `text` into lines of at most `width` characters (a longer word gets a line of its own),
// keeping its own line breaks; the first line continues after `first` characters already written,
// the others start with `indent` spaces.
std::string wrap(const std::string& text, std::size_t first, std::size_t indent,
                 std::size_t width = kHelpWidth) {
  std::string out;
  std::size_t column = first;
  bool line_start = true;
  std::istringstream lines(text);
  std::string line;
  bool first_line = true;
  while (std::getline(lines, line)) {
    if (!first_line) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    }
    first_line = false;
    line_start = true;
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      if (!line_start && column + 1 + word.size() > width) {
        out += "\n" + std::string(indent, ' ');
        column = indent;
        line_start = true;
      }
      if (!line_start) {
        out += ' ';
        ++column;
      }
      out += word;
      column += word.size();
      line_start = false;
    }
  }
  return out;
}

bool is_help(const CLI::App& app, const CLI::Option* option) {
  return option == app.get_help_ptr() || option == app.get_help_all_ptr();
}

bool is_flag(const CLI::Option* option) {
  return option->get_expected_max() == 0;
}

// Takes several values: a repeatable option (`--set a=1 --set b=2`), a list of arguments.
bool repeats(const CLI::Option* option) {
  return option->get_expected_max() > 1;
}

// An option that may be given again, each time with a value, rather than one taking several
// values at once (`--dataset TYPE ROOT ...`).
bool repeatable(const CLI::Option* option) {
  return !option->get_positional() && repeats(option) && option->get_expected_min() <= 1 &&
         option->get_type_name().find(',') == std::string::npos;
}

// "--out", "-h, --help": every name, short ones first.
std::string names_of(const CLI::Option* option) {
  std::vector<std::string> names;
  for (const auto& name : option->get_snames()) names.push_back("-" + name);
  for (const auto& name : option->get_lnames()) names.push_back("--" + name);
  return CLI::detail::join(names, ", ");
}

std::string main_name(const CLI::Option* option) {
  if (option->get_positional()) return option->get_name(true, false);
  if (!option->get_lnames().empty()) return "--" + option->get_lnames().front();
  return "-" + option->get_snames().front();
}

// How the option is written on a usage line, without brackets: "--out DIR", "FILE.png...".
std::string usage_token(const CLI::Option* option) {
  if (option->get_positional()) return main_name(option) + (repeats(option) ? "..." : "");
  if (is_flag(option)) return main_name(option);
  return main_name(option) + " " + option->get_type_name();
}

std::vector<const CLI::Option*> shown_options(const CLI::App& app) {
  return app.get_options([&app](const CLI::Option* option) {
    return !is_help(app, option) && !option->get_group().empty();
  });
}

// Usage tokens in definition order, positionals first; options that exclude each other share one
// token ("[--cache-dir DIR | --no-cache]").
std::vector<std::string> usage_tokens(const CLI::App& app, bool with_plugin) {
  std::vector<const CLI::Option*> ordered;
  for (const CLI::Option* option : shown_options(app)) {
    if (option->get_positional()) ordered.push_back(option);
  }
  for (const CLI::Option* option : shown_options(app)) {
    if (!option->get_positional() && (with_plugin || main_name(option) != "--plugin")) {
      ordered.push_back(option);
    }
  }
  std::vector<std::vector<const CLI::Option*>> groups;
  for (const CLI::Option* option : ordered) {
    auto joined = std::find_if(groups.begin(), groups.end(), [option](const auto& group) {
      return std::any_of(group.begin(), group.end(), [option](const CLI::Option* member) {
        return member->get_excludes().count(const_cast<CLI::Option*>(option)) > 0 ||
               option->get_excludes().count(const_cast<CLI::Option*>(member)) > 0;
      });
    });
    if (joined != groups.end()) {
      joined->push_back(option);
    } else {
      groups.push_back({option});
    }
  }
  std::vector<std::string> tokens;
  for (const auto& group : groups) {
    std::vector<std::string> parts;
    bool optional = true;
    for (const CLI::Option* member : group) {
      parts.push_back(usage_token(member));
      if (member->get_required() || member->get_positional()) optional = false;
    }
    std::string token = CLI::detail::join(parts, " | ");
    if (group.size() == 1 && group.front()->get_positional() && !group.front()->get_required()) {
      optional = true;  // a lone optional argument
    }
    if (optional) token = "[" + token + "]";
    if (group.size() == 1 && repeatable(group.front())) {
      token += "...";
    }
    tokens.push_back(token);
  }
  return tokens;
}

// The text after an option's names: its description, then in one parenthesis what its definition
// adds: the values it takes (option_text, set by number_options.hpp), its default, whether it
// repeats.
std::string option_description(const CLI::Option* option) {
  std::vector<std::string> notes;
  if (!option->get_option_text().empty()) notes.push_back(option->get_option_text());
  if (!option->get_default_str().empty()) notes.push_back("default: " + option->get_default_str());
  if (repeatable(option)) notes.push_back("repeatable");
  std::string text = option->get_description();
  if (!notes.empty()) text += " (" + CLI::detail::join(notes, "; ") + ")";
  return text;
}

std::string option_label(const CLI::App& app, const CLI::Option* option) {
  if (option->get_positional()) return main_name(option) + (repeats(option) ? "..." : "");
  std::string label = names_of(option);
  if (!is_flag(option) && !is_help(app, option)) label += " " + option->get_type_name();
  return label;
}

std::string option_lines(const CLI::App& app, const std::vector<const CLI::Option*>& options) {
  constexpr std::size_t kMaxLabel = 24;
  std::size_t label_width = 0;
  for (const CLI::Option* option : options) {
    const std::size_t size = option_label(app, option).size();
    if (size <= kMaxLabel) label_width = std::max(label_width, size);
  }
  const std::size_t column = 2 + label_width + 2;
  std::string out;
  for (const CLI::Option* option : options) {
    const std::string label = "  " + option_label(app, option);
    out += label;
    if (label.size() + 2 > column) {
      out += "\n" + std::string(column, ' ');
    } else {
      out += std::string(column - label.size(), ' ');
    }
    out += wrap(option_description(option), column, column) + "\n";
  }
  return out;
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

std::string verb_help(const CLI::App& verb, const std::string& name) {
  std::string out = usage_of(verb, "usage: " + name, true) + "\n";
  if (!verb.get_description().empty()) out += "\n" + verb.get_description() + "\n";
  std::vector<const CLI::Option*> arguments;
  std::vector<const CLI::Option*> options;
  for (const CLI::Option* option : shown_options(verb)) {
    (option->get_positional() ? arguments : options).push_back(option);
  }
  if (verb.get_help_ptr() != nullptr) options.push_back(verb.get_help_ptr());
  if (!arguments.empty()) out += "\narguments:\n" + option_lines(verb, arguments);
  if (!options.empty()) out += "\noptions:\n" + option_lines(verb, options);
  if (!verb.get_footer().empty()) out += "\n" + verb.get_footer() + "\n";
  return out;
}

std::string program_help(const CLI::App& program, const std::string& name) {
  std::string out = program.get_description() + "\n\n";
  out += "usage: " + name + " [--plugin PATH]... VERB [ARGUMENTS] [OPTIONS]\n";
  out += "       " + name + " help [VERB]\n";
  out += "       " + name + " --version\n";
  out += "\nverbs:\n";
  for (const CLI::App* verb : program.get_subcommands({})) {
    if (verb->get_group().empty()) continue;  // hidden
    // --plugin is every verb's: listed once, below.
    out += usage_of(*verb, "  " + name + " " + verb->get_name(), false) + "\n";
    out += "      " + wrap(first_line(verb->get_description()), 6, 6) + "\n";
  }
  std::vector<const CLI::Option*> options = shown_options(program);
  if (program.get_help_ptr() != nullptr) options.push_back(program.get_help_ptr());
  out += "\noptions:\n" + option_lines(program, options);
  if (!program.get_footer().empty()) out += "\n" + program.get_footer() + "\n";
  return out;
}

class HelpFormatter : public CLI::FormatterBase {
 public:
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode) const override {
    return app->get_parent() == nullptr ? program_help(*app, name) : verb_help(*app, name);
  }
};

}  // namespace

std::shared_ptr<CLI::FormatterBase> make_help_formatter() {
  return std::make_shared<HelpFormatter>();
}

std::string usage_of(const CLI::App& verb, const std::string& head, bool with_plugin) {
  std::string line = head;
  std::size_t column = line.size();
  const std::size_t continuation = head.size() + 1;
  for (const std::string& token : usage_tokens(verb, with_plugin)) {
    if (column + 1 + token.size() > kHelpWidth && column > continuation) {
      line += "\n" + std::string(continuation, ' ');
      column = continuation;
    } else {
      line += ' ';
      ++column;
    }
    line += token;
    column += token.size();
  }
  return line;
}

}  // namespace radarpr::cli
