// The shared OpenCV module's entry point: its build record and its registration, which the
// program's loader (module_loader.cpp) finds by name. Compiled into the module only.
#include "descriptors/opencv_module/module_entry.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/opencv_module/opencv_module.hpp"

extern "C" RADARPR_PLUGIN_EXPORT const RadarprPluginAbi radarpr_opencv_module_abi =
    radarpr::this_build_plugin_abi(RADARPR_VERSION_MINOR, RADARPR_PLUGIN_ABI);

extern "C" RADARPR_PLUGIN_EXPORT void radarpr_opencv_module_register(
    radarpr::DescriptorRegistry& registry) {
  radarpr::register_opencv_module_descriptors(registry);
}
