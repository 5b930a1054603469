#include "descriptors/parity_preset.hpp"

namespace radarpr {

ParameterSpec parity_parameter(const std::string& official_code) {
  return {.name = "parity",
          .kind = ParameterKind::choice,
          .default_value = std::string("radarpr"),
          .description = "preset: radarpr (radarpr's own choices) or official (reproduces " +
                         official_code + "); switches set to auto follow it",
          .choices = {"radarpr", "official"}};
}

ParityPreset parity_preset(const ParameterValues& values) {
  return choice_value<ParityPreset>(
      values, "parity", {{"radarpr", ParityPreset::radarpr}, {"official", ParityPreset::official}});
}

std::string preset_choice(const ParameterValues& values, std::string_view name,
                          std::string_view radarpr_value, std::string_view official_value) {
  const std::string& chosen = values.choice(name);
  if (chosen != kPresetAuto) return chosen;
  return std::string(parity_preset(values) == ParityPreset::official ? official_value
                                                                     : radarpr_value);
}

}  // namespace radarpr
