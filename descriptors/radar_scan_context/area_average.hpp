#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// Exact area averaging ("resize by pixel area") for Radar Scan Context, descriptors.md §4.
//
// Shrinking n input bins to m <= n output cells, output cell i covers the input interval
// [i n/m, (i+1) n/m). Measured in units of 1/m bin, input bin k spans [k m, (k+1) m) and output
// cell i spans [i n, (i+1) n): every overlap is a whole number of units, so the weighted sums
// below are exact integers and the only rounding is the final division. (cv::resize INTER_AREA
// gives the same averages up to float rounding, but needs a transposed float copy of the scan
// and took 3 ms per MulRan scan against 0.25 ms here.)

// Output cell i of one axis: the input bins first..last it touches, and how many units of the
// first and the last bin lie outside it. Its weighted sum is
// m * (v[first] + ... + v[last]) - front_overhang * v[first] - back_overhang * v[last],
// whose weights add up to n (the cell's length in units).
struct AreaSpan {
  int first = 0;
  int last = 0;
  std::int64_t front_overhang = 0;
  std::int64_t back_overhang = 0;
  friend bool operator==(const AreaSpan&, const AreaSpan&) = default;
};

// The `outputs` spans of an axis of `inputs` bins. Throws std::invalid_argument unless
// 1 <= outputs <= inputs.
std::vector<AreaSpan> area_spans(int inputs, int outputs);

// The A x R polar scan `power` (CV_8UC1, row = azimuth, column = range bin) transposed to
// range x azimuth and area-averaged to rings x sectors: element [i * sectors + j] is the mean of
// the scan over ring i (range) and sector j (azimuth), partial bins weighted by their overlap.
// Exact up to the final rounding to float. Throws std::invalid_argument for another type, an
// empty scan, or fewer range bins than rings or azimuths than sectors.
std::vector<float> area_average_range_by_azimuth(const cv::Mat& power, int rings, int sectors);

}  // namespace radarpr
