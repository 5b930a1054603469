#include "descriptors/raplace/raplace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>

#include <opencv2/core.hpp>

#include "descriptors/parity_preset.hpp"
#include "descriptors/raplace/matlab_radon.hpp"
#include "descriptors/raplace/polar_to_cartesian.hpp"
#include "descriptors/raplace/radon_transform.hpp"
#include "descriptors/raplace/sinogram_spectrum.hpp"
#include "descriptors/resampling/matlab_imresize.hpp"

namespace radarpr {
namespace {

// The shrunk length of one sinogram axis: `fixed` when set, else round(full x resize).
// At least `minimum` long: rho needs 2 rows for a non-empty half spectrum.
// MATLAB's imresize(S, resize) makes ceil(full x resize) samples; radarpr rounds to nearest.
int shrunk_length(int full, int fixed, double resize, bool round_up, int minimum,
                  const char* fixed_name, const char* axis) {
  const double scaled = full * resize;
  const int length = fixed > 0  ? fixed
                     : round_up ? static_cast<int>(std::ceil(scaled))
                                : static_cast<int>(std::lround(scaled));
  if (length < minimum || length > full) {
    const std::string parameter = fixed > 0 ? fixed_name : "resize";
    throw ParameterError(parameter, "raplace: the sinogram's " + std::string(axis) + " axis of " +
                                        std::to_string(full) + " would shrink to " +
                                        std::to_string(length) + " (" + parameter + "); expected " +
                                        std::to_string(minimum) + " .. " + std::to_string(full));
  }
  return length;
}

}  // namespace

RaplaceSizes raplace_sizes(const RaplaceParams& params) {
  if (params.cart_size < 1) {
    throw ParameterError(
        "cart_size", "raplace: cart_size must be >= 1, got " + std::to_string(params.cart_size));
  }
  if (!(params.resize > 0.0) || !std::isfinite(params.resize)) {
    throw ParameterError("resize",
                         "raplace: resize must be > 0, got " + std::to_string(params.resize));
  }
  RaplaceSizes sizes;
  sizes.rho_bins = params.radon == RaplaceRadon::matlab
                       ? raplace::matlab_radon_rho_bins(params.cart_size, params.cart_size)
                       : raplace::radon_rho_bins(params.cart_size, params.cart_size);
  const bool round_up = params.shrink == RaplaceShrink::matlab_bicubic;
  sizes.sinogram_rows = shrunk_length(sizes.rho_bins, params.sinogram_rows, params.resize, round_up,
                                      2, "sinogram_rows", "rho");
  sizes.sinogram_cols = shrunk_length(raplace::kRadonAngles, params.sinogram_cols, params.resize,
                                      round_up, 1, "sinogram_cols", "theta");
  sizes.descriptor = {sizes.sinogram_rows / 2, sizes.sinogram_cols};
  return sizes;
}

RaplaceDescriptor::RaplaceDescriptor(RaplaceParams params)
    : params_(params),
      sizes_(raplace_sizes(params_)),
      correlation_(sizes_.descriptor.rows, sizes_.descriptor.cols, params_.shift_axis) {
  if (params_.cart_range_m < 0.0 || !std::isfinite(params_.cart_range_m)) {
    throw ParameterError("cart_range_m",
                         "raplace: cart_range_m must be >= 0 (0 = full range), got " +
                             std::to_string(params_.cart_range_m));
  }
}

DescriptorValue RaplaceDescriptor::extract(const PolarImage& scan) const {
  const double cart_range_m = params_.cart_range_m > 0.0
                                  ? params_.cart_range_m
                                  : scan.range_bin_count() * scan.range_resolution_m;
  cv::Mat cartesian = raplace::polar_to_cartesian(scan, params_.cart_size, cart_range_m);
  if (params_.cart_uint8) {
    cartesian.forEach<float>(
        [](float& value, const int*) { value = std::clamp(std::round(value), 0.0F, 255.0F); });
  }
  const cv::Mat sinogram = raplace::normalize_by_max(params_.radon == RaplaceRadon::matlab
                                                         ? raplace::matlab_radon(cartesian)
                                                         : raplace::radon_transform(cartesian));
  cv::Mat shrunk;
  if (params_.shrink == RaplaceShrink::area) {
    shrunk = raplace::shrink_sinogram(sinogram, sizes_.sinogram_rows, sizes_.sinogram_cols);
  } else if (params_.sinogram_rows == 0 && params_.sinogram_cols == 0) {
    shrunk = matlab_imresize_scale(sinogram, params_.resize);  // imresize(R, resize)
  } else {
    shrunk = matlab_imresize(sinogram, sizes_.sinogram_rows, sizes_.sinogram_cols);
  }
  const cv::Mat spectrum = raplace::rho_spectrum_magnitude(shrunk);
  return {spectrum.rows, spectrum.cols, raplace::z_score(spectrum)};
}

void RaplaceDescriptor::check_shape(const DescriptorValue& value, const char* role) const {
  const DescriptorShape& shape = sizes_.descriptor;
  if (value.rows != shape.rows || value.cols != shape.cols ||
      value.values.size() != shape.element_count()) {
    throw std::invalid_argument(
        "raplace: the " + std::string(role) + " value is " + std::to_string(value.rows) + " x " +
        std::to_string(value.cols) + " with " + std::to_string(value.values.size()) +
        " values, expected " + std::to_string(shape.rows) + " x " + std::to_string(shape.cols));
  }
}

raplace::CorrelationPeak RaplaceDescriptor::similarity(const DescriptorValue& query,
                                                       const DescriptorValue& database) const {
  check_shape(query, "query");
  check_shape(database, "database");
  return correlation_.max_correlation(correlation_.spectra(query.values),
                                      correlation_.spectra(database.values));
}

double RaplaceDescriptor::distance(const DescriptorValue& query,
                                   const DescriptorValue& database) const {
  check_shape(query, "query");
  check_shape(database, "database");
  // The same calls, on the same numbers, as RaplacePreparedDistances: identical results.
  const raplace::LineSpectra query_spectra = correlation_.spectra(query.values);
  const raplace::LineSpectra database_spectra = correlation_.spectra(database.values);
  const double self = correlation_.max_correlation(query_spectra, query_spectra).value;
  const double cross = correlation_.max_correlation(query_spectra, database_spectra).value;
  return raplace_distance_from(params_.distance, self, cross, database_spectra.all_zero);
}

std::unique_ptr<PreparedDistances> RaplaceDescriptor::prepare_distances(
    const std::vector<DescriptorValue>& queries,
    const std::vector<DescriptorValue>& database) const {
  return std::make_unique<RaplacePreparedDistances>(correlation_, params_.distance, queries,
                                                    database);
}

std::optional<double> RaplaceDescriptor::yaw_modulo_pi(const DescriptorValue& query,
                                                       const DescriptorValue& database) const {
  check_shape(query, "query");
  check_shape(database, "database");
  if (params_.shift_axis != raplace::ShiftAxis::theta) return std::nullopt;
  const raplace::LineSpectra query_spectra = correlation_.spectra(query.values);
  const raplace::LineSpectra database_spectra = correlation_.spectra(database.values);
  if (query_spectra.all_zero || database_spectra.all_zero) return std::nullopt;
  const int shift = correlation_.max_correlation(query_spectra, database_spectra).shift;
  // Shift s of the theta columns (180 / cols degrees each) = a turn by s pi / cols, modulo pi.
  double yaw = std::numbers::pi * shift / sizes_.descriptor.cols;
  if (yaw > std::numbers::pi / 2.0) yaw -= std::numbers::pi;
  return yaw;
}

DescriptorInfo make_raplace_info() {
  const RaplaceParams defaults;
  std::vector<ParameterSpec> specs = {
      parity_parameter("the public MATLAB code, hyesu-jang/RaPlace: radon=matlab, "
                       "shrink=matlab_bicubic, cart_rounding=uint8, shift_axis=rho, "
                       "distance=raw_over_1000"),
      {.name = "radon",
       .kind = ParameterKind::choice,
       .default_value = std::string("auto"),
       .description = "point_per_pixel (one point per pixel, ceil(diagonal) bins; radarpr) or "
                      "matlab (MATLAB's radon: 2 x 2 sub-pixels, 2L+1 bins; official)",
       .choices = {"auto", "point_per_pixel", "matlab"}},
      {.name = "shrink",
       .kind = ParameterKind::choice,
       .default_value = std::string("auto"),
       .description = "sinogram shrink: area (radarpr) or matlab_bicubic (MATLAB imresize; "
                      "official)",
       .choices = {"auto", "area", "matlab_bicubic"}},
      {.name = "cart_rounding",
       .kind = ParameterKind::choice,
       .default_value = std::string("auto"),
       .description = "none (radarpr) or uint8: the Cartesian image rounded to 8 bits, as the "
                      "public code reads it from a PNG (official)",
       .choices = {"auto", "none", "uint8"}},
      {.name = "cart_size",
       .kind = ParameterKind::integer,
       .default_value = std::int64_t{defaults.cart_size},
       .description = "side of the Cartesian image in pixels",
       .minimum = 1.0,
       .maximum = 8192.0},
      {.name = "cart_range_m",
       .kind = ParameterKind::number,
       .default_value = defaults.cart_range_m,
       .description = "the Cartesian image covers +-cart_range_m metres; 0 = the sensor's full "
                      "range (range bins x resolution)",
       .minimum = 0.0,
       .maximum = 1e6},
      {.name = "resize",
       .kind = ParameterKind::number,
       .default_value = defaults.resize,
       .description = "sinogram shrink factor per axis (n_rho x 180 -> about 40 x 18)",
       .minimum = 1e-6,
       .maximum = 1.0},
      {.name = "sinogram_rows",
       .kind = ParameterKind::integer,
       .default_value = std::int64_t{defaults.sinogram_rows},
       .description = "rho rows of the shrunk sinogram; 0 = use resize (RaPlace-DS: 16)",
       .minimum = 0.0,
       .maximum = 100000.0},
      {.name = "sinogram_cols",
       .kind = ParameterKind::integer,
       .default_value = std::int64_t{defaults.sinogram_cols},
       .description = "theta columns of the shrunk sinogram; 0 = use resize (RaPlace-DS: 7)",
       .minimum = 0.0,
       .maximum = 180.0},
      {.name = "shift_axis",
       .kind = ParameterKind::choice,
       .default_value = std::string("auto"),
       .description = "circular shift of the similarity: theta (rotation, the paper; radarpr) or "
                      "rho (the public code's fast_dft.m; official)",
       .choices = {"auto", "theta", "rho"}},
      {.name = "distance",
       .kind = ParameterKind::choice,
       .default_value = std::string("auto"),
       .description = "(C(q,q) - C(q,i)) / C(q,q) (the paper; radarpr) or / 1000 (the public "
                      "code; official)",
       .choices = {"auto", "normalized", "raw_over_1000"}},
  };
  return DescriptorInfo{
      "raplace",
      "RaPlace: |DFT along rho| of the Radon sinogram of the Cartesian scan, matched by the best "
      "circular theta shift",
      std::move(specs),
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        RaplaceParams params;
        params.radon = preset_choice(values, "radon", "point_per_pixel", "matlab") == "matlab"
                           ? RaplaceRadon::matlab
                           : RaplaceRadon::point_per_pixel;
        params.shrink =
            preset_choice(values, "shrink", "area", "matlab_bicubic") == "matlab_bicubic"
                ? RaplaceShrink::matlab_bicubic
                : RaplaceShrink::area;
        params.cart_uint8 = preset_choice(values, "cart_rounding", "none", "uint8") == "uint8";
        params.cart_size = static_cast<int>(values.integer("cart_size"));
        params.cart_range_m = values.number("cart_range_m");
        params.resize = values.number("resize");
        params.sinogram_rows = static_cast<int>(values.integer("sinogram_rows"));
        params.sinogram_cols = static_cast<int>(values.integer("sinogram_cols"));
        params.shift_axis = preset_choice(values, "shift_axis", "theta", "rho") == "rho"
                                ? raplace::ShiftAxis::rho
                                : raplace::ShiftAxis::theta;
        params.distance =
            preset_choice(values, "distance", "normalized", "raw_over_1000") == "raw_over_1000"
                ? RaplaceDistance::raw_over_1000
                : RaplaceDistance::normalized;
        return std::make_unique<RaplaceDescriptor>(params);
      },
      [](const Descriptor& descriptor, const PolarImage& scan) {
        const RaplaceParams params = dynamic_cast<const RaplaceDescriptor&>(descriptor).params();
        // As RaplaceDescriptor::extract: 0 means the scan's whole range.
        const double range_m = params.cart_range_m > 0.0
                                   ? params.cart_range_m
                                   : scan.range_bin_count() * scan.range_resolution_m;
        return std::vector<ExtractionStage>{
            {std::string(kPreparationStage), "the Cartesian image (raplace::polar_to_cartesian)",
             [cart_size = params.cart_size, range_m, &scan] {
               raplace::polar_to_cartesian(scan, cart_size, range_m);
             }}};
      }};
}

RADARPR_REGISTER_DESCRIPTOR(raplace, make_raplace_info)

}  // namespace radarpr
