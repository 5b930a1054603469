#include "descriptors/raplace/polar_to_cartesian.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "descriptors/referee/referee_common.hpp"

namespace radarpr::raplace {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

// x reduced to [0, 2 pi).
double wrap_to_turn(double x) {
  double wrapped = x - kTurn * std::floor(x / kTurn);
  if (wrapped >= kTurn) wrapped -= kTurn;  // floor rounding can leave exactly one turn
  return wrapped;
}

// The azimuth of every row as an angle after row 0's, increasing: offsets[0] = 0 and
// offsets[a] - offsets[a - 1] = (azimuth[a] - azimuth[a - 1]) mod 2 pi. Row A-1 is followed by
// row 0 again at offset 2 pi.
std::vector<double> azimuth_offsets(const PolarImage& scan) {
  const int rows = scan.azimuth_count();
  std::vector<double> azimuths = scan.azimuths_rad;
  if (azimuths.empty()) azimuths = uniform_azimuths(rows);
  if (azimuths.size() != static_cast<std::size_t>(rows)) {
    throw std::invalid_argument("raplace: the scan has " + std::to_string(rows) +
                                " azimuth rows but " + std::to_string(azimuths.size()) +
                                " azimuth angles (expected one per row, or none)");
  }
  std::vector<double> offsets(azimuths.size(), 0.0);
  for (std::size_t a = 0; a < azimuths.size(); ++a) {
    if (!std::isfinite(azimuths[a])) {
      throw std::invalid_argument("raplace: azimuth " + std::to_string(a) + " is not finite");
    }
    if (a > 0) offsets[a] = offsets[a - 1] + wrap_to_turn(azimuths[a] - azimuths[a - 1]);
  }
  if (offsets.back() >= kTurn) {
    throw std::invalid_argument(
        "raplace: the scan's azimuths must increase (modulo 2 pi) through less than one turn, "
        "but they advance by " +
        std::to_string(offsets.back()) + " rad from the first row to the last");
  }
  return offsets;
}

struct AzimuthSample {
  int row = 0;
  int next_row = 0;
  double weight_next = 0.0;  // linear weight of next_row
};

// The two rows around `bearing` (radians) and the weight of the second.
AzimuthSample sample_azimuth(const std::vector<double>& offsets, double first_azimuth,
                             double bearing) {
  const double offset = wrap_to_turn(bearing - first_azimuth);
  // offsets[0] = 0 <= offset, so the row found is valid.
  const auto after = std::upper_bound(offsets.begin(), offsets.end(), offset);
  const int row = static_cast<int>(after - offsets.begin()) - 1;
  const bool wraps = after == offsets.end();
  const double start = offsets[static_cast<std::size_t>(row)];
  const double width = (wraps ? kTurn : *after) - start;
  AzimuthSample sample;
  sample.row = row;
  sample.next_row = wraps ? 0 : row + 1;
  sample.weight_next = width > 0.0 ? (offset - start) / width : 0.0;
  return sample;
}

// Linear interpolation along one azimuth row at fractional bin `bin` (>= 0); bins >= R are 0.
double sample_range(const std::uint8_t* row, int range_bins, int bin, double weight_next) {
  const double near = bin < range_bins ? row[bin] : 0.0;
  const double far = bin + 1 < range_bins ? row[bin + 1] : 0.0;
  return (1.0 - weight_next) * near + weight_next * far;
}

// Where one pixel of the image reads the scan: its two azimuth rows and their weight, its range
// bin and the weight of the next one. A function of the geometry alone, so kept between scans.
struct PixelSample {
  std::int32_t pixel = 0;  // row-major index in the image
  std::int32_t row = 0;
  std::int32_t next_row = 0;
  std::int32_t bin = 0;
  double weight_next = 0.0;  // of next_row
  double weight_far = 0.0;   // of bin + 1
};

// The samples of every pixel inside the scan's range (the others stay 0) for one geometry.
struct WarpTable {
  int cart_size = 0;
  double cart_range_m = 0.0;
  double range_resolution_m = 0.0;
  int range_bins = 0;
  std::vector<double> azimuths;  // as the scan gives them (empty: uniform)
  int azimuth_count = 0;
  std::vector<PixelSample> samples;

  bool serves(const PolarImage& scan, int size, double range_m) const {
    return cart_size == size && cart_range_m == range_m &&
           range_resolution_m == scan.range_resolution_m && range_bins == scan.range_bin_count() &&
           azimuth_count == scan.azimuth_count() && azimuths == scan.azimuths_rad;
  }
};

// The scan's geometry as the samples need it.
struct WarpGeometry {
  std::vector<double> offsets;  // azimuth_offsets
  double first_azimuth = 0.0;
  int range_bins = 0;
  double range_resolution_m = 0.0;
  int cart_size = 0;
  double pixel_m = 0.0;
  double half = 0.0;
};

WarpGeometry warp_geometry(const PolarImage& scan, int cart_size, double cart_range_m) {
  WarpGeometry geometry;
  geometry.offsets = azimuth_offsets(scan);
  geometry.first_azimuth = scan.azimuths_rad.empty() ? 0.0 : scan.azimuths_rad.front();
  geometry.range_bins = scan.range_bin_count();
  geometry.range_resolution_m = scan.range_resolution_m;
  geometry.cart_size = cart_size;
  geometry.pixel_m = 2.0 * cart_range_m / cart_size;
  geometry.half = cart_size / 2.0;
  return geometry;
}

// Appends the samples of image row i's pixels that lie inside the scan's range.
void append_row_samples(const WarpGeometry& geometry, int i, std::vector<PixelSample>& samples) {
  const double y = (geometry.half - i - 0.5) * geometry.pixel_m;
  for (int j = 0; j < geometry.cart_size; ++j) {
    const double x = (j + 0.5 - geometry.half) * geometry.pixel_m;
    const double bin_position = std::max(std::hypot(x, y) / geometry.range_resolution_m - 0.5, 0.0);
    if (bin_position >= geometry.range_bins) continue;  // both neighbours lie beyond R: 0
    const int bin = static_cast<int>(bin_position);
    const AzimuthSample azimuth =
        sample_azimuth(geometry.offsets, geometry.first_azimuth, std::atan2(y, x));
    samples.push_back({static_cast<std::int32_t>(i * geometry.cart_size + j), azimuth.row,
                       azimuth.next_row, bin, azimuth.weight_next, bin_position - bin});
  }
}

// Writes every sampled pixel of `image` (CV_32FC1, zero elsewhere).
void apply_samples(const PolarImage& scan, const std::vector<PixelSample>& samples,
                   cv::Mat& image) {
  const int range_bins = scan.range_bin_count();
  auto* out = image.ptr<float>(0);
  for (const PixelSample& sample : samples) {
    const double value =
        (1.0 - sample.weight_next) *
            sample_range(scan.power.row(sample.row), range_bins, sample.bin, sample.weight_far) +
        sample.weight_next * sample_range(scan.power.row(sample.next_row), range_bins, sample.bin,
                                          sample.weight_far);
    out[sample.pixel] = static_cast<float>(value);
  }
}

// Images up to this many pixels keep their table between scans (32 bytes a pixel: 32 MB).
constexpr long long kMaxTablePixels = 1024LL * 1024LL;

}  // namespace

cv::Mat polar_to_cartesian(const PolarImage& scan, int cart_size, double cart_range_m) {
  check_polar_scan(scan, "raplace");
  if (!(scan.range_resolution_m > 0.0) || !std::isfinite(scan.range_resolution_m)) {
    throw std::invalid_argument("raplace: the scan's range resolution must be > 0 m per bin, got " +
                                std::to_string(scan.range_resolution_m));
  }
  if (cart_size < 1) {
    throw std::invalid_argument("raplace: cart_size must be >= 1 pixel, got " +
                                std::to_string(cart_size));
  }
  if (!(cart_range_m > 0.0) || !std::isfinite(cart_range_m)) {
    throw std::invalid_argument("raplace: the Cartesian range must be > 0 m, got " +
                                std::to_string(cart_range_m));
  }
  cv::Mat image(cart_size, cart_size, CV_32FC1, cv::Scalar(0.0f));
  if (static_cast<long long>(cart_size) * cart_size > kMaxTablePixels) {
    const WarpGeometry geometry = warp_geometry(scan, cart_size, cart_range_m);
    std::vector<PixelSample> samples;
    for (int i = 0; i < cart_size; ++i) {
      samples.clear();
      append_row_samples(geometry, i, samples);
      apply_samples(scan, samples, image);
    }
    return image;
  }
  // One table per thread, kept while the geometry repeats (it does within a dataset): building
  // it (a square root and an arc tangent per pixel) costs several times applying it.
  thread_local WarpTable table;
  if (!table.serves(scan, cart_size, cart_range_m)) {
    table = WarpTable{};  // a throw below leaves no half-built table behind
    const WarpGeometry geometry = warp_geometry(scan, cart_size, cart_range_m);
    std::vector<PixelSample> samples;
    for (int i = 0; i < cart_size; ++i) append_row_samples(geometry, i, samples);
    // In the scan's order (azimuth row, then range bin), so that applying the table reads the
    // scan nearly sequentially; the writes land in the much smaller image.
    std::sort(samples.begin(), samples.end(), [](const PixelSample& a, const PixelSample& b) {
      return a.row != b.row ? a.row < b.row : a.bin != b.bin ? a.bin < b.bin : a.pixel < b.pixel;
    });
    table.samples = std::move(samples);
    table.cart_size = cart_size;
    table.cart_range_m = cart_range_m;
    table.range_resolution_m = scan.range_resolution_m;
    table.range_bins = scan.range_bin_count();
    table.azimuths = scan.azimuths_rad;
    table.azimuth_count = scan.azimuth_count();
  }
  apply_samples(scan, table.samples, image);
  return image;
}

}  // namespace radarpr::raplace
