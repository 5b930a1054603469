#pragma once
// The descriptors whose code needs OpenCV's library (RaPlace, Open-RadVLAD, Radar Scan Context and
// the resampling they use: descriptors/CMakeLists.txt lists the folders) are built twice over the
// same objects: as a static library that tests, benchmark programs and the Python extension link,
// and as a shared module (build/radarpr_opencv_descriptors.so, installed under lib/radarpr/) that
// the `radarpr` program loads the first time one of them is needed. A start that needs none of
// them (`radarpr --version`, `radarpr extract referee`) then does not load OpenCV and the
// libraries it brings (docs/architecture.md, "The OpenCV module").
//
// The registry (descriptor_registry.cpp) knows the module's descriptor names without loading it,
// and calls load_opencv_module() once, when one of them is created, described or listed.
#include <span>
#include <string_view>

namespace radarpr {

class DescriptorRegistry;

// The names of the module's descriptors, sorted (the build-generated builtin_descriptors.cpp).
std::span<const std::string_view> opencv_module_descriptor_names();

// Adds the module's descriptors to `registry`; `wanted` says what needs them, for messages
// ("descriptor 'raplace'"). Defined once per way of linking: opencv_module/linked_module.cpp
// registers the statically linked descriptors, opencv_module/module_loader.cpp (the `radarpr`
// program only) loads the shared module found from the program's own location and throws
// std::runtime_error naming the path and `wanted` when it is missing or does not match.
void load_opencv_module(DescriptorRegistry& registry, std::string_view wanted);

// The module's registrations (the build-generated opencv_module_descriptors.cpp, part of the
// module): what the shared module's entry point and linked_module.cpp call.
void register_opencv_module_descriptors(DescriptorRegistry& registry);

}  // namespace radarpr
