#include "descriptors/plugins/plugin_loader.hpp"

#include <dlfcn.h>

#include <deque>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/plugins/plugin.hpp"
#include "descriptors/plugins/plugin_compatibility.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

using RegisterFunction = void (*)(DescriptorRegistry&);

struct LoadedPlugins {
  std::mutex mutex;
  std::deque<LoadedPlugin> in_order;  // a deque: references handed out stay valid
};

LoadedPlugins& loaded_plugins() {
  static LoadedPlugins plugins;
  return plugins;
}

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
  throw std::invalid_argument(fmt::format("plugin {}: {}", path.string(), what));
}

std::string last_dl_error() {
  const char* error = ::dlerror();
  return error != nullptr ? error : "unknown error";
}

// Closes a library that failed a check before any of its code was called.
struct LibraryHandle {
  void* handle = nullptr;
  ~LibraryHandle() {
    if (handle != nullptr) ::dlclose(handle);
  }
  void* release() {
    void* kept = handle;
    handle = nullptr;
    return kept;
  }
};

std::string build_identity(const fs::path& path) {
  std::error_code error;
  const auto size = fs::file_size(path, error);
  const auto modified = fs::last_write_time(path, error);
  if (error) return path.string();
  return fmt::format("{} {} bytes, modified {}", path.string(), size,
                     modified.time_since_epoch().count());
}

LoadedPlugin load_new_plugin(const fs::path& path) {
  // RTLD_NOW: an unresolved symbol (a plugin built against another radarpr) fails here, not in
  // the middle of a run. RTLD_LOCAL: one plugin's symbols never interpose on another's.
  LibraryHandle library{::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)};
  if (library.handle == nullptr) {
    fail(path, fmt::format("cannot load it: {} (expected an ELF shared library built against "
                           "radarpr, e.g. a CMake MODULE linking radarpr::plugin_api)",
                           last_dl_error()));
  }
  const auto* abi =
      static_cast<const RadarprPluginAbi*>(::dlsym(library.handle, RADARPR_PLUGIN_ABI_SYMBOL));
  const auto register_function =
      reinterpret_cast<RegisterFunction>(::dlsym(library.handle, RADARPR_PLUGIN_REGISTER_SYMBOL));
  if (abi == nullptr || register_function == nullptr) {
    fail(path,
         fmt::format("no radarpr entry point: it exports no '{}' symbol, so it is not a "
                     "radarpr descriptor plugin (end its source with "
                     "RADARPR_PLUGIN(register_function);)",
                     abi == nullptr ? RADARPR_PLUGIN_ABI_SYMBOL : RADARPR_PLUGIN_REGISTER_SYMBOL));
  }
  // The record is checked before any function of the plugin runs.
  if (const auto reason = plugin_incompatibility(*abi, host_plugin_abi())) {
    fail(path, "incompatible build, rebuild it against this radarpr: " + *reason);
  }
  DescriptorRegistry registered;
  try {
    register_function(registered);
  } catch (const std::exception& error) {
    fail(path, fmt::format("its registration failed: {}", error.what()));
  }
  if (registered.all().empty()) fail(path, "it registers no descriptor");

  LoadedPlugin plugin{path, build_identity(path), {}};
  for (const DescriptorInfo* info : registered.all()) plugin.descriptors.push_back(info->name);
  DescriptorRegistry::add_plugin_descriptors(registered, path.string(), plugin.build);
  library.release();  // the registry now holds the plugin's factories: never unloaded
  return plugin;
}

}  // namespace

const LoadedPlugin& load_descriptor_plugin(const fs::path& path) {
  std::error_code error;
  if (!fs::exists(path, error)) fail(path, "file not found");
  if (fs::is_directory(path, error)) fail(path, "is a directory, expected a shared library file");
  const fs::path canonical = fs::canonical(path, error);
  if (error) fail(path, fmt::format("cannot resolve the path: {}", error.message()));

  LoadedPlugins& plugins = loaded_plugins();
  const std::lock_guard lock(plugins.mutex);
  for (const LoadedPlugin& plugin : plugins.in_order) {
    if (plugin.path == canonical) return plugin;
  }
  plugins.in_order.push_back(load_new_plugin(canonical));
  return plugins.in_order.back();
}

std::vector<LoadedPlugin> loaded_descriptor_plugins() {
  LoadedPlugins& plugins = loaded_plugins();
  const std::lock_guard lock(plugins.mutex);
  return {plugins.in_order.begin(), plugins.in_order.end()};
}

std::vector<fs::path> split_plugin_list(const std::string& list) {
  std::vector<fs::path> paths;
  std::size_t start = 0;
  while (start <= list.size()) {
    const auto colon = list.find(':', start);
    const std::string entry =
        list.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    if (!entry.empty()) paths.emplace_back(entry);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return paths;
}

}  // namespace radarpr
