#include "descriptors/raplace/segment_radon.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "datasets/cpu_features.hpp"
#include "descriptors/raplace/radon_transform.hpp"

// The AVX2 build of the line walk exists on x86-64 only; elsewhere the default build runs.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RADARPR_SEGMENT_RADON_X86 1
#endif

namespace radarpr::raplace {
namespace {

// The image, its transpose, its quarter turn and its mirror, summed side by side.
constexpr int kLanes = 4;
// Base angles 0 .. 45 degrees; the lanes turn them into 0 .. 179.
constexpr int kBaseAngles = 46;

// One double per lane, added lane by lane: the same IEEE operations whether the compiler
// uses one AVX2 register or two SSE2 registers, so both builds give the same bits. Aligned like a
// double, so that containers need no over-aligned allocation (unaligned loads cost nothing here).
typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double)), aligned(sizeof(double))));

// Lanes as a container element (a vector attribute would be lost as a template argument).
struct LaneCell {
  Lanes value;
};

// The sinogram column (degrees) that lane `lane` fills at base angle `t`: projecting image(T p)
// at t is projecting the image at the angle of T n(t) (T orthogonal). With x right and y up:
// lane 1 holds image(y, x), the transpose (90 - t); lane 2 image(-y, x), a quarter turn
// (90 + t); lane 3 image(-x, y), the mirror (180 - t; 180 itself is column 0 again and is left
// out).
int lane_angle(int lane, int t) {
  switch (lane) {
    case 0:
      return t;
    case 1:
      return 90 - t;
    case 2:
      return 90 + t;
    default:
      return 180 - t;
  }
}

// Sums over the first k pixels of a run, per lane: of v, and of k v held as the rounded sum and
// the rounding errors so far, so that the difference of two long prefixes, nearly cancelled by
// the run's first k times its sum of v, is as exact as the short run it stands for.
struct Prefix {
  Lanes sum_high;
  Lanes moment_high;
  Lanes moment_low;
};

// high + low += value, with the rounding error of high + value (Knuth's two-sum) kept in low.
inline void add_exactly(Lanes& high, Lanes& low, const Lanes& value) {
  const Lanes sum = high + value;
  const Lanes value_part = sum - high;
  low += (high - (sum - value_part)) + (value - value_part);
  high = sum;
}

// A straight line of pixels through the image: (i0 + k di, j0 + k dj), k = 0 .. length - 1
// (row i, column j); rho grows by dj cos(theta) - di sin(theta) per pixel (kLineDirections).
struct PixelLine {
  int i0 = 0;
  int j0 = 0;
  int di = 0;
  int dj = 0;
  int length = 0;
};

// Prefix sums of the lanes of one line between its first and last non-zero pixel.
struct PixelRun {
  int first_i = 0;  // the run's first pixel (prefix[0])
  int first_j = 0;
  int count = 0;  // pixels in the run; 0 when the line is all zero in every lane
  std::vector<Prefix> prefix;
  std::vector<int> ends;  // project_run's segment ends, one per bin (scratch)
};

// The lanes at pixel (i, j): see lane_angle (x = j - (n - 1) / 2, y = (n - 1) / 2 - i).
// (Writes through a reference: a 32-byte vector returned by value has another ABI with and
// without AVX.)
__attribute__((always_inline)) inline void lanes_at(const cv::Mat& image, int i, int j,
                                                    Lanes& value) {
  const int last_index = image.rows - 1;
  const auto* row = image.ptr<double>(i);
  const auto* mirrored_row = image.ptr<double>(last_index - j);
  value = Lanes{row[j], mirrored_row[last_index - i], mirrored_row[i], row[last_index - j]};
}

// Whether any lane of each pixel is non-zero (NaN counts as non-zero), row-major: computed once,
// so that finding a line's run reads one byte per pixel. The lanes of pixel (i, j) are the image
// at (i, j), (n-1-j, n-1-i), (n-1-j, i) and (i, n-1-j) (lanes_at): with the non-zero bytes A of
// the image and their transpose T, that is A(i, j) | A(i, n-1-j) | T(i, n-1-j) | T(n-1-i, n-1-j),
// every read along a row.
std::vector<std::uint8_t> occupied_pixels(const cv::Mat& image) {
  const int n = image.rows;
  const auto size = static_cast<std::size_t>(n);
  std::vector<std::uint8_t> non_zero(size * size);
  std::vector<std::uint8_t> transposed(size * size);
  for (int i = 0; i < n; ++i) {
    const double* row = image.ptr<double>(i);
    std::uint8_t* out = non_zero.data() + static_cast<std::size_t>(i) * size;
    for (int j = 0; j < n; ++j) out[j] = row[j] != 0.0 ? 1 : 0;
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      transposed[static_cast<std::size_t>(j) * size + static_cast<std::size_t>(i)] =
          non_zero[static_cast<std::size_t>(i) * size + static_cast<std::size_t>(j)];
    }
  }
  std::vector<std::uint8_t> occupied(size * size);
  const int last = n - 1;
  for (int i = 0; i < n; ++i) {
    const std::uint8_t* a = non_zero.data() + static_cast<std::size_t>(i) * size;
    const std::uint8_t* t = transposed.data() + static_cast<std::size_t>(i) * size;
    const std::uint8_t* t_turned = transposed.data() + static_cast<std::size_t>(last - i) * size;
    std::uint8_t* out = occupied.data() + static_cast<std::size_t>(i) * size;
    for (int j = 0; j < n; ++j) {
      out[j] = static_cast<std::uint8_t>(a[j] | a[last - j] | t[last - j] | t_turned[last - j]);
    }
  }
  return occupied;
}

// The run of one line (its first to its last pixel with a non-zero lane) and its prefix sums.
__attribute__((always_inline)) inline void load_line(const cv::Mat& image,
                                                     const std::uint8_t* occupied,
                                                     const PixelLine& line, PixelRun& run) {
  const int n = image.rows;
  const auto is_occupied = [&](int k) {
    return occupied[static_cast<std::ptrdiff_t>(line.i0 + k * line.di) * n + line.j0 +
                    k * line.dj] != 0;
  };
  int first = 0;
  while (first < line.length && !is_occupied(first)) ++first;
  int last = line.length - 1;
  while (last > first && !is_occupied(last)) --last;
  run.count = first == line.length ? 0 : last - first + 1;
  run.first_i = line.i0 + first * line.di;
  run.first_j = line.j0 + first * line.dj;
  const Lanes zero = {0.0, 0.0, 0.0, 0.0};
  Prefix next{zero, zero, zero};
  run.prefix[0] = next;
  for (int k = 0; k < run.count; ++k) {
    Lanes value;
    lanes_at(image, run.first_i + k * line.di, run.first_j + k * line.dj, value);
    next.sum_high += value;
    // k v is exact for the Cartesian images (float values, k < 2^29); for other doubles it is
    // rounded once, relative to itself.
    const Lanes moment = static_cast<double>(k) * value;
    add_exactly(next.moment_high, next.moment_low, moment);
    run.prefix[static_cast<std::size_t>(k) + 1] = next;
  }
}

// ends[s] = the first pixel of a run at or beyond bin first_bin + s + 1, s < segments, for pixel
// positions start + k / inverse_step: computed ahead of the segments' sums, in a loop of its own
// that does not wait for them.
void segment_ends(int first_bin, int segments, double start, double inverse_step, int* ends) {
  for (int s = 0; s < segments; ++s) {
    ends[s] = static_cast<int>(std::ceil((first_bin + s + 1 - start) * inverse_step));
  }
}

// Adds one column run's projection to `out` (bins x lanes): pixel k of the run lies at rho
// position start + k step (offset by the centre bin).
__attribute__((always_inline)) inline void project_run(PixelRun& run, double start, double step,
                                                       int bins, LaneCell* out) {
  const Prefix* prefix = run.prefix.data();
  const Prefix& whole = prefix[run.count];
  if (step == 0.0) {
    // Every pixel of the column at one position.
    const int bin = static_cast<int>(start);
    if (bin < 0 || bin + 1 >= bins) throw std::logic_error("raplace: segment Radon out of range");
    const double weight_next = start - bin;
    const Lanes mass = whole.sum_high;
    out[bin].value += mass - weight_next * mass;
    out[bin + 1].value += weight_next * mass;
    return;
  }
  const int first_bin = static_cast<int>(start);
  const int last_bin = static_cast<int>(start + (run.count - 1) * step);
  if (first_bin < 0 || last_bin + 1 >= bins) {
    throw std::logic_error("raplace: segment Radon out of range");
  }
  const double inverse_step = 1.0 / step;
  // The first pixel at or beyond bin + 1 for every bin but the last, computed ahead; rounding
  // here only moves a pixel that lies within a rounding of the boundary, where both bins weigh it
  // alike.
  int* ends = run.ends.data();
  segment_ends(first_bin, last_bin - first_bin, start, inverse_step, ends);
  int begin = 0;  // the current segment's first pixel (prefix index)
  Lanes low_sum_high = prefix[0].sum_high;
  Lanes low_moment_high = prefix[0].moment_high;
  Lanes low_moment_low = prefix[0].moment_low;
  Lanes carry = {0.0, 0.0, 0.0, 0.0};  // sum v w of the previous segment, owed to this bin
  for (int bin = first_bin; bin <= last_bin; ++bin) {
    const int end =
        bin < last_bin ? std::clamp(ends[bin - first_bin], begin, run.count) : run.count;
    const Prefix& high = prefix[end];
    const double first_weight = start + begin * step - bin;  // w of the segment's first pixel
    const Lanes mass = high.sum_high - low_sum_high;
    // sum over the segment of (k - begin) v
    const Lanes moment =
        ((high.moment_high - low_moment_high) + (high.moment_low - low_moment_low)) -
        static_cast<double>(begin) * mass;
    const Lanes upper = first_weight * mass + step * moment;  // sum v w
    out[bin].value += (mass - upper) + carry;
    carry = upper;
    low_sum_high = high.sum_high;
    low_moment_high = high.moment_high;
    low_moment_low = high.moment_low;
    begin = end;
  }
  out[last_bin + 1].value += carry;
}

// What projecting a line needs besides the line: the angles it serves and where the sums go.
struct LineAngles {
  double half = 0.0;  // (n - 1) / 2
  double rho_centre = 0.0;
  const double* cosines = nullptr;
  const double* sines = nullptr;
  const std::uint8_t* angles = nullptr;    // 1: this base angle is summed along this kind of line
  const std::uint8_t* occupied = nullptr;  // occupied_pixels of the image
  int bins = 0;
};

// Loads one line and adds its projections at the marked base angles to sums (angle-major,
// bins x lanes).
__attribute__((always_inline)) inline void project_line(const cv::Mat& image, const PixelLine& line,
                                                        const LineAngles& where, PixelRun& run,
                                                        LaneCell* sums) {
  load_line(image, where.occupied, line, run);
  if (run.count == 0) return;
  const double x = run.first_j - where.half;  // the run's first pixel
  const double y = where.half - run.first_i;
  for (int t = 0; t < kBaseAngles; ++t) {
    if (!where.angles[t]) continue;
    const double start = x * where.cosines[t] + y * where.sines[t] + where.rho_centre;
    const double step = line.dj * where.cosines[t] - line.di * where.sines[t];
    project_run(run, start, step, where.bins, sums + static_cast<std::ptrdiff_t>(t) * where.bins);
  }
}

#if RADARPR_SEGMENT_RADON_X86
// The same code compiled for AVX2 (one register per Lanes, no FMA: the same roundings as the
// default build), chosen at run time where the processor has it.
__attribute__((target("avx2"))) void project_line_avx2(const cv::Mat& image, const PixelLine& line,
                                                       const LineAngles& where, PixelRun& run,
                                                       LaneCell* sums) {
  project_line(image, line, where, run, sums);
}
#endif

void project_line_default(const cv::Mat& image, const PixelLine& line, const LineAngles& where,
                          PixelRun& run, LaneCell* sums) {
  project_line(image, line, where, run, sums);
}

// The walks, as steps (di, dj) in (row, column): columns upwards (rho step sin), rows of the
// lattice two down and one right or back (cos - 2 sin, 2 sin - cos: zero at 26.6 degrees) and
// diagonals down and right (cos - sin). Each base angle takes the one whose step is smallest, so
// columns serve 0 .. 18.4 degrees, the (2, 1) lines 18.4 .. 33.7 and diagonals 33.7 .. 45: on
// average 0.15 bins crossed per pixel and angle, against 0.22 with columns and diagonals alone.
struct LineDirection {
  int di = 0;
  int dj = 0;
};
constexpr std::array<LineDirection, 4> kLineDirections = {{{-1, 0}, {2, 1}, {-2, -1}, {1, 1}}};

// Every line of pixels of an n x n image along `direction`, each from the pixel whose
// predecessor lies outside to the last pixel inside: every pixel on exactly one line. Columns run
// left to right, diagonals from the bottom left corner's (j - i = -(n - 1)) to the top right's.
template <typename Visit>
void for_each_line(int n, LineDirection direction, Visit visit) {
  const auto length_from = [&](int i, int j) {
    int length = n;
    if (direction.di > 0) length = std::min(length, (n - 1 - i) / direction.di + 1);
    if (direction.di < 0) length = std::min(length, i / -direction.di + 1);
    if (direction.dj > 0) length = std::min(length, (n - 1 - j) / direction.dj + 1);
    if (direction.dj < 0) length = std::min(length, j / -direction.dj + 1);
    return length;
  };
  if (direction.di == -1 && direction.dj == 0) {
    for (int j = 0; j < n; ++j) visit(PixelLine{n - 1, j, -1, 0, n});
    return;
  }
  if (direction.di == 1 && direction.dj == 1) {
    for (int c = -(n - 1); c < n; ++c) {  // the diagonal j - i = c
      visit(PixelLine{c >= 0 ? 0 : -c, c >= 0 ? c : 0, 1, 1, n - (c >= 0 ? c : -c)});
    }
    return;
  }
  // A first pixel has its predecessor's row outside (any column), or its predecessor's column
  // outside: within |dj| columns of the side the lines enter by.
  for (int i = 0; i < n; ++i) {
    const bool row_outside = i - direction.di < 0 || i - direction.di >= n;
    int begin = 0;
    int end = n;
    if (!row_outside) {
      if (direction.dj > 0) end = std::min(direction.dj, n);
      if (direction.dj < 0) begin = std::max(0, n + direction.dj);
      if (direction.dj == 0) end = 0;
    }
    for (int j = begin; j < end; ++j) {
      visit(PixelLine{i, j, direction.di, direction.dj, length_from(i, j)});
    }
  }
}

}  // namespace

cv::Mat square_radon_by_segments(const cv::Mat& image, int rho_bins) {
  if (image.empty() || image.type() != CV_64FC1 || image.rows != image.cols) {
    throw std::invalid_argument(
        "raplace: the segment Radon transform expects a non-empty square CV_64FC1 image, got " +
        std::to_string(image.rows) + " x " + std::to_string(image.cols) + " of type " +
        cv::typeToString(image.type()));
  }
  if (rho_bins != radon_rho_bins(image.cols, image.rows)) {
    throw std::invalid_argument("raplace: the segment Radon transform of a " +
                                std::to_string(image.rows) + "-pixel square needs " +
                                std::to_string(radon_rho_bins(image.cols, image.rows)) +
                                " rho bins, got " + std::to_string(rho_bins));
  }
  const int n = image.rows;
  const double half = (n - 1) / 2.0;
  const double rho_centre = (rho_bins - 1) / 2.0;
  const int bins = rho_bins + 1;  // one more: the split of the last pixel may touch it by 0
  std::array<double, kBaseAngles> cosines{};
  std::array<double, kBaseAngles> sines{};
  for (int t = 0; t < kBaseAngles; ++t) {
    const double angle = t * std::numbers::pi / 180.0;  // as radon_transform_by_pixels
    cosines[static_cast<std::size_t>(t)] = std::cos(angle);
    sines[static_cast<std::size_t>(t)] = std::sin(angle);
  }

  const Lanes zero = {0.0, 0.0, 0.0, 0.0};
  std::vector<LaneCell> sums(static_cast<std::size_t>(kBaseAngles) * static_cast<std::size_t>(bins),
                             LaneCell{zero});
  // Which base angles walk which lines: those whose step (rho moved per pixel, not negative) is
  // the smallest, so that they cross the fewest bins.
  std::array<std::array<std::uint8_t, kBaseAngles>, kLineDirections.size()> walks{};
  for (std::size_t t = 0; t < static_cast<std::size_t>(kBaseAngles); ++t) {
    std::size_t best = 0;
    double best_step = 0.0;
    for (std::size_t d = 0; d < kLineDirections.size(); ++d) {
      const double step = kLineDirections[d].dj * cosines[t] - kLineDirections[d].di * sines[t];
      if (step < 0.0) continue;
      if (d == 0 || step < best_step) {
        best = d;
        best_step = step;
      }
    }
    walks[best][t] = 1;
  }
  const std::vector<std::uint8_t> occupied = occupied_pixels(image);
  PixelRun run;
  run.prefix.resize(static_cast<std::size_t>(n) + 1);
  run.ends.resize(static_cast<std::size_t>(bins));
#if RADARPR_SEGMENT_RADON_X86
  static const auto project_line_here =
      cpu_features().avx2 ? project_line_avx2 : project_line_default;
#else
  const auto project_line_here = project_line_default;
#endif
  const auto project = [&](const PixelLine& line, const std::uint8_t* angles) {
    const LineAngles where{half, rho_centre, cosines.data(), sines.data(), angles, occupied.data(),
                           bins};
    project_line_here(image, line, where, run, sums.data());
  };
  for (std::size_t d = 0; d < kLineDirections.size(); ++d) {
    const std::uint8_t* angles = walks[d].data();
    if (std::find(walks[d].begin(), walks[d].end(), 1) == walks[d].end()) continue;
    for_each_line(n, kLineDirections[d], [&](const PixelLine& line) { project(line, angles); });
  }

  cv::Mat sinogram(rho_bins, kRadonAngles, CV_64FC1, cv::Scalar(0.0));
  std::array<bool, kRadonAngles> filled{};
  for (int t = 0; t < kBaseAngles; ++t) {
    const LaneCell* projection =
        sums.data() + static_cast<std::size_t>(t) * static_cast<std::size_t>(bins);
    for (int lane = 0; lane < kLanes; ++lane) {
      const int theta = lane_angle(lane, t);
      if (theta >= kRadonAngles || filled[static_cast<std::size_t>(theta)]) continue;
      filled[static_cast<std::size_t>(theta)] = true;
      for (int k = 0; k < rho_bins; ++k) {
        sinogram.at<double>(k, theta) = projection[k].value[lane];
      }
    }
  }
  return sinogram;
}

}  // namespace radarpr::raplace
