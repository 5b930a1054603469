#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "descriptors/plugins/plugin_loader.hpp"

namespace radarpr::cli {
namespace {

// `radarpr --help`, `--version` and any `COMMAND --help` only print: a plugin that fails to load
// (a stale $RADARPR_PLUGINS) must not stop them.
bool asks_only_for_help_or_version(const std::vector<std::string>& args) {
  if (args.empty()) return true;
  for (const std::string& arg : args) {
    if (arg == "--help" || arg == "-h" || arg == "--version") return true;
  }
  return args[0] == "help";
}

}  // namespace

std::vector<std::string> load_plugins_and_strip_options(const std::vector<std::string>& args) {
  std::vector<std::string> rest;
  std::vector<std::string> plugins;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--plugin") {
      if (i + 1 >= args.size()) throw UsageError("--plugin needs the path of a shared library");
      plugins.push_back(args[++i]);
    } else if (args[i].starts_with("--plugin=")) {
      plugins.push_back(args[i].substr(std::string("--plugin=").size()));
    } else {
      rest.push_back(args[i]);
    }
  }
  if (asks_only_for_help_or_version(rest)) return rest;
  // The environment's plugins first, then the command line's, each in the order given.
  if (const char* listed = std::getenv("RADARPR_PLUGINS"); listed != nullptr) {
    for (const auto& path : split_plugin_list(listed)) load_descriptor_plugin(path);
  }
  for (const std::string& path : plugins) load_descriptor_plugin(path);
  return rest;
}

}  // namespace radarpr::cli
