#include "descriptors/plugins/plugin_compatibility.hpp"

#include <fmt/format.h>

namespace radarpr {
namespace {

const char* standard_library_name(std::uint32_t library) {
  switch (library) {
    case RADARPR_STDLIB_LIBSTDCXX:
      return "libstdc++";
    case RADARPR_STDLIB_LIBCXX:
      return "libc++";
    default:
      return "an unknown standard library";
  }
}

struct SizeCheck {
  const char* type;
  std::uint32_t RadarprPluginAbi::*member;
};

constexpr SizeCheck kSizeChecks[] = {
    {"std::string", &RadarprPluginAbi::sizeof_string},
    {"std::function", &RadarprPluginAbi::sizeof_function},
    {"std::shared_ptr", &RadarprPluginAbi::sizeof_shared_ptr},
    {"radarpr::DescriptorInfo", &RadarprPluginAbi::sizeof_descriptor_info},
    {"radarpr::ParameterSpec", &RadarprPluginAbi::sizeof_parameter_spec},
    {"radarpr::PolarImage", &RadarprPluginAbi::sizeof_polar_image},
    {"radarpr::DescriptorValue", &RadarprPluginAbi::sizeof_descriptor_value},
};

}  // namespace

const RadarprPluginAbi& host_plugin_abi() {
  static constexpr RadarprPluginAbi host =
      this_build_plugin_abi(RADARPR_VERSION_MINOR, RADARPR_PLUGIN_ABI);
  return host;
}

std::string describe_plugin_abi(const RadarprPluginAbi& abi) {
  return fmt::format("radarpr {}.{}.{} (plugin ABI {}, {}, {} ABI flag {})", abi.version_major,
                     abi.version_minor, abi.version_patch, abi.plugin_abi,
                     abi.compiler != nullptr ? abi.compiler : "unknown compiler",
                     standard_library_name(abi.standard_library), abi.standard_library_abi);
}

std::optional<std::string> plugin_incompatibility(const RadarprPluginAbi& plugin,
                                                  const RadarprPluginAbi& host) {
  if (plugin.magic != host.magic || plugin.record_size != host.record_size) {
    return fmt::format(
        "its ABI record is of another layout (magic {:#x}, {} bytes; expected {:#x}, {} bytes): "
        "built against a much older or newer radarpr",
        plugin.magic, plugin.record_size, host.magic, host.record_size);
  }
  const std::string both = fmt::format("the plugin was built against {}, this program is {}",
                                       describe_plugin_abi(plugin), describe_plugin_abi(host));
  if (plugin.plugin_abi != host.plugin_abi) {
    return fmt::format("plugin ABI {} differs from {}: {}", plugin.plugin_abi, host.plugin_abi,
                       both);
  }
  if (plugin.version_major != host.version_major || plugin.version_minor != host.version_minor) {
    return fmt::format("radarpr version {}.{} differs from {}.{} (major.minor must match): {}",
                       plugin.version_major, plugin.version_minor, host.version_major,
                       host.version_minor, both);
  }
  if (plugin.standard_library != host.standard_library ||
      plugin.standard_library_abi != host.standard_library_abi) {
    return fmt::format("built with {} ABI flag {}, this program with {} ABI flag {}: {}",
                       standard_library_name(plugin.standard_library), plugin.standard_library_abi,
                       standard_library_name(host.standard_library), host.standard_library_abi,
                       both);
  }
  for (const SizeCheck& check : kSizeChecks) {
    if (plugin.*check.member != host.*check.member) {
      return fmt::format("sizeof({}) is {} in the plugin, {} here: {}", check.type,
                         plugin.*check.member, host.*check.member, both);
    }
  }
  return std::nullopt;
}

}  // namespace radarpr
