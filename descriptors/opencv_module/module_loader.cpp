// load_opencv_module() of the `radarpr` program: loads the shared OpenCV module (opencv_module.hpp)
// from the program's own location. Never from the current directory or a path the environment
// names: loading a library someone else chose would run their code.
#include <dlfcn.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/opencv_module/module_entry.hpp"
#include "descriptors/opencv_module/opencv_module.hpp"
#include "descriptors/plugins/plugin_compatibility.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using RegisterFunction = void (*)(DescriptorRegistry&);

// Where the module may be: next to the program (a build tree, build/radarpr) or in the installed
// package's library folder (bin/radarpr and lib/radarpr/), in that order.
std::vector<fs::path> module_candidates() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) {
    throw std::runtime_error(fmt::format(
        "cannot find radarpr's OpenCV module: the program's own path (/proc/self/exe) is "
        "unreadable: {}",
        error.message()));
  }
  const fs::path folder = program.parent_path();
  return {folder / RADARPR_OPENCV_MODULE_FILE,
          (folder / RADARPR_OPENCV_MODULE_FROM_PROGRAM / RADARPR_OPENCV_MODULE_FILE)
              .lexically_normal()};
}

std::string last_dl_error() {
  const char* error = ::dlerror();
  return error != nullptr ? error : "unknown error";
}

[[noreturn]] void fail(const fs::path& path, std::string_view wanted, const std::string& what) {
  throw std::runtime_error(
      fmt::format("{} needs radarpr's OpenCV module {}, which {}; rebuild radarpr (cmake "
                  "--build) or reinstall it, so that the module matches the program",
                  wanted, path.string(), what));
}

// What the module's registration threw, as text: the exception object may live in the module.
std::optional<std::string> registration_failure(RegisterFunction register_function,
                                                DescriptorRegistry& registered) {
  try {
    register_function(registered);
  } catch (const std::exception& error) {
    return error.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
  return std::nullopt;
}

}  // namespace

void load_opencv_module(DescriptorRegistry& registry, std::string_view wanted) {
  const std::vector<fs::path> candidates = module_candidates();
  const auto found = std::find_if(candidates.begin(), candidates.end(), [](const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error);
  });
  if (found == candidates.end()) {
    throw std::runtime_error(fmt::format(
        "{} needs radarpr's OpenCV module, which is missing: expected {} (a build tree) or {} "
        "(an installed radarpr); build it (cmake --build) or reinstall radarpr",
        wanted, candidates[0].string(), candidates[1].string()));
  }
  const fs::path& path = *found;
  // RTLD_NOW: a function the program does not provide fails here, with its name, not in the
  // middle of a run. RTLD_LOCAL: the module's symbols never interpose on a plugin's.
  void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) fail(path, wanted, "cannot be loaded: " + last_dl_error());
  // From here on the module is never closed: a failed check leaves it mapped and unused, and a
  // successful one hands its factories to the registry.
  const auto* abi =
      static_cast<const RadarprPluginAbi*>(::dlsym(library, RADARPR_OPENCV_MODULE_ABI_SYMBOL));
  const auto register_function =
      reinterpret_cast<RegisterFunction>(::dlsym(library, RADARPR_OPENCV_MODULE_REGISTER_SYMBOL));
  if (abi == nullptr || register_function == nullptr) {
    fail(path, wanted,
         fmt::format("exports no '{}': not radarpr's OpenCV module",
                     abi == nullptr ? RADARPR_OPENCV_MODULE_ABI_SYMBOL
                                    : RADARPR_OPENCV_MODULE_REGISTER_SYMBOL));
  }
  const RadarprPluginAbi& host = host_plugin_abi();
  if (const auto reason = plugin_incompatibility(*abi, host)) {
    fail(path, wanted, "was built for another radarpr: " + *reason);
  }
  if (abi->version_patch != host.version_patch) {
    fail(path, wanted,
         fmt::format("was built for another radarpr: {}, this program is {}",
                     describe_plugin_abi(*abi), describe_plugin_abi(host)));
  }
  DescriptorRegistry registered;
  if (const auto failure = registration_failure(register_function, registered)) {
    fail(path, wanted, "failed to register its descriptors: " + *failure);
  }
  std::vector<std::string_view> names;
  for (const DescriptorInfo* info : registered.all()) names.push_back(info->name);
  const auto expected = opencv_module_descriptor_names();
  if (!std::equal(names.begin(), names.end(), expected.begin(), expected.end())) {
    fail(path, wanted,
         fmt::format("registers the descriptors {}, where this program expects {}",
                     fmt::join(names, ", "), fmt::join(expected, ", ")));
  }
  for (const DescriptorInfo* info : registered.all()) registry.add(*info);
}

}  // namespace radarpr
