#include "descriptors/features/cen2018_parameters.hpp"

#include <cstdint>
#include <string>

namespace radarpr {
std::vector<ParameterSpec> cen2018_parameter_specs() {
  const Cen2018Params defaults;
  return {
      {.name = "detrend",
       .kind = ParameterKind::choice,
       .default_value = std::string("row_mean"),
       .description =
           "trend removed from each azimuth: its mean, or a running median of width 200 bins",
       .choices = {"row_mean", "median"}},
      {.name = "kernel",
       .kind = ParameterKind::choice,
       .default_value = std::string("gaussian"),
       .description =
           "range smoothing: Gaussian of `sigma` bins truncated at 3 sigma, or a 17-bin box",
       .choices = {"gaussian", "box"}},
      {.name = "sigma",
       .kind = ParameterKind::number,
       .default_value = defaults.sigma,
       .description = "standard deviation of the Gaussian kernel in range bins (not used by `box`)",
       .minimum = 0.5,
       .maximum = 1000.0},
      {.name = "sigma_convention",
       .kind = ParameterKind::choice,
       .default_value = std::string("negative_rms"),
       .description =
           "noise scale: RMS of the negative detrended bins, or sqrt(2) times it (yeti C++)",
       .choices = {"negative_rms", "negative_rms_x2"}},
      {.name = "z_q",
       .kind = ParameterKind::number,
       .default_value = defaults.z_q,
       .description = "detection threshold in noise-scale units (6 in the paper, 3 in public code)",
       .minimum = 0.0,
       .maximum = 1000.0},
      {.name = "min_range_bins",
       .kind = ParameterKind::integer,
       .default_value = std::int64_t{defaults.min_range_bins},
       .description = "a feature at range bin r is kept only if r > min_range_bins",
       .minimum = 0.0,
       .maximum = 100000.0},
  };
}

Cen2018Params cen2018_params_from(const ParameterValues& values) {
  Cen2018Params params;
  params.detrend = choice_value<CenDetrend>(
      values, "detrend", {{"row_mean", CenDetrend::row_mean}, {"median", CenDetrend::median}});
  params.kernel = choice_value<CenKernel>(
      values, "kernel", {{"gaussian", CenKernel::gaussian}, {"box", CenKernel::box}});
  params.sigma = values.number("sigma");
  params.sigma_convention =
      choice_value<CenSigmaConvention>(values, "sigma_convention",
                                       {{"negative_rms", CenSigmaConvention::negative_rms},
                                        {"negative_rms_x2", CenSigmaConvention::negative_rms_x2}});
  params.z_q = values.number("z_q");
  params.min_range_bins = static_cast<int>(values.integer("min_range_bins"));
  return params;
}

}  // namespace radarpr
