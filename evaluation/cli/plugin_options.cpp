#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "descriptors/plugins/plugin_loader.hpp"
#include "evaluation/cli/commands.hpp"

namespace radarpr::cli {

std::vector<std::string> load_plugins_and_strip_options(const std::vector<std::string>& args) {
  // The environment's plugins first, then the command line's, each in the order given.
  if (const char* listed = std::getenv("RADARPR_PLUGINS"); listed != nullptr) {
    for (const auto& path : split_plugin_list(listed)) load_descriptor_plugin(path);
  }
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--plugin") {
      if (i + 1 >= args.size()) throw UsageError("--plugin needs the path of a shared library");
      load_descriptor_plugin(args[++i]);
    } else if (args[i].starts_with("--plugin=")) {
      load_descriptor_plugin(args[i].substr(std::string("--plugin=").size()));
    } else {
      rest.push_back(args[i]);
    }
  }
  return rest;
}

}  // namespace radarpr::cli
