#include "evaluation/config/config_plugins.hpp"

#include <stdexcept>

#include "descriptors/plugins/plugin_loader.hpp"
#include "evaluation/config/environment_expansion.hpp"

namespace radarpr {

std::vector<std::filesystem::path> load_config_plugins(ConfigReader& reader,
                                                       const std::filesystem::path& config_folder) {
  std::vector<std::filesystem::path> plugins;
  if (!reader.has("plugins")) return plugins;
  for (const auto& [entry, path] : reader.array("plugins")) {
    if (!entry->is_string() || entry->get<std::string>().empty()) {
      throw ConfigError(path, "expected the path of a descriptor plugin (a shared library), got " +
                                  entry->dump());
    }
    std::filesystem::path plugin(expand_environment_variables(entry->get<std::string>(), path));
    if (plugin.is_relative() && !config_folder.empty()) plugin = config_folder / plugin;
    try {
      load_descriptor_plugin(plugin);
    } catch (const std::invalid_argument& error) {
      throw ConfigError(path, error.what());
    }
    plugins.push_back(plugin);
  }
  return plugins;
}

}  // namespace radarpr
