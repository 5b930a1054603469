#pragma once

#include <optional>
#include <string>

#include "descriptors/plugins/plugin.hpp"

namespace radarpr {

// The record of this radarpr build (the host), as a plugin built with the same compiler, standard
// library and radarpr version would declare it.
const RadarprPluginAbi& host_plugin_abi();

// Why a plugin built as `plugin` cannot be loaded into a host built as `host`, or nothing when it
// can. The rule: same record layout, same plugin ABI number, same radarpr major.minor (a patch
// release never changes what a plugin compiles against), same standard library and its ABI flag,
// and the same sizes of the types that cross the boundary.
std::optional<std::string> plugin_incompatibility(const RadarprPluginAbi& plugin,
                                                  const RadarprPluginAbi& host);

// "radarpr 0.1.0 (plugin ABI 1, 12.2.0 libstdc++ 20220819, C++11 string ABI 1)".
std::string describe_plugin_abi(const RadarprPluginAbi& abi);

}  // namespace radarpr
