#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "evaluation/cli/commands.hpp"

namespace radarpr::cli {

const char* const kListHelp = R"(usage: radarpr list [--json]

Lists every registered descriptor with its parameters, their kinds, defaults and allowed values.
A descriptor is named on the command line and in configs by its id: the name, then ':' and the
changed parameters, e.g. referee_r:kernel=box,z_q=3.

  --json   print the same as one JSON document
)";

namespace {

std::string describe_values(const ParameterSpec& spec) {
  if (spec.kind == ParameterKind::choice) return fmt::format("{}", fmt::join(spec.choices, "|"));
  std::string text(to_string(spec.kind));
  if (spec.minimum || spec.maximum) {
    text += fmt::format(" in [{}, {}]", spec.minimum ? fmt::format("{}", *spec.minimum) : "-inf",
                        spec.maximum ? fmt::format("{}", *spec.maximum) : "inf");
  }
  return text;
}

}  // namespace

int list_command(const std::vector<std::string>& args) {
  bool json = false;
  for (const auto& arg : args) {
    if (arg == "--help" || arg == "-h") {
      fmt::print("{}", kListHelp);
      return 0;
    } else if (arg == "--json") {
      json = true;
    } else {
      throw UsageError(fmt::format("unknown argument '{}'", arg));
    }
  }
  const auto descriptors = DescriptorRegistry::global().all();
  if (json) {
    nlohmann::json document = nlohmann::json::array();
    for (const auto* info : descriptors) {
      nlohmann::json parameters = nlohmann::json::array();
      for (const auto& spec : info->parameters) {
        nlohmann::json entry{{"name", spec.name},
                             {"kind", to_string(spec.kind)},
                             {"default", format_parameter_value(spec.default_value)},
                             {"description", spec.description}};
        if (!spec.choices.empty()) entry["choices"] = spec.choices;
        if (spec.minimum) entry["minimum"] = *spec.minimum;
        if (spec.maximum) entry["maximum"] = *spec.maximum;
        parameters.push_back(entry);
      }
      document.push_back(
          {{"name", info->name}, {"summary", info->summary}, {"parameters", parameters}});
    }
    fmt::print("{}\n", document.dump(2));
    return 0;
  }
  for (const auto* info : descriptors) {
    fmt::print("{}\n  {}\n", info->name, info->summary);
    for (const auto& spec : info->parameters) {
      fmt::print("    {:<18} = {:<10} {:<28} {}\n", spec.name,
                 format_parameter_value(spec.default_value), describe_values(spec),
                 spec.description);
    }
    fmt::print("\n");
  }
  return 0;
}

}  // namespace radarpr::cli
