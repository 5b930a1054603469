#include "descriptors/descriptor_registry.hpp"

#include <algorithm>
#include <mutex>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "descriptors/opencv_module/opencv_module.hpp"

namespace radarpr {
namespace {

bool is_identifier(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

const ParameterSpec& find_spec(const DescriptorInfo& info, std::string_view parameter) {
  for (const auto& spec : info.parameters) {
    if (spec.name == parameter) return spec;
  }
  std::vector<std::string> known;
  for (const auto& spec : info.parameters) known.push_back(spec.name);
  throw ParameterError(
      std::string(parameter),
      fmt::format("unknown parameter '{}' of descriptor '{}' (known: {})", parameter, info.name,
                  known.empty() ? "none" : fmt::format("{}", fmt::join(known, ", "))));
}

ParameterValue from_json(const ParameterSpec& spec, const nlohmann::json& value) {
  if (value.is_boolean()) return check_parameter_value(spec, value.get<bool>());
  if (value.is_number_integer()) return check_parameter_value(spec, value.get<std::int64_t>());
  if (value.is_number()) return check_parameter_value(spec, value.get<double>());
  if (value.is_string()) return check_parameter_value(spec, value.get<std::string>());
  throw ParameterError(spec.name, fmt::format("parameter '{}' must be a {}, got {}", spec.name,
                                              to_string(spec.kind), value.dump()));
}

bool is_opencv_module_descriptor(std::string_view name) {
  const auto names = opencv_module_descriptor_names();
  return std::binary_search(names.begin(), names.end(), name);
}

// The OpenCV module's descriptors, loaded by the first call. A load that throws leaves the flag
// unset, so the next call tries again (and fails with the same message).
const DescriptorRegistry& opencv_module_registry(std::string_view wanted) {
  static std::once_flag loaded_flag;
  static DescriptorRegistry module;
  std::call_once(loaded_flag, [&] {
    DescriptorRegistry loaded;
    load_opencv_module(loaded, wanted);
    module = std::move(loaded);
  });
  return module;
}

}  // namespace

// The built-ins, filled on first use; add_plugin_descriptors adds to it later. One map sorted by
// name: plugin descriptors sort among the built-ins (all() does not put built-ins first).
DescriptorRegistry& DescriptorRegistry::mutable_global() {
  static DescriptorRegistry registry = [] {
    DescriptorRegistry builtins;
    register_builtin_descriptors(builtins);
    builtins.includes_opencv_module_ = true;
    return builtins;
  }();
  return registry;
}

std::string origin_of(const DescriptorInfo& info) {
  return info.plugin_path.empty() ? std::string("built-in") : "plugin " + info.plugin_path;
}

const DescriptorRegistry& DescriptorRegistry::global() {
  return mutable_global();
}

void DescriptorRegistry::add_plugin_descriptors(const DescriptorRegistry& plugin,
                                                const std::string& plugin_path,
                                                const std::string& plugin_build) {
  DescriptorRegistry& registry = mutable_global();
  for (const auto& [name, _] : plugin.descriptors_) {
    if (registry.contains(name)) {
      throw std::invalid_argument(
          fmt::format("descriptor name '{}' is already registered ({}); rename the descriptor",
                      name, origin_of(registry.info(name))));
    }
  }
  for (const auto& [name, info] : plugin.descriptors_) {
    DescriptorInfo added = info;
    added.plugin_path = plugin_path;
    added.plugin_build = plugin_build;
    registry.descriptors_.emplace(name, std::move(added));
  }
}

void DescriptorRegistry::add(DescriptorInfo info) {
  if (!is_identifier(info.name)) {
    throw std::invalid_argument(
        fmt::format("descriptor name '{}' must be non-empty [a-z0-9_]", info.name));
  }
  if (!info.create) {
    throw std::invalid_argument(fmt::format("descriptor '{}' has no factory", info.name));
  }
  if (contains(info.name)) {
    throw std::invalid_argument(fmt::format("descriptor '{}' is registered twice", info.name));
  }
  std::set<std::string> names;
  for (auto& spec : info.parameters) {
    if (!is_identifier(spec.name) || !names.insert(spec.name).second) {
      throw std::invalid_argument(
          fmt::format("descriptor '{}': parameter name '{}' is empty, repeated or not [a-z0-9_]",
                      info.name, spec.name));
    }
    try {
      spec.default_value = check_parameter_value(spec, spec.default_value);
    } catch (const ParameterError& error) {
      throw std::invalid_argument(
          fmt::format("descriptor '{}': invalid default: {}", info.name, error.what()));
    }
  }
  std::sort(info.parameters.begin(), info.parameters.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  std::string name = info.name;
  descriptors_.emplace(std::move(name), std::move(info));
}

bool DescriptorRegistry::contains(std::string_view name) const {
  return descriptors_.find(name) != descriptors_.end() ||
         (includes_opencv_module_ && is_opencv_module_descriptor(name));
}

const DescriptorInfo* DescriptorRegistry::find(std::string_view name) const {
  const auto it = descriptors_.find(name);
  if (it != descriptors_.end()) return &it->second;
  if (includes_opencv_module_ && is_opencv_module_descriptor(name)) {
    return &opencv_module_registry(fmt::format("descriptor '{}'", name)).info(name);
  }
  return nullptr;
}

const DescriptorInfo& DescriptorRegistry::info(std::string_view name) const {
  const DescriptorInfo* found = find(name);
  if (found == nullptr) throw std::invalid_argument(unknown_descriptor_message(name));
  return *found;
}

std::string DescriptorRegistry::unknown_descriptor_message(std::string_view name) const {
  std::vector<std::string> known;
  for (const auto& [known_name, _] : descriptors_) known.push_back(known_name);
  if (includes_opencv_module_) {
    for (const std::string_view module_name : opencv_module_descriptor_names()) {
      known.emplace_back(module_name);
    }
    std::sort(known.begin(), known.end());
  }
  // A plugin's descriptor is unknown until its plugin is loaded, which is easy to forget.
  return fmt::format(
      "unknown descriptor '{}' (known: {}); a plugin's descriptor needs its plugin loaded: "
      "--plugin PATH, \"plugins\" in the config or $RADARPR_PLUGINS",
      name, fmt::join(known, ", "));
}

std::vector<const DescriptorInfo*> DescriptorRegistry::all() const {
  std::vector<const DescriptorInfo*> infos;
  for (const auto& [_, info] : descriptors_) infos.push_back(&info);
  if (includes_opencv_module_ && !opencv_module_descriptor_names().empty()) {
    for (const DescriptorInfo* info : opencv_module_registry("listing every descriptor").all()) {
      infos.push_back(info);
    }
    std::sort(infos.begin(), infos.end(),
              [](const DescriptorInfo* a, const DescriptorInfo* b) { return a->name < b->name; });
  }
  return infos;
}

DescriptorInstance DescriptorRegistry::create(
    std::string_view name, const std::map<std::string, ParameterValue>& overrides) const {
  const DescriptorInfo& descriptor_info = info(name);
  std::map<std::string, ParameterValue> values;
  for (const auto& spec : descriptor_info.parameters) values.emplace(spec.name, spec.default_value);
  for (const auto& [parameter, value] : overrides) {
    values[parameter] = check_parameter_value(find_spec(descriptor_info, parameter), value);
  }
  ParameterValues resolved(std::move(values));
  DescriptorInstance instance;
  instance.id = canonical_descriptor_id(descriptor_info, resolved);
  instance.name = descriptor_info.name;
  instance.descriptor = descriptor_info.create(resolved);
  instance.create_fresh = [create = descriptor_info.create, resolved] { return create(resolved); };
  instance.parameters = std::move(resolved);
  return instance;
}

DescriptorInstance DescriptorRegistry::create(std::string_view name,
                                              const nlohmann::json& parameters) const {
  const DescriptorInfo& descriptor_info = info(name);
  if (!parameters.is_null() && !parameters.is_object()) {
    throw std::invalid_argument(fmt::format(
        "parameters of descriptor '{}' must be a JSON object, got {}", name, parameters.dump()));
  }
  std::map<std::string, ParameterValue> overrides;
  if (parameters.is_object()) {
    for (const auto& [key, value] : parameters.items()) {
      overrides.emplace(key, from_json(find_spec(descriptor_info, key), value));
    }
  }
  return create(name, overrides);
}

DescriptorInstance DescriptorRegistry::create_from_id(std::string_view id) const {
  const auto colon = id.find(':');
  const std::string_view name = id.substr(0, colon);
  const DescriptorInfo& descriptor_info = info(name);
  std::map<std::string, ParameterValue> overrides;
  if (colon != std::string_view::npos) {
    std::string_view rest = id.substr(colon + 1);
    while (true) {
      const auto comma = rest.find(',');
      const std::string_view assignment = rest.substr(0, comma);
      const auto equals = assignment.find('=');
      if (equals == std::string_view::npos || equals == 0) {
        throw std::invalid_argument(fmt::format(
            "descriptor id '{}': expected key=value after ':', got '{}'", id, assignment));
      }
      const std::string key(assignment.substr(0, equals));
      const ParameterSpec& spec = find_spec(descriptor_info, key);
      if (!overrides.emplace(key, parse_parameter_value(spec, assignment.substr(equals + 1)))
               .second) {
        throw ParameterError(key, fmt::format("descriptor id '{}' sets '{}' twice", id, key));
      }
      if (comma == std::string_view::npos) break;
      rest = rest.substr(comma + 1);
    }
  }
  return create(name, overrides);
}

std::string canonical_descriptor_id(const DescriptorInfo& info, const ParameterValues& values) {
  std::vector<std::string> changed;
  for (const auto& spec : info.parameters) {  // sorted by name in add()
    const auto it = values.all().find(spec.name);
    if (it != values.all().end() && it->second != spec.default_value) {
      changed.push_back(fmt::format("{}={}", spec.name, format_parameter_value(it->second)));
    }
  }
  if (changed.empty()) return info.name;
  return fmt::format("{}:{}", info.name, fmt::join(changed, ","));
}

}  // namespace radarpr
