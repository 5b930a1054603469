// Fuzz target: the check of a plugin's ABI record, what the loader reads from a plugin file
// before calling any of its code, and the plugin list of $RADARPR_PLUGINS. Input: the record's
// bytes (without its compiler pointer), the compiler text, then the list after a NUL. The
// loading itself (dlopen) is not fuzzed: it runs the library's initialisers, which is what loading
// a plugin means.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "descriptors/plugins/plugin_compatibility.hpp"
#include "descriptors/plugins/plugin_loader.hpp"
#include "tests/fuzz/fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace radarpr;
  RadarprPluginAbi record{};
  constexpr std::size_t kFields = offsetof(RadarprPluginAbi, compiler);
  std::memcpy(&record, data, std::min(size, kFields));
  const std::string_view rest =
      size > kFields ? fuzz::as_text(data + kFields, size - kFields) : std::string_view();
  const std::string compiler(rest.substr(0, rest.find('\0')));
  const std::string list(rest.size() > compiler.size() ? rest.substr(compiler.size() + 1) : "");
  record.compiler =
      (size > kFields && !rest.empty() && rest.front() == '\x01') ? nullptr : compiler.c_str();

  const RadarprPluginAbi& host = host_plugin_abi();
  const auto reason = plugin_incompatibility(record, host);
  // A record equal to the host's in every checked field is compatible; any difference is named.
  if (reason && reason->empty()) std::abort();
  static_cast<void>(describe_plugin_abi(record));
  if (plugin_incompatibility(host, host)) std::abort();

  for (const auto& path : split_plugin_list(list)) {
    if (path.empty()) std::abort();  // empty entries are skipped
  }
  return 0;
}
