#pragma once

#include <string>
#include <string_view>

#include "descriptors/parameters.hpp"

namespace radarpr {

// A descriptor's `parity` parameter: `radarpr` (the default: radarpr's own choices) or `official`
// (reproduce the authors' public code, docs/descriptors.md). Every switch a preset sets is a
// choice parameter whose default `auto` means "as the preset says", so that an explicit value
// still overrides the preset (`raplace:parity=official,shift_axis=theta`).
enum class ParityPreset { radarpr, official };

inline constexpr std::string_view kPresetAuto = "auto";

// The `parity` spec; `official_code` names the code the official preset reproduces.
ParameterSpec parity_parameter(const std::string& official_code);

ParityPreset parity_preset(const ParameterValues& values);

// The value of choice `name`: its own when set, else `radarpr_value` or `official_value` as the
// preset says.
std::string preset_choice(const ParameterValues& values, std::string_view name,
                          std::string_view radarpr_value, std::string_view official_value);

}  // namespace radarpr
