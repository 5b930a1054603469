#include "descriptors/radar_scan_context/radar_scan_context.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "descriptors/radar_scan_context/area_average.hpp"
#include "descriptors/radar_scan_context/column_alignment.hpp"

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

DescriptorValue RadarScanContextDescriptor::extract(const PolarImage& scan) const {
  return DescriptorValue{params_.rings, params_.sectors,
                         area_average_range_by_azimuth(scan.power, params_.rings, params_.sectors)};
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
      {count_parameter("rings", 20, "number of range rings (context rows)"),
       count_parameter("sectors", 60, "number of azimuth sectors (context columns)"),
       count_parameter("candidates", 5,
                       "ring-key nearest neighbours re-ranked by the context distance")},
      [](const ParameterValues& values) -> std::unique_ptr<Descriptor> {
        RadarScanContextParams params;
        params.rings = static_cast<int>(values.integer("rings"));
        params.sectors = static_cast<int>(values.integer("sectors"));
        params.candidates = static_cast<int>(values.integer("candidates"));
        return std::make_unique<RadarScanContextDescriptor>(params);
      }};
}

RADARPR_REGISTER_DESCRIPTOR(radar_scan_context, make_radar_scan_context_info)

}  // namespace radarpr
