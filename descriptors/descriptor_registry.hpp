#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "descriptors/descriptor.hpp"
#include "descriptors/extraction_stages.hpp"
#include "descriptors/parameters.hpp"

namespace radarpr {

// Everything the registry knows about one descriptor name.
struct DescriptorInfo {
  std::string name;
  std::string summary;
  std::vector<ParameterSpec> parameters;
  std::function<std::unique_ptr<Descriptor>(const ParameterValues&)> create;
  // The stages of its extraction that `radarpr bench` times on their own; empty (or returning
  // none): the extraction is timed as one "descriptor" stage.
  ExtractionStagesFunction stages;
  // Set by the plugin loader for a descriptor a plugin registered; empty for a built-in. The
  // build identity (path, size, modification time) keys the descriptor cache, so that a rebuilt
  // plugin never reuses values its previous build extracted.
  std::string plugin_path;
  std::string plugin_build;
};

// "built-in" or "plugin <path>", for messages.
std::string origin_of(const DescriptorInfo& info);

// One configured descriptor: its canonical id names its results on disk and on the command line.
struct DescriptorInstance {
  std::string id;  // e.g. "referee_r:kernel=box,z_q=3"; just the name when all are defaults
  std::string name;
  std::string label;  // how tables name it ("RadarSC-DS"); empty = the id
  const std::string& display_name() const { return label.empty() ? id : label; }
  ParameterValues parameters;
  std::shared_ptr<const Descriptor> descriptor;
  // A new descriptor with the same parameters: trainable descriptors are trained once per
  // dataset, each on a fresh, untrained instance.
  std::function<std::unique_ptr<Descriptor>()> create_fresh;
};

// Descriptors by name. The global registry is a function-local static filled on first use by
// the generated register_builtin_descriptors(), which calls every descriptor file's
// RADARPR_REGISTER_DESCRIPTOR function by name: the calls keep the linker from dropping those
// object files out of a static library, and no static-initialisation order is involved. Plugins
// (descriptors/plugins/) add to it afterwards, through add_plugin_descriptors only.
//
// The global registry also answers for the OpenCV module's descriptors
// (opencv_module/opencv_module.hpp): it knows their names from the build, so contains() and
// unknown_descriptor_message() do not load the module; info(), create*() of one of them and all()
// load it once (thread-safe), and throw std::runtime_error naming the module's path and the
// descriptor when it is missing or does not match the program.
class DescriptorRegistry {
 public:
  static const DescriptorRegistry& global();
  // Adds every descriptor of `plugin` (a registry the plugin filled) to the global registry,
  // marked with the plugin's path and build identity; all of them or, when a name is already
  // registered, none: throws std::invalid_argument naming the name and who registered it first.
  // Not synchronised with readers: plugins are loaded before any work starts.
  static void add_plugin_descriptors(const DescriptorRegistry& plugin,
                                     const std::string& plugin_path,
                                     const std::string& plugin_build);

  DescriptorRegistry() = default;
  void add(DescriptorInfo info);  // throws std::invalid_argument on a duplicate or bad spec

  bool contains(std::string_view name) const;
  const DescriptorInfo& info(std::string_view name) const;  // throws, listing the known names
  // "unknown descriptor 'x' (known: ...)", with a hint about plugins.
  std::string unknown_descriptor_message(std::string_view name) const;
  std::vector<const DescriptorInfo*> all() const;  // sorted by name; loads the OpenCV module

  // `parameters` is a JSON object of overrides; unknown keys and bad values throw ParameterError.
  DescriptorInstance create(std::string_view name, const nlohmann::json& parameters) const;
  DescriptorInstance create(std::string_view name,
                            const std::map<std::string, ParameterValue>& overrides) const;
  // Parses a canonical (or any equivalent) id such as "referee_r:z_q=3,kernel=box".
  DescriptorInstance create_from_id(std::string_view id) const;

 private:
  static DescriptorRegistry& mutable_global();
  // The descriptor named `name`, or nullptr; loads the OpenCV module for one of its names.
  const DescriptorInfo* find(std::string_view name) const;

  std::map<std::string, DescriptorInfo, std::less<>> descriptors_;
  // Set for the global registry only: the OpenCV module's descriptors are its too.
  bool includes_opencv_module_ = false;
};

// Canonical id: name, then ":" and the non-default parameters as key=value sorted by key.
std::string canonical_descriptor_id(const DescriptorInfo& info, const ParameterValues& values);

// Defined in the build-generated builtin_descriptors.cpp.
void register_builtin_descriptors(DescriptorRegistry& registry);

}  // namespace radarpr

// Registers a built-in descriptor; use once per descriptor, at namespace radarpr scope in its .cpp,
// with a function returning its DescriptorInfo. The build scans for this line (one per line,
// starting the line), so adding a descriptor edits nothing outside its own folder.
#define RADARPR_REGISTER_DESCRIPTOR(symbol, make_info)              \
  void register_descriptor_##symbol(DescriptorRegistry& registry) { \
    registry.add(make_info());                                      \
  }
