#include "descriptors/open_radvlad/centre_products.hpp"

#include <algorithm>
#include <cstddef>

#include <Eigen/Core>

#include "datasets/cpu_features.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define RADARPR_CENTRE_PRODUCTS_X86 1
#endif

namespace radarpr {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

bool mirror_symmetric(const cv::Mat& rows) {
  const int dims = rows.cols;
  if (dims < 4) return false;
  for (int a = 0; a < rows.rows; ++a) {
    const float* x = rows.ptr<float>(a);
    for (int k = 1; k < dims - k; ++k) {
      if (!(x[k] == x[dims - k])) return false;
    }
  }
  return true;
}

// The centres as the rows see them: folded to d / 2 + 1 columns for mirror-symmetric rows
// (c[0], then c[k] + c[d - k], the middle one alone when d is even), else as they are.
RowMatrix folded_centres(const cv::Mat& centres, bool fold) {
  const Eigen::Map<const RowMatrix> codebook(centres.ptr<float>(), centres.rows, centres.cols);
  if (!fold) return codebook;
  const Eigen::Index dims = codebook.cols();
  const Eigen::Index half = dims / 2 + 1;
  RowMatrix folded(codebook.rows(), half);
  for (Eigen::Index c = 0; c < codebook.rows(); ++c) {
    const float* centre = codebook.row(c).data();
    folded(c, 0) = centre[0];
    for (Eigen::Index k = 1; k < half; ++k) {
      folded(c, k) = k == dims - k ? centre[k] : centre[k] + centre[dims - k];
    }
  }
  return folded;
}

#if RADARPR_CENTRE_PRODUCTS_X86
constexpr int kRowBlock = 4;
constexpr int kCentreBlock = 16;

// Four rows against sixteen centres at a time, eight registers of sums, one fused multiply-add
// per term (its rounding error is within the standard bound of a dot product, as Eigen's is).
// The centres are transposed (depth x padded centres) so that a term of sixteen centres is two
// loads.
__attribute__((target("avx2,fma"))) void products_avx2(const cv::Mat& rows, const RowMatrix& folded,
                                                       std::vector<float>& out) {
  const int depth = static_cast<int>(folded.cols());
  const int count = static_cast<int>(folded.rows());
  const int padded = (count + kCentreBlock - 1) / kCentreBlock * kCentreBlock;
  std::vector<float> transposed(static_cast<std::size_t>(depth) * static_cast<std::size_t>(padded),
                                0.0f);
  for (int c = 0; c < count; ++c) {
    for (int k = 0; k < depth; ++k) {
      transposed[static_cast<std::size_t>(k) * static_cast<std::size_t>(padded) +
                 static_cast<std::size_t>(c)] = folded(c, k);
    }
  }
  for (int a = 0; a < rows.rows; a += kRowBlock) {
    const int block_rows = std::min(kRowBlock, rows.rows - a);
    const float* x[kRowBlock];
    for (int r = 0; r < kRowBlock; ++r) x[r] = rows.ptr<float>(a + std::min(r, block_rows - 1));
    for (int c = 0; c < padded; c += kCentreBlock) {
      // Named sums (an array of them is kept in memory by the compiler, not in registers).
      __m256 sum00 = _mm256_setzero_ps();
      __m256 sum01 = sum00;
      __m256 sum10 = sum00;
      __m256 sum11 = sum00;
      __m256 sum20 = sum00;
      __m256 sum21 = sum00;
      __m256 sum30 = sum00;
      __m256 sum31 = sum00;
      const float* centre = transposed.data() + c;
      for (int k = 0; k < depth; ++k, centre += padded) {
        const __m256 low = _mm256_loadu_ps(centre);
        const __m256 high = _mm256_loadu_ps(centre + 8);
        const __m256 x0 = _mm256_broadcast_ss(x[0] + k);
        const __m256 x1 = _mm256_broadcast_ss(x[1] + k);
        const __m256 x2 = _mm256_broadcast_ss(x[2] + k);
        const __m256 x3 = _mm256_broadcast_ss(x[3] + k);
        sum00 = _mm256_fmadd_ps(x0, low, sum00);
        sum01 = _mm256_fmadd_ps(x0, high, sum01);
        sum10 = _mm256_fmadd_ps(x1, low, sum10);
        sum11 = _mm256_fmadd_ps(x1, high, sum11);
        sum20 = _mm256_fmadd_ps(x2, low, sum20);
        sum21 = _mm256_fmadd_ps(x2, high, sum21);
        sum30 = _mm256_fmadd_ps(x3, low, sum30);
        sum31 = _mm256_fmadd_ps(x3, high, sum31);
      }
      const __m256 sums[kRowBlock][2] = {
          {sum00, sum01}, {sum10, sum11}, {sum20, sum21}, {sum30, sum31}};
      for (int r = 0; r < block_rows; ++r) {
        alignas(32) float values[kCentreBlock];
        _mm256_store_ps(values, sums[r][0]);
        _mm256_store_ps(values + 8, sums[r][1]);
        float* product = out.data() + static_cast<std::ptrdiff_t>(a + r) * count;
        for (int i = 0; i < kCentreBlock && c + i < count; ++i) product[c + i] = values[i];
      }
    }
  }
}
#endif

}  // namespace

std::vector<float> centre_products(const cv::Mat& rows, const cv::Mat& centres, ProductPath path) {
  const bool fold = mirror_symmetric(rows);
  const RowMatrix folded = folded_centres(centres, fold);
  std::vector<float> out(static_cast<std::size_t>(rows.rows) *
                         static_cast<std::size_t>(centres.rows));
  if (rows.rows == 0) return out;
#if RADARPR_CENTRE_PRODUCTS_X86
  static const bool avx2_fma = cpu_features().avx2 && cpu_features().fma;
  if (avx2_fma && path == ProductPath::fastest) {
    products_avx2(rows, folded, out);
    return out;
  }
#endif
  static_cast<void>(path);
  const Eigen::Map<const RowMatrix> points(rows.ptr<float>(), rows.rows, rows.cols);
  Eigen::Map<RowMatrix>(out.data(), rows.rows, centres.rows) =
      points.leftCols(folded.cols()) * folded.transpose();
  return out;
}

}  // namespace radarpr
