#include "descriptors/open_radvlad/vlad.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "datasets/cpu_features.hpp"
#include "descriptors/open_radvlad/centre_products.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define RADARPR_VLAD_X86 1
#endif

namespace radarpr {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void check_inputs(const cv::Mat& rows, const cv::Mat& centres) {
  const auto describe = [](const cv::Mat& m) {
    return std::to_string(m.rows) + " x " + std::to_string(m.cols) + " " +
           cv::typeToString(m.type());
  };
  if (rows.type() != CV_32FC1 || centres.type() != CV_32FC1 || centres.empty() ||
      rows.cols != centres.cols) {
    throw std::invalid_argument(
        "vlad: expected CV_32FC1 rows and a non-empty CV_32FC1 codebook of equal width, got "
        "rows " +
        describe(rows) + " and codebook " + describe(centres));
  }
}

// A continuous view for Eigen (a copy only when OpenCV's layout has gaps).
Eigen::Map<const RowMatrix> view(const cv::Mat& matrix) {
  return {matrix.ptr<float>(), matrix.rows, matrix.cols};
}

// The nearest centre of each row by plain squared differences, (c - x).squaredNorm() in float:
// exact ties stay ties, so the lower index wins as specified. Computing that for every pair is
// rows x centres x dims subtractions; instead one matrix product gives every distance as
// |x|^2 + |c|^2 - 2 x.c, within B(c) = (dims + 3) u (|x| + |c|)^2 of the real distance (u =
// 2^-24, the float dot products' rounding; centre_products.hpp states the products' share), as
// the plain squared differences are. Only the centres whose interval [d - 2B, d + 2B] reaches below
// every other centre's upper end can hold the plain minimum; the plain squared differences decide
// among those (usually one or two).
std::vector<int> nearest_of(const cv::Mat& rows, const cv::Mat& centres) {
  const auto points = view(rows);
  const auto codebook = view(centres);
  std::vector<int> nearest(static_cast<std::size_t>(rows.rows), 0);
  const std::vector<float> products = centre_products(rows, centres);
  const Eigen::VectorXf point_norms = points.rowwise().squaredNorm();
  const Eigen::VectorXf centre_norms = codebook.rowwise().squaredNorm();
  const double unit = 0x1p-24 * (static_cast<double>(codebook.cols()) + 3.0) * 1.01;
  const Eigen::Index count = codebook.rows();
  std::vector<double> low(static_cast<std::size_t>(count));
  std::vector<double> centre_lengths(static_cast<std::size_t>(count));
  for (Eigen::Index c = 0; c < count; ++c) {
    centre_lengths[static_cast<std::size_t>(c)] = std::sqrt(static_cast<double>(centre_norms[c]));
  }
  for (Eigen::Index a = 0; a < points.rows(); ++a) {
    const double point_length = std::sqrt(static_cast<double>(point_norms[a]));
    double lowest_high = std::numeric_limits<double>::infinity();
    for (Eigen::Index c = 0; c < count; ++c) {
      const double distance =
          static_cast<double>(point_norms[a]) + centre_norms[c] -
          2.0 * static_cast<double>(products[static_cast<std::size_t>(a * count + c)]);
      const double length = point_length + centre_lengths[static_cast<std::size_t>(c)];
      const double bound = 2.0 * unit * length * length;
      low[static_cast<std::size_t>(c)] = distance - bound;
      lowest_high = std::min(lowest_high, distance + bound);
    }
    Eigen::Index best = -1;
    float best_distance = 0.0f;
    for (Eigen::Index c = 0; c < count; ++c) {
      // NaN distances (non-finite values) are never skipped: !(low > lowest_high).
      if (low[static_cast<std::size_t>(c)] > lowest_high) continue;
      const float distance = (codebook.row(c) - points.row(a)).squaredNorm();
      if (best < 0 || distance < best_distance) {
        best = c;
        best_distance = distance;
      }
    }
    nearest[static_cast<std::size_t>(a)] = static_cast<int>(best < 0 ? 0 : best);
  }
  return nearest;
}

// v <- sign(v) sqrt(|v|), every value on its own: square roots are correctly rounded, so four
// per AVX instruction give the same values as one at a time (at four times the throughput).
void signed_square_roots_baseline(double* values, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    values[i] = std::copysign(std::sqrt(std::abs(values[i])), values[i]);
  }
}

#if RADARPR_VLAD_X86
__attribute__((target("avx2"))) void signed_square_roots_avx2(double* values, std::size_t count) {
  const __m256d sign = _mm256_set1_pd(-0.0);
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const __m256d v = _mm256_loadu_pd(values + i);
    const __m256d root = _mm256_sqrt_pd(_mm256_andnot_pd(sign, v));
    _mm256_storeu_pd(values + i, _mm256_or_pd(root, _mm256_and_pd(sign, v)));
  }
  signed_square_roots_baseline(values + i, count - i);
}
#endif

void signed_square_roots(std::vector<double>& values) {
#if RADARPR_VLAD_X86
  static const bool avx2 = cpu_features().avx2;
  if (avx2) return signed_square_roots_avx2(values.data(), values.size());
#endif
  signed_square_roots_baseline(values.data(), values.size());
}

cv::Mat continuous(const cv::Mat& m) {
  return m.isContinuous() ? m : m.clone();
}

}  // namespace

std::vector<int> nearest_centres(const cv::Mat& rows, const cv::Mat& centres) {
  check_inputs(rows, centres);
  return nearest_of(continuous(rows), continuous(centres));
}

std::vector<float> vlad_vector(const cv::Mat& rows, const cv::Mat& centres) {
  check_inputs(rows, centres);
  const cv::Mat points = continuous(rows);
  const cv::Mat codebook = continuous(centres);
  const auto dims = static_cast<std::size_t>(codebook.cols);
  const std::vector<int> nearest = nearest_of(points, codebook);

  std::vector<double> residuals(static_cast<std::size_t>(codebook.rows) * dims, 0.0);
  for (int a = 0; a < points.rows; ++a) {
    const auto cluster = static_cast<std::size_t>(nearest[static_cast<std::size_t>(a)]);
    const float* x = points.ptr<float>(a);
    const float* centre = codebook.ptr<float>(static_cast<int>(cluster));
    double* sum = residuals.data() + cluster * dims;
    for (std::size_t j = 0; j < dims; ++j) sum[j] += static_cast<double>(x[j]) - centre[j];
  }

  signed_square_roots(residuals);
  double squared_norm = 0.0;
  for (const double v : residuals) squared_norm += v * v;
  // An all-zero V (every row exactly on its centre) stays zero instead of 0/0.
  const double scale = squared_norm > 0.0 ? 1.0 / std::sqrt(squared_norm) : 0.0;
  std::vector<float> vlad(residuals.size());
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    vlad[i] = static_cast<float>(residuals[i] * scale);
  }
  return vlad;
}

}  // namespace radarpr
