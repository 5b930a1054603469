#include "descriptors/features/cen2018_parameters.hpp"

#include <cstdint>
#include <string>

namespace radarpr {
namespace {

ParameterSpec choice(std::string name, std::string default_choice, std::vector<std::string> choices,
                     std::string description) {
  ParameterSpec spec;
  spec.name = std::move(name);
  spec.kind = ParameterKind::choice;
  spec.default_value = std::move(default_choice);
  spec.choices = std::move(choices);
  spec.description = std::move(description);
  return spec;
}

ParameterSpec number(std::string name, double default_value, double minimum, double maximum,
                     std::string description) {
  ParameterSpec spec;
  spec.name = std::move(name);
  spec.kind = ParameterKind::number;
  spec.default_value = default_value;
  spec.minimum = minimum;
  spec.maximum = maximum;
  spec.description = std::move(description);
  return spec;
}

template <typename Enum>
Enum pick(const ParameterValues& values, const char* name,
          std::initializer_list<std::pair<const char*, Enum>> options) {
  const std::string& text = values.choice(name);
  for (const auto& [option, value] : options) {
    if (text == option) return value;
  }
  throw ParameterError(name, std::string("cen2018: unknown ") + name + " '" + text + "'");
}

}  // namespace

std::vector<ParameterSpec> cen2018_parameter_specs() {
  const Cen2018Params defaults;
  ParameterSpec min_range;
  min_range.name = "min_range_bins";
  min_range.kind = ParameterKind::integer;
  min_range.default_value = std::int64_t{defaults.min_range_bins};
  min_range.minimum = 0.0;
  min_range.maximum = 100000.0;
  min_range.description = "a feature at range bin r is kept only if r > min_range_bins";
  return {
      choice("detrend", "row_mean", {"row_mean", "median"},
             "trend removed from each azimuth: its mean, or a running median of width 200 bins"),
      choice("kernel", "gaussian", {"gaussian", "box"},
             "range smoothing: Gaussian of `sigma` bins truncated at 3 sigma, or a 17-bin box"),
      number("sigma", defaults.sigma, 0.5, 1000.0,
             "standard deviation of the Gaussian kernel in range bins (not used by `box`)"),
      choice("sigma_convention", "negative_rms", {"negative_rms", "negative_rms_x2"},
             "noise scale: RMS of the negative detrended bins, or sqrt(2) times it (yeti C++)"),
      number("z_q", defaults.z_q, 0.0, 1000.0,
             "detection threshold in noise-scale units (6 in the paper, 3 in public code)"),
      min_range,
  };
}

Cen2018Params cen2018_params_from(const ParameterValues& values) {
  Cen2018Params params;
  params.detrend = pick<CenDetrend>(
      values, "detrend", {{"row_mean", CenDetrend::row_mean}, {"median", CenDetrend::median}});
  params.kernel = pick<CenKernel>(values, "kernel",
                                  {{"gaussian", CenKernel::gaussian}, {"box", CenKernel::box}});
  params.sigma = values.number("sigma");
  params.sigma_convention =
      pick<CenSigmaConvention>(values, "sigma_convention",
                               {{"negative_rms", CenSigmaConvention::negative_rms},
                                {"negative_rms_x2", CenSigmaConvention::negative_rms_x2}});
  params.z_q = values.number("z_q");
  params.min_range_bins = static_cast<int>(values.integer("min_range_bins"));
  return params;
}

}  // namespace radarpr
