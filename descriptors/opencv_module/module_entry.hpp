#pragma once
// The two symbols the shared OpenCV module exports (extern "C": unmangled, found by dlsym), shared
// by the module's entry point (module_entry.cpp) and the program's loader (module_loader.cpp).
//
// The record is the plugin ABI record (descriptors/plugins/plugin.hpp) of the module's build. The
// module is built with the program, so the loader asks more than of a plugin: the same version
// to the patch, besides what plugin_incompatibility() checks.
#include "descriptors/plugins/plugin.hpp"

#define RADARPR_OPENCV_MODULE_ABI_SYMBOL "radarpr_opencv_module_abi"
#define RADARPR_OPENCV_MODULE_REGISTER_SYMBOL "radarpr_opencv_module_register"
