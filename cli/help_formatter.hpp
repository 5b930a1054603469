#pragma once

// The help of the program and of each verb, generated from the CLI11 definitions: the usage line
// lists every argument and option of the verb (so it cannot drift from what the parser accepts),
// each option's line carries its value, default, range and whether it repeats. An option's
// option_text (CLI11) is taken as a note on the values it accepts ("N in 0..1024").
#include <memory>
#include <string>

namespace CLI {
class App;
class FormatterBase;
}  // namespace CLI

namespace radarpr::cli {

inline constexpr std::size_t kHelpWidth = 100;

// The formatter the program and every verb print their --help with.
std::shared_ptr<CLI::FormatterBase> make_help_formatter();

// `head` ("usage: radarpr run") followed by every argument and option of `verb` (without
// --plugin unless `with_plugin`), wrapped at kHelpWidth with later lines indented under the first.
std::string usage_of(const CLI::App& verb, const std::string& head, bool with_plugin);

}  // namespace radarpr::cli
