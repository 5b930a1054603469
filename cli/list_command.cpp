#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/verb.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr::cli {

namespace {

constexpr const char* kListDescription =
    R"(the descriptors with their parameters and defaults

Lists every registered descriptor with its parameters (kinds, defaults, allowed values) and, for
its default parameters, its shape, element type, payload bytes and paper bytes (a float64 numpy
file: elements x 8 + 128) on 400 x 3360 and 400 x 3768 scans. A descriptor is named on the
command line and in configs by its id: the name, then ':' and the changed parameters, e.g.
referee_r:kernel=box,z_q=3. Given ids, lists those configurations only.)";

struct ListArguments {
  std::vector<std::string> ids;
  bool json = false;
};

std::string describe_values(const ParameterSpec& spec) {
  if (spec.kind == ParameterKind::choice) return fmt::format("{}", fmt::join(spec.choices, "|"));
  std::string text(to_string(spec.kind));
  if (spec.minimum || spec.maximum) {
    text += fmt::format(" in [{}, {}]", spec.minimum ? fmt::format("{}", *spec.minimum) : "-inf",
                        spec.maximum ? fmt::format("{}", *spec.maximum) : "inf");
  }
  return text;
}

// The scan sizes of the ReFeree paper's radars: CIR204-H (MulRan, Boreas) and CTS350-X (Oxford,
// OORD).
const std::vector<ScanGeometry> kListedGeometries = {{400, 3360, 0.0595238}, {400, 3768, 0.0432}};

struct SizeOnScan {
  ScanGeometry geometry;
  DescriptorShape shape;
};

std::vector<SizeOnScan> sizes_of(const Descriptor& descriptor) {
  std::vector<SizeOnScan> sizes;
  for (const ScanGeometry& geometry : kListedGeometries) {
    sizes.push_back({geometry, descriptor.shape(geometry)});
  }
  return sizes;
}

std::string_view describe_retrieval(const Descriptor& descriptor) {
  switch (descriptor.retrieval_method()) {
    case RetrievalMethod::kdtree:
      return "KD-tree";
    case RetrievalMethod::key_then_rerank:
      return "KD-tree over keys, then re-rank";
    case RetrievalMethod::exhaustive:
      return "exhaustive";
    case RetrievalMethod::exhaustive_l2:
      return "exhaustive L2 (matrix products)";
  }
  return "unknown";
}

nlohmann::json parameters_json(const DescriptorInfo& info) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const auto& spec : info.parameters) {
    nlohmann::json entry{{"name", spec.name},
                         {"kind", to_string(spec.kind)},
                         {"default", format_parameter_value(spec.default_value)},
                         {"description", spec.description}};
    if (!spec.choices.empty()) entry["choices"] = spec.choices;
    if (spec.minimum) entry["minimum"] = *spec.minimum;
    if (spec.maximum) entry["maximum"] = *spec.maximum;
    parameters.push_back(entry);
  }
  return parameters;
}

nlohmann::json instance_json(const DescriptorInstance& instance) {
  const Descriptor& descriptor = *instance.descriptor;
  nlohmann::json sizes = nlohmann::json::array();
  for (const auto& [geometry, shape] : sizes_of(descriptor)) {
    sizes.push_back({{"scan", {geometry.azimuths, geometry.range_bins}},
                     {"shape", {shape.rows, shape.cols}},
                     {"payload_bytes", shape.payload_bytes()},
                     {"paper_bytes", shape.paper_bytes()}});
  }
  return {{"id", instance.id},
          {"element_type", kDescriptorElementType},
          {"sizes", sizes},
          {"rotation_invariant", descriptor.rotation_invariant()},
          {"trainable", descriptor.trainable()},
          {"retrieval", describe_retrieval(descriptor)}};
}

void print_instance(const DescriptorInstance& instance) {
  const Descriptor& descriptor = *instance.descriptor;
  const auto sizes = sizes_of(descriptor);
  std::vector<std::string> described;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const DescriptorShape& shape = sizes[i].shape;
    const auto scan =
        fmt::format("{}x{}", sizes[i].geometry.azimuths, sizes[i].geometry.range_bins);
    if (i > 0 && shape == sizes[i - 1].shape) {
      described.back() += " and " + scan;
      continue;
    }
    described.push_back(fmt::format("{}x{} {}, payload {} B, paper {} B on {}", shape.rows,
                                    shape.cols, kDescriptorElementType, shape.payload_bytes(),
                                    shape.paper_bytes(), scan));
  }
  fmt::print("  id {}: {} scans\n  {}; retrieval: {}{}\n", instance.id,
             fmt::join(described, " scans; "),
             descriptor.rotation_invariant() ? "rotation-invariant" : "not rotation-invariant",
             describe_retrieval(descriptor), descriptor.trainable() ? "; trainable" : "");
}

int list(const ListArguments& arguments) {
  const std::vector<std::string>& ids = arguments.ids;
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  std::vector<DescriptorInstance> instances;
  if (ids.empty()) {
    for (const auto* info : registry.all())
      instances.push_back(registry.create_from_id(info->name));
  } else {
    for (const auto& id : ids) instances.push_back(registry.create_from_id(id));
  }
  if (arguments.json) {
    nlohmann::json document = nlohmann::json::array();
    for (const auto& instance : instances) {
      const DescriptorInfo& info = registry.info(instance.name);
      nlohmann::json entry{
          {"name", info.name}, {"summary", info.summary}, {"parameters", parameters_json(info)}};
      entry.update(instance_json(instance));
      entry["origin"] = info.plugin_path.empty() ? "built-in" : "plugin";
      if (!info.plugin_path.empty()) entry["plugin"] = info.plugin_path;
      document.push_back(entry);
    }
    fmt::print("{}\n", document.dump(2));
    return 0;
  }
  for (const auto& instance : instances) {
    const DescriptorInfo& info = registry.info(instance.name);
    fmt::print("{}\n  {}\n", info.name, info.summary);
    if (!info.plugin_path.empty()) fmt::print("  from plugin {}\n", info.plugin_path);
    print_instance(instance);
    if (ids.empty()) {
      for (const auto& spec : info.parameters) {
        fmt::print("    {:<18} = {:<10} {:<28} {}\n", spec.name,
                   format_parameter_value(spec.default_value), describe_values(spec),
                   spec.description);
      }
    }
    fmt::print("\n");
  }
  return 0;
}

// The arguments and options of `radarpr list`, and what it does with them.
VerbAction define_list(CLI::App& verb) {
  auto arguments = std::make_shared<ListArguments>();
  verb.add_option("ID", arguments->ids,
                  "list these configurations only, e.g. referee_r:kernel=box,z_q=3");
  verb.add_flag("--json", arguments->json, "print the same as one JSON document");
  return [arguments] { return list(*arguments); };
}

}  // namespace

Verb list_verb() {
  return {"list", kListDescription, define_list};
}

}  // namespace radarpr::cli
