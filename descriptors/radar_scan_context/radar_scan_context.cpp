#include "descriptors/radar_scan_context/radar_scan_context.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include <cmath>

#include <opencv2/core.hpp>

#include "descriptors/opencv_image.hpp"
#include "descriptors/parity_preset.hpp"
#include "descriptors/radar_scan_context/area_average.hpp"
#include "descriptors/radar_scan_context/column_alignment.hpp"
#include "descriptors/resampling/matlab_imresize.hpp"

namespace radarpr {
namespace {

std::string shape_text(int rows, int cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}

ParameterSpec count_parameter(const char* name, std::int64_t default_value,
                              const char* description) {
  return {.name = name,
          .kind = ParameterKind::integer,
          .default_value = default_value,
          .description = description,
          .minimum = 1.0,
          .maximum = 100000.0};
}

}  // namespace

std::vector<float> radar_scan_context_ring_key(const DescriptorValue& context) {
  if (context.rows < 1 || context.cols < 1 ||
      context.values.size() !=
          static_cast<std::size_t>(context.rows) * static_cast<std::size_t>(context.cols)) {
    throw std::invalid_argument(
        "radar_scan_context: a ring key needs a rings x sectors context, got " +
        shape_text(context.rows, context.cols) + " with " + std::to_string(context.values.size()) +
        " values");
  }
  const auto sectors = static_cast<std::size_t>(context.cols);
  std::vector<float> key;
  key.reserve(static_cast<std::size_t>(context.rows));
  for (auto ring = context.values.begin(); ring != context.values.end();
       ring += static_cast<std::ptrdiff_t>(sectors)) {
    double sum = 0.0;
    for (auto value = ring; value != ring + static_cast<std::ptrdiff_t>(sectors); ++value) {
      sum += *value;
    }
    key.push_back(static_cast<float>(sum / static_cast<double>(sectors)));
  }
  return key;
}

RadarScanContextDescriptor::RadarScanContextDescriptor(RadarScanContextParams params)
    : params_(params) {
  if (params_.rings < 1 || params_.sectors < 1 || params_.candidates < 1) {
    throw std::invalid_argument(
        "radar_scan_context: rings, sectors and candidates must be >= 1, got " +
        std::to_string(params_.rings) + ", " + std::to_string(params_.sectors) + ", " +
        std::to_string(params_.candidates));
  }
}

namespace {

// makeExperience.m's context: imresize(range x azimuth scan, [rings sectors]).
std::vector<float> matlab_context(const cv::Mat& power, int rings, int sectors, bool to_uint8) {
  if (power.empty() || power.type() != CV_8UC1 || power.cols < rings || power.rows < sectors) {
    throw std::invalid_argument("radar_scan_context: expected a CV_8UC1 scan with at least " +
                                std::to_string(sectors) + " azimuths and " + std::to_string(rings) +
                                " range bins, got " + std::to_string(power.rows) + " x " +
                                std::to_string(power.cols) + " of type " +
                                cv::typeToString(power.type()));
  }
  const cv::Mat range_by_azimuth = power.t();
  cv::Mat context;
  if (to_uint8) {
    context = matlab_imresize(range_by_azimuth, rings, sectors);  // uint8, rounded per pass
  } else {
    cv::Mat values;
    range_by_azimuth.convertTo(values, CV_64F);
    context = matlab_imresize(values, rings, sectors);
  }
  cv::Mat as_float;
  context.convertTo(as_float, CV_32F);
  return std::vector<float>(as_float.begin<float>(), as_float.end<float>());
}

}  // namespace

DescriptorValue RadarScanContextDescriptor::extract(const PolarImage& scan) const {
  if (params_.resize == RadarScanContextResize::matlab_bicubic) {
    return DescriptorValue{params_.rings, params_.sectors,
                           matlab_context(opencv_view(scan.power), params_.rings, params_.sectors,
                                          params_.round_to_uint8)};
  }
  std::vector<float> context =
      area_average_range_by_azimuth(opencv_view(scan.power), params_.rings, params_.sectors);
  if (params_.round_to_uint8) {
    for (float& value : context) value = std::round(value);  // half away from zero, 0..255 kept
  }
  return DescriptorValue{params_.rings, params_.sectors, std::move(context)};
}

void RadarScanContextDescriptor::check_context(const DescriptorValue& value,
                                               const char* role) const {
  if (value.rows != params_.rings || value.cols != params_.sectors ||
      value.values.size() !=
          static_cast<std::size_t>(params_.rings) * static_cast<std::size_t>(params_.sectors)) {
    throw std::invalid_argument("radar_scan_context: expected a " +
                                shape_text(params_.rings, params_.sectors) + " context as " + role +
                                ", got " + shape_text(value.rows, value.cols) + " with " +
                                std::to_string(value.values.size()) + " values");
  }
}

double RadarScanContextDescriptor::distance(const DescriptorValue& a,
                                            const DescriptorValue& b) const {
  check_context(a, "first value");
  check_context(b, "second value");
  const std::optional<ColumnAlignment> best =
      best_column_alignment(a.values, b.values, params_.rings, params_.sectors);
  if (!best) return 1.0;
  // Unit columns can give a cosine a rounding error above 1; keep the distance in [0, 2].
  return std::clamp(1.0 - best->similarity, 0.0, 2.0);
}

std::vector<float> RadarScanContextDescriptor::search_key(const DescriptorValue& value) const {
  check_context(value, "search key input");
  return radar_scan_context_ring_key(value);
}

std::optional<double> RadarScanContextDescriptor::estimate_yaw(
    const DescriptorValue& query, const DescriptorValue& database) const {
  check_context(query, "query");
  check_context(database, "database value");
  const std::optional<ColumnAlignment> best =
      best_column_alignment(query.values, database.values, params_.rings, params_.sectors);
  if (!best) return std::nullopt;
  double yaw = 2.0 * std::numbers::pi * best->shift / static_cast<double>(params_.sectors);
  if (yaw > std::numbers::pi) yaw -= 2.0 * std::numbers::pi;  // (-pi, pi]
  return yaw;
}

DescriptorInfo make_radar_scan_context_info() {
  return DescriptorInfo{
      "radar_scan_context",
      "Radar Scan Context: mean power per ring (range) x sector (azimuth), compared by the best "
      "circular sector shift after a ring-key pre-search",
      {parity_parameter("the MulRan evaluator's makeExperience.m, gisbi-kim/scancontext: "
                        "resize=matlab_bicubic, rounding=uint8"),
       {.name = "resize",
        .kind = ParameterKind::choice,
        .default_value = std::string("auto"),
        .description = "shrink of the range x azimuth scan: area (exact area average; radarpr) or "
                       "matlab_bicubic (MATLAB imresize, bicubic anti-aliased; official)",
        .choices = {"auto", "area", "matlab_bicubic"}},
       {.name = "rounding",
        .kind = ParameterKind::choice,
        .default_value = std::string("auto"),
        .description = "none (radarpr) or uint8: the context rounded to integers as MATLAB's "
                       "imresize of a uint8 image does (official)",
        .choices = {"auto", "none", "uint8"}},
       count_parameter("rings", 20, "number of range rings (context rows)"),
       count_parameter("sectors", 60, "number of azimuth sectors (context columns)"),
       count_parameter("candidates", 5,
                       "ring-key nearest neighbours re-ranked by the context distance")},
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        RadarScanContextParams params;
        params.resize =
            preset_choice(values, "resize", "area", "matlab_bicubic") == "matlab_bicubic"
                ? RadarScanContextResize::matlab_bicubic
                : RadarScanContextResize::area;
        params.round_to_uint8 = preset_choice(values, "rounding", "none", "uint8") == "uint8";
        params.rings = static_cast<int>(values.integer("rings"));
        params.sectors = static_cast<int>(values.integer("sectors"));
        params.candidates = static_cast<int>(values.integer("candidates"));
        return std::make_unique<RadarScanContextDescriptor>(params);
      }};
}

RADARPR_REGISTER_DESCRIPTOR(radar_scan_context, make_radar_scan_context_info)

}  // namespace radarpr
