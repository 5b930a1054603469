#pragma once
// The one header a descriptor plugin includes: the Descriptor interface, the registry and the
// RADARPR_PLUGIN macro that exports the plugin's entry point.
//
// A plugin is a shared library (CMake MODULE) that ends its source with
//   RADARPR_PLUGIN(register_my_descriptors);
// where `void register_my_descriptors(radarpr::DescriptorRegistry&)` adds DescriptorInfos.
//
// Symbols: the plugin does not carry a copy of radarpr. It links radarpr::plugin_api (headers
// only) and leaves radarpr's functions undefined; the radarpr program that loads it exports them
// (ENABLE_EXPORTS), so the plugin shares the host's registry, Descriptor vtable and typeinfo, and
// exceptions cross the boundary as themselves. Hence the ABI record below: the loader reads it
// before calling the plugin's registration and refuses one built against an incompatible radarpr
// or standard library. The plugin's static initialisers do run at load, before the check: keep
// them trivial (register descriptors in the registration function, not from a static object).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "datasets/polar_image.hpp"
#include "descriptors/descriptor.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/parameters.hpp"
#include "descriptors/plugins/plugin_version.hpp"

// Bump when Descriptor, DescriptorInfo, DescriptorRegistry or anything a plugin compiles into its
// own code changes layout, virtual functions or an inline default a plugin inherits; a plugin must
// be rebuilt then. 2: DescriptorInfo declares extraction stages. 3: Descriptor::retrieval_method()
// defaults to exhaustive (was kdtree). 4: Descriptor::saves_training(), save_training() and
// load_training(). 5: PolarImage::power is a radarpr::ByteImage (was a cv::Mat).
#define RADARPR_PLUGIN_ABI 5

// The two symbols a plugin exports (extern "C": unmangled, found by dlsym).
#define RADARPR_PLUGIN_ABI_SYMBOL "radarpr_plugin_abi"
#define RADARPR_PLUGIN_REGISTER_SYMBOL "radarpr_plugin_register"

// Standard library families, as recorded in RadarprPluginAbi::standard_library.
#define RADARPR_STDLIB_OTHER 0u
#define RADARPR_STDLIB_LIBSTDCXX 1u
#define RADARPR_STDLIB_LIBCXX 2u
#if defined(__GLIBCXX__)
#define RADARPR_STDLIB RADARPR_STDLIB_LIBSTDCXX
#define RADARPR_STDLIB_ABI_FLAG _GLIBCXX_USE_CXX11_ABI
#elif defined(_LIBCPP_VERSION)
#define RADARPR_STDLIB RADARPR_STDLIB_LIBCXX
#define RADARPR_STDLIB_ABI_FLAG _LIBCPP_ABI_VERSION
#else
#define RADARPR_STDLIB RADARPR_STDLIB_OTHER
#define RADARPR_STDLIB_ABI_FLAG 0
#endif

#define RADARPR_PLUGIN_STRINGIFY_(x) #x
#define RADARPR_PLUGIN_STRINGIFY(x) RADARPR_PLUGIN_STRINGIFY_(x)

// Tests build deliberately incompatible plugins by overriding what the plugin declares.
#ifndef RADARPR_PLUGIN_DECLARED_VERSION_MINOR
#define RADARPR_PLUGIN_DECLARED_VERSION_MINOR RADARPR_VERSION_MINOR
#endif
#ifndef RADARPR_PLUGIN_DECLARED_ABI
#define RADARPR_PLUGIN_DECLARED_ABI RADARPR_PLUGIN_ABI
#endif

extern "C" {

// What a plugin was built against. `magic` and `record_size` come first and never move, so that
// any later layout is still recognised as another layout rather than misread.
struct RadarprPluginAbi {
  std::uint32_t magic;        // kRadarprPluginMagic
  std::uint32_t record_size;  // sizeof(RadarprPluginAbi) of the plugin's build
  std::uint32_t plugin_abi;   // RADARPR_PLUGIN_ABI
  std::uint32_t version_major;
  std::uint32_t version_minor;
  std::uint32_t version_patch;
  std::uint32_t standard_library;      // RADARPR_STDLIB_*
  std::uint32_t standard_library_abi;  // _GLIBCXX_USE_CXX11_ABI (libstdc++), _LIBCPP_ABI_VERSION
  // Sizes of the types that cross the boundary by value: a mismatch means the two sides would
  // disagree about a layout (another standard library, another packing).
  std::uint32_t sizeof_string;
  std::uint32_t sizeof_function;
  std::uint32_t sizeof_shared_ptr;
  std::uint32_t sizeof_descriptor_info;
  std::uint32_t sizeof_parameter_spec;
  std::uint32_t sizeof_polar_image;
  std::uint32_t sizeof_descriptor_value;
  const char* compiler;  // e.g. "12.2.0 libstdc++ 20220819", for messages
};

}  // extern "C"

namespace radarpr {

inline constexpr std::uint32_t kRadarprPluginMagic = 0x50525052u;  // "RPRP"

// The record of the translation unit that evaluates it: the host's own, or a plugin's.
constexpr RadarprPluginAbi this_build_plugin_abi(std::uint32_t version_minor,
                                                 std::uint32_t plugin_abi) {
  return RadarprPluginAbi {
    kRadarprPluginMagic, static_cast<std::uint32_t>(sizeof(RadarprPluginAbi)), plugin_abi,
        RADARPR_VERSION_MAJOR, version_minor, RADARPR_VERSION_PATCH, RADARPR_STDLIB,
        static_cast<std::uint32_t>(RADARPR_STDLIB_ABI_FLAG),
        static_cast<std::uint32_t>(sizeof(std::string)),
        static_cast<std::uint32_t>(sizeof(std::function<void()>)),
        static_cast<std::uint32_t>(sizeof(std::shared_ptr<int>)),
        static_cast<std::uint32_t>(sizeof(DescriptorInfo)),
        static_cast<std::uint32_t>(sizeof(ParameterSpec)),
        static_cast<std::uint32_t>(sizeof(PolarImage)),
        static_cast<std::uint32_t>(sizeof(DescriptorValue)),
#if defined(__GLIBCXX__)
        __VERSION__ " libstdc++ " RADARPR_PLUGIN_STRINGIFY(__GLIBCXX__),
#elif defined(_LIBCPP_VERSION)
        __VERSION__ " libc++ " RADARPR_PLUGIN_STRINGIFY(_LIBCPP_VERSION),
#else
        __VERSION__,
#endif
  };
}

}  // namespace radarpr

// Exported even from a library built with -fvisibility=hidden.
#define RADARPR_PLUGIN_EXPORT __attribute__((visibility("default")))

// Use once per plugin, at global scope: exports the ABI record and the registration entry point
// that calls `register_function(radarpr::DescriptorRegistry&)`. Write a ';' after it.
#define RADARPR_PLUGIN(register_function)                                      \
  extern "C" RADARPR_PLUGIN_EXPORT const RadarprPluginAbi radarpr_plugin_abi = \
      radarpr::this_build_plugin_abi(RADARPR_PLUGIN_DECLARED_VERSION_MINOR,    \
                                     RADARPR_PLUGIN_DECLARED_ABI);             \
  extern "C" RADARPR_PLUGIN_EXPORT void radarpr_plugin_register(               \
      radarpr::DescriptorRegistry& registry) {                                 \
    register_function(registry);                                               \
  }                                                                            \
  static_assert(true, "RADARPR_PLUGIN(register_function) is followed by a semicolon")
