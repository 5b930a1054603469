// A library that exports the ABI record of RADARPR_PLUGIN but no radarpr_plugin_register: the
// loader must name the missing entry point.
#include "descriptors/plugins/plugin.hpp"

extern "C" RADARPR_PLUGIN_EXPORT const RadarprPluginAbi radarpr_plugin_abi =
    radarpr::this_build_plugin_abi(RADARPR_VERSION_MINOR, RADARPR_PLUGIN_ABI);
