#include "descriptors/open_radvlad/training_rows.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "descriptors/open_radvlad/seeded_random.hpp"

namespace radarpr {
namespace {

constexpr std::uint64_t kSamplingStream = 2;

cv::Mat spectra_of(const TrainingScans& scans, std::size_t index,
                   const AzimuthSpectraParams& params) {
  try {
    return azimuth_spectra(scans.load(index), params);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("open_radvlad: training scan " + std::to_string(index) + " of " +
                                scans.description() + " is unusable: " + error.what());
  }
}

// Appends `rows` to `stack`, reserving room for `expected_rows` on the first call so that a
// sequence of equal scans is stacked without repeated reallocation.
void append(cv::Mat& stack, const cv::Mat& rows, std::size_t expected_rows) {
  if (stack.empty()) {
    stack = rows.clone();
    stack.reserve(expected_rows);
  } else {
    stack.push_back(rows);
  }
}

// The first `count` entries of a seeded Fisher-Yates shuffle of 0..size-1.
std::vector<std::size_t> seeded_sample(std::size_t size, std::size_t count, SeededRandom& random) {
  std::vector<std::size_t> order(size);
  std::iota(order.begin(), order.end(), std::size_t{0});
  for (std::size_t i = 0; i < count && i + 1 < size; ++i) {
    std::swap(order[i], order[i + random.below(size - i)]);
  }
  order.resize(count);
  return order;
}

TrainingRows all_rows(const TrainingScans& scans, const AzimuthSpectraParams& params) {
  TrainingRows collected;
  for (std::size_t index = 0; index < scans.size(); ++index) {
    const cv::Mat spectra = spectra_of(scans, index, params);
    append(collected.rows, spectra, static_cast<std::size_t>(spectra.rows) * scans.size());
    ++collected.scans_used;
  }
  return collected;
}

TrainingRows sampled_rows(const TrainingScans& scans, const AzimuthSpectraParams& params,
                          std::size_t max_rows, std::uint64_t seed) {
  SeededRandom random(seed, kSamplingStream);
  TrainingRows collected;
  for (const std::size_t index : seeded_sample(scans.size(), scans.size(), random)) {
    const cv::Mat spectra = spectra_of(scans, index, params);
    ++collected.scans_used;
    const auto missing = max_rows - static_cast<std::size_t>(collected.rows.rows);
    const std::size_t expected_rows =
        std::min(max_rows, static_cast<std::size_t>(spectra.rows) * scans.size());
    if (static_cast<std::size_t>(spectra.rows) <= missing) {
      append(collected.rows, spectra, expected_rows);
    } else {
      std::vector<std::size_t> picked =
          seeded_sample(static_cast<std::size_t>(spectra.rows), missing, random);
      std::sort(picked.begin(), picked.end());
      for (const std::size_t row : picked) {
        append(collected.rows, spectra.row(static_cast<int>(row)), expected_rows);
      }
    }
    if (static_cast<std::size_t>(collected.rows.rows) == max_rows) break;
  }
  return collected;
}

}  // namespace

TrainingRows collect_training_rows(const TrainingScans& scans, const AzimuthSpectraParams& params,
                                   std::size_t max_rows, std::uint64_t seed) {
  validate(params);
  if (scans.size() == 0) {
    throw std::invalid_argument("open_radvlad: no training scan in " + scans.description());
  }
  return max_rows == 0 ? all_rows(scans, params) : sampled_rows(scans, params, max_rows, seed);
}

}  // namespace radarpr
