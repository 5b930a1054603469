#include "descriptors/radar_scan_context/column_alignment.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace radarpr {
namespace {

// A context's columns scaled to unit length, stored column after column so that a column is
// contiguous; an all-zero column stays zero and is marked unusable (its cosine is undefined).
struct UnitColumns {
  std::vector<double> values;        // sectors x rings
  std::vector<std::uint8_t> usable;  // per column, 1 = non-zero (a byte: read in the hot loop)
};

UnitColumns unit_columns(std::span<const float> context, std::size_t rings, std::size_t sectors,
                         std::string_view which) {
  UnitColumns columns{std::vector<double>(rings * sectors), std::vector<std::uint8_t>(sectors, 0)};
  for (std::size_t j = 0; j < sectors; ++j) {
    double* column = columns.values.data() + j * rings;
    double squared_norm = 0.0;
    for (std::size_t i = 0; i < rings; ++i) {
      const double value = context[i * sectors + j];
      if (!std::isfinite(value)) {
        throw std::invalid_argument("radar_scan_context: context " + std::string(which) +
                                    " holds a non-finite value at ring " + std::to_string(i) +
                                    ", sector " + std::to_string(j));
      }
      column[i] = value;
      squared_norm += value * value;  // float inputs cannot overflow a double sum
    }
    if (squared_norm == 0.0) continue;
    const double inverse_norm = 1.0 / std::sqrt(squared_norm);
    for (std::size_t i = 0; i < rings; ++i) column[i] *= inverse_norm;
    columns.usable[j] = 1;
  }
  return columns;
}

}  // namespace

std::optional<ColumnAlignment> best_column_alignment(std::span<const float> a,
                                                     std::span<const float> b, int rings,
                                                     int sectors) {
  if (rings < 1 || sectors < 1) {
    throw std::invalid_argument(
        "radar_scan_context: contexts need rings >= 1 and sectors >= 1, got " +
        std::to_string(rings) + " x " + std::to_string(sectors));
  }
  const auto ring_count = static_cast<std::size_t>(rings);
  const auto sector_count = static_cast<std::size_t>(sectors);
  if (a.size() != ring_count * sector_count || b.size() != a.size()) {
    throw std::invalid_argument("radar_scan_context: cannot compare contexts of " +
                                std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                                " values as " + std::to_string(rings) + " x " +
                                std::to_string(sectors));
  }
  // Normalising once per call turns every cosine of the shift loop into a plain dot product.
  const UnitColumns unit_a = unit_columns(a, ring_count, sector_count, "a");
  const UnitColumns unit_b = unit_columns(b, ring_count, sector_count, "b");

  std::optional<ColumnAlignment> best;
  for (std::size_t s = 0; s < sector_count; ++s) {
    double cosine_sum = 0.0;
    std::size_t pairs = 0;
    for (std::size_t j = 0; j < sector_count; ++j) {
      const std::size_t source = j >= s ? j - s : j + sector_count - s;  // (j - s) mod sectors
      if (!unit_a.usable[source] || !unit_b.usable[j]) continue;
      const double* column_a = unit_a.values.data() + source * ring_count;
      const double* column_b = unit_b.values.data() + j * ring_count;
      double dot = 0.0;
      for (std::size_t i = 0; i < ring_count; ++i) dot += column_a[i] * column_b[i];
      cosine_sum += dot;
      ++pairs;
    }
    if (pairs == 0) continue;
    const double similarity = cosine_sum / static_cast<double>(pairs);
    if (!best || similarity > best->similarity)
      best = ColumnAlignment{static_cast<int>(s), similarity};
  }
  return best;
}

}  // namespace radarpr
