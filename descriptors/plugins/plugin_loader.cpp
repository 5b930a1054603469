#include "descriptors/plugins/plugin_loader.hpp"

#include <cxxabi.h>
#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

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

// How messages name a plugin: the path as the user gave it, and where it leads when that differs.
std::string plugin_label(const fs::path& given, const fs::path& canonical) {
  if (canonical.empty() || given == canonical) return given.string();
  return fmt::format("{} ({})", given.string(), canonical.string());
}

[[noreturn]] void fail(const std::string& label, const std::string& what) {
  throw std::invalid_argument(fmt::format("plugin {}: {}", label, what));
}

std::string last_dl_error() {
  const char* error = ::dlerror();
  return error != nullptr ? error : "unknown error";
}

// Closes a library that failed a check: nothing of it (code, typeinfo, exception object) may be
// used after this runs.
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

// The symbol a dlerror text such as "/p/x.so: undefined symbol: _ZN7radarpr3fooEv" names,
// demangled when it is a C++ name.
std::string undefined_symbol_in(const std::string& dl_error) {
  constexpr std::string_view marker = "undefined symbol: ";
  const auto at = dl_error.find(marker);
  if (at == std::string::npos) return "";
  std::string symbol = dl_error.substr(at + marker.size());
  symbol = symbol.substr(0, symbol.find_first_of(" ,\t\n"));
  int status = 0;
  const std::unique_ptr<char, decltype(&std::free)> demangled(
      abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), &std::free);
  return status == 0 && demangled ? std::string(demangled.get()) : symbol;
}

// A plugin built against another radarpr usually fails RTLD_NOW on a radarpr function this
// program lacks, before its ABI record can be read. Opening it again with lazy binding (functions
// resolve at their first call, which never comes) reads the record, so the user learns about the
// version mismatch rather than one symbol. Its static initialisers run again, as at any load.
[[noreturn]] void fail_on_undefined_symbol(const fs::path& path, const std::string& label,
                                           const std::string& dl_error) {
  const std::string symbol = undefined_symbol_in(dl_error);
  std::optional<std::string> incompatibility;
  {
    LibraryHandle lazy{::dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL)};
    if (lazy.handle != nullptr) {
      if (const auto* abi = static_cast<const RadarprPluginAbi*>(
              ::dlsym(lazy.handle, RADARPR_PLUGIN_ABI_SYMBOL))) {
        incompatibility = plugin_incompatibility(*abi, host_plugin_abi());
      }
    }
  }
  if (incompatibility) {
    fail(label, "incompatible build, rebuild it against this radarpr: " + *incompatibility);
  }
  if (symbol.empty()) fail(label, fmt::format("cannot load it: {}", dl_error));
  fail(label, fmt::format("it needs symbol {} that this radarpr does not provide: built against "
                          "another radarpr version?",
                          symbol));
}

// Runs the plugin's registration into `registered`. What it throws is turned into a message
// inside the handler: the exception object (its typeinfo and destructor may live in the plugin)
// is gone before the caller fails and the plugin is closed.
std::optional<std::string> registration_failure(RegisterFunction register_function,
                                                DescriptorRegistry& registered) {
  try {
    register_function(registered);
  } catch (const std::exception& error) {
    return fmt::format("its registration failed: {}", error.what());
  } catch (...) {
    return "its registration threw an exception that is not a std::exception (throw "
           "std::invalid_argument or another std::exception, with a message)";
  }
  return std::nullopt;
}

LoadedPlugin load_new_plugin(const fs::path& path, const std::string& label) {
  // RTLD_NOW: an unresolved symbol (a plugin built against another radarpr) fails here, not in
  // the middle of a run. RTLD_LOCAL: one plugin's symbols never interpose on another's. The
  // plugin's static initialisers run here, before its ABI record can be checked.
  LibraryHandle library{::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)};
  if (library.handle == nullptr) {
    const std::string dl_error = last_dl_error();
    if (dl_error.find("undefined symbol") != std::string::npos) {
      fail_on_undefined_symbol(path, label, dl_error);
    }
    fail(label, fmt::format("cannot load it: {} (expected an ELF shared library built against "
                            "radarpr, e.g. a CMake MODULE linking radarpr::plugin_api)",
                            dl_error));
  }
  const auto* abi =
      static_cast<const RadarprPluginAbi*>(::dlsym(library.handle, RADARPR_PLUGIN_ABI_SYMBOL));
  const auto register_function =
      reinterpret_cast<RegisterFunction>(::dlsym(library.handle, RADARPR_PLUGIN_REGISTER_SYMBOL));
  if (abi == nullptr || register_function == nullptr) {
    fail(label,
         fmt::format("no radarpr entry point: it exports no '{}' symbol, so it is not a "
                     "radarpr descriptor plugin (end its source with "
                     "RADARPR_PLUGIN(register_function);)",
                     abi == nullptr ? RADARPR_PLUGIN_ABI_SYMBOL : RADARPR_PLUGIN_REGISTER_SYMBOL));
  }
  // The record is checked before the registration (or any other plugin function) is called.
  if (const auto reason = plugin_incompatibility(*abi, host_plugin_abi())) {
    fail(label, "incompatible build, rebuild it against this radarpr: " + *reason);
  }
  // Declared after `library`: its factories (plugin code) are destroyed before a dlclose.
  DescriptorRegistry registered;
  if (const auto failure = registration_failure(register_function, registered)) {
    fail(label, *failure);
  }
  if (registered.all().empty()) fail(label, "it registers no descriptor");

  LoadedPlugin plugin{path, build_identity(path), {}};
  for (const DescriptorInfo* info : registered.all()) plugin.descriptors.push_back(info->name);
  try {
    DescriptorRegistry::add_plugin_descriptors(registered, path.string(), plugin.build);
  } catch (const std::invalid_argument& error) {
    fail(label, error.what());
  }
  library.release();  // the registry now holds the plugin's factories: never unloaded
  return plugin;
}

}  // namespace

const LoadedPlugin& load_descriptor_plugin(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) fail(path.string(), "file not found");
  if (error) {
    // E.g. a folder on the way that this user may not enter: not the same as a missing file.
    fail(path.string(), fmt::format("cannot access it: {}", error.message()));
  }
  if (fs::is_directory(status)) {
    fail(path.string(), "is a directory, expected a shared library file");
  }
  const fs::path canonical = fs::canonical(path, error);
  if (error) fail(path.string(), fmt::format("cannot resolve the path: {}", error.message()));
  const std::string label = plugin_label(path, canonical);
  if (::access(canonical.c_str(), R_OK) != 0) {
    fail(label, fmt::format("cannot read it: {}",
                            std::error_code(errno, std::generic_category()).message()));
  }

  LoadedPlugins& plugins = loaded_plugins();
  const std::lock_guard lock(plugins.mutex);
  for (const LoadedPlugin& plugin : plugins.in_order) {
    if (plugin.path == canonical) return plugin;
  }
  plugins.in_order.push_back(load_new_plugin(canonical, label));
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
