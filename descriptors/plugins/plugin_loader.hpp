#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace radarpr {

// One descriptor plugin loaded into this process.
struct LoadedPlugin {
  std::filesystem::path path;            // canonical
  std::string build;                     // "<path> <size> bytes, modified <mtime>": keys the cache
  std::vector<std::string> descriptors;  // the names it registered
};

// Loads the descriptor plugin (a shared library exporting RADARPR_PLUGIN) at `path` and adds its
// descriptors to DescriptorRegistry::global(). A path already loaded (same canonical file) is
// not loaded again. Throws std::invalid_argument naming the path when the file is missing, is not
// a shared library, has no radarpr entry point, was built against an incompatible radarpr or
// standard library, registers nothing, or registers a name already taken.
//
// Load plugins before any thread uses the registry. A loaded plugin is never unloaded: the
// registry holds its factories.
const LoadedPlugin& load_descriptor_plugin(const std::filesystem::path& path);

// Every plugin loaded so far, in load order.
std::vector<LoadedPlugin> loaded_descriptor_plugins();

// The paths of a colon-separated list such as $RADARPR_PLUGINS (empty entries skipped).
std::vector<std::filesystem::path> split_plugin_list(const std::string& list);

}  // namespace radarpr
