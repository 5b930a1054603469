#pragma once

#include <filesystem>
#include <optional>

namespace radarpr {

// Where radarpr keeps what it can always recompute (rendered synthetic scans, extracted
// descriptors), so that a second run skips the work. In order: the override below,
// $RADARPR_CACHE_DIR, $XDG_CACHE_HOME/radarpr, $HOME/.cache/radarpr. "off" (in the override or
// the variable) disables caching: nullopt. Nothing is created here.
std::optional<std::filesystem::path> cache_directory();

// Replaces the environment's choice for this process (`radarpr --no-cache`, `--cache-dir`);
// "off" disables caching, nullopt returns to the environment's choice.
void override_cache_directory(std::optional<std::filesystem::path> directory);

}  // namespace radarpr
