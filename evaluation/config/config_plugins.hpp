#pragma once

#include <filesystem>
#include <vector>

#include "evaluation/config/config_reader.hpp"

namespace radarpr {

// Loads the descriptor plugins a config names in its top-level "plugins" array (absent = none),
// so that its descriptors can name what they register. Each entry is a path to a shared library;
// "${NAME}" is replaced by the environment variable NAME and a relative path is taken from
// `config_folder` (the config file's folder). Returns the resolved paths; a plugin that fails to
// load is a ConfigError at "plugins[i]" carrying the loader's message.
std::vector<std::filesystem::path> load_config_plugins(ConfigReader& reader,
                                                       const std::filesystem::path& config_folder);

}  // namespace radarpr
