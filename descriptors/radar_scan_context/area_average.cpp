#include "descriptors/radar_scan_context/area_average.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace radarpr {

std::vector<AreaSpan> area_spans(int inputs, int outputs) {
  if (outputs < 1 || outputs > inputs) {
    throw std::invalid_argument("area average: cannot shrink " + std::to_string(inputs) +
                                " bins to " + std::to_string(outputs) +
                                " cells (need 1 <= cells <= bins)");
  }
  const std::int64_t n = inputs;
  const std::int64_t m = outputs;
  std::vector<AreaSpan> spans;
  spans.reserve(static_cast<std::size_t>(outputs));
  for (std::int64_t i = 0; i < m; ++i) {
    const std::int64_t begin = i * n;  // in units of 1/m bin
    const std::int64_t end = (i + 1) * n;
    const std::int64_t first = begin / m;
    const std::int64_t last = (end - 1) / m;  // the bin holding the cell's last unit
    spans.push_back(
        {static_cast<int>(first), static_cast<int>(last), begin - first * m, (last + 1) * m - end});
  }
  return spans;
}

std::vector<float> area_average_range_by_azimuth(const cv::Mat& power, int rings, int sectors) {
  if (power.empty() || power.type() != CV_8UC1) {
    throw std::invalid_argument(
        "radar_scan_context: expected a non-empty CV_8UC1 A x R polar image, got " +
        std::to_string(power.rows) + " x " + std::to_string(power.cols) + " of type " +
        cv::typeToString(power.type()));
  }
  const int azimuths = power.rows;
  const int range_bins = power.cols;
  if (range_bins < rings || rings < 1) {
    throw std::invalid_argument("radar_scan_context: the scan has " + std::to_string(range_bins) +
                                " range bins, fewer than rings = " + std::to_string(rings));
  }
  if (azimuths < sectors || sectors < 1) {
    throw std::invalid_argument("radar_scan_context: the scan has " + std::to_string(azimuths) +
                                " azimuths, fewer than sectors = " + std::to_string(sectors));
  }
  const std::vector<AreaSpan> ring_spans = area_spans(range_bins, rings);
  const std::vector<AreaSpan> sector_spans = area_spans(azimuths, sectors);
  const auto rings_size = static_cast<std::size_t>(rings);
  const auto azimuths_size = static_cast<std::size_t>(azimuths);

  // Pass 1, along range: ring_sums[i * A + a] = sum of the azimuth row a over ring i, weighted in
  // units of 1/rings bin (weights add up to R).
  std::vector<std::int64_t> ring_sums(rings_size * azimuths_size);
  for (int a = 0; a < azimuths; ++a) {
    const std::uint8_t* row = power.ptr<std::uint8_t>(a);
    for (std::size_t i = 0; i < rings_size; ++i) {
      const AreaSpan& span = ring_spans[i];
      std::int64_t plain = 0;
      for (int r = span.first; r <= span.last; ++r) plain += row[r];
      ring_sums[i * azimuths_size + static_cast<std::size_t>(a)] =
          rings * plain - span.front_overhang * row[span.first] -
          span.back_overhang * row[span.last];
    }
  }

  // Pass 2, along azimuth: weights in units of 1/sectors row add up to A, so every cell's sum
  // carries a total weight of R * A.
  const double total_weight = static_cast<double>(range_bins) * azimuths;
  std::vector<float> context(rings_size * static_cast<std::size_t>(sectors));
  for (std::size_t i = 0; i < rings_size; ++i) {
    const std::int64_t* ring = ring_sums.data() + i * azimuths_size;
    for (std::size_t j = 0; j < sector_spans.size(); ++j) {
      const AreaSpan& span = sector_spans[j];
      std::int64_t plain = 0;
      for (int a = span.first; a <= span.last; ++a) plain += ring[a];
      const std::int64_t weighted = sectors * plain - span.front_overhang * ring[span.first] -
                                    span.back_overhang * ring[span.last];
      context[i * sector_spans.size() + j] =
          static_cast<float>(static_cast<double>(weighted) / total_weight);
    }
  }
  return context;
}

}  // namespace radarpr
