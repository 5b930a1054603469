#include "descriptors/open_radvlad/area_resampling.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "datasets/cpu_features.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#define RADARPR_AREA_RESAMPLING_X86 1
#endif

namespace radarpr {
namespace {

// One input column's share of an output bin.
struct AreaWeight {
  int column = 0;
  double weight = 0.0;
};

// Output bin j covers [j W, (j+1) W) and input column i covers [i width, (i+1) width), both in
// units of 1/width of a column: integer overlaps, so the weights (overlap / W) are exact ratios.
// Calls take(j, column, weight) for every bin j and its columns in increasing order.
template <typename Take>
void for_each_area_weight(int input_width, int width, Take take) {
  const auto w_in = static_cast<std::int64_t>(input_width);
  const auto w_out = static_cast<std::int64_t>(width);
  for (std::int64_t j = 0; j < w_out; ++j) {
    const std::int64_t begin = j * w_in;
    const std::int64_t end = begin + w_in;
    for (std::int64_t i = begin / w_out; i * w_out < end; ++i) {
      const std::int64_t overlap = std::min(end, (i + 1) * w_out) - std::max(begin, i * w_out);
      if (overlap > 0) {
        take(static_cast<int>(j), static_cast<int>(i),
             static_cast<double>(overlap) / static_cast<double>(w_in));
      }
    }
  }
}

std::vector<std::vector<AreaWeight>> area_weights(int input_width, int width) {
  std::vector<std::vector<AreaWeight>> weights(static_cast<std::size_t>(width));
  for_each_area_weight(input_width, width, [&](int j, int column, double weight) {
    weights[static_cast<std::size_t>(j)].push_back({column, weight});
  });
  return weights;
}

// The area weights flattened, output bin j reading terms [first[j], first[j + 1]), for a uint8
// row whose columns below `zeroed` read as 0: their terms add 0.0 to a sum that starts at 0.0 and
// are left out, which changes no sum. Columns are counted from `zeroed`.
struct FlatAreaWeights {
  std::vector<int> first;
  std::vector<int> columns;
  std::vector<double> weights;
};

FlatAreaWeights flat_area_weights(int input_width, int width, int zeroed) {
  FlatAreaWeights flat;
  flat.first.assign(static_cast<std::size_t>(width) + 1, 0);
  for_each_area_weight(input_width, width, [&](int j, int column, double weight) {
    if (column < zeroed) return;
    flat.columns.push_back(column - zeroed);
    flat.weights.push_back(weight);
    flat.first[static_cast<std::size_t>(j) + 1] = static_cast<int>(flat.columns.size());
  });
  // A bin without a kept column ends where the previous one does.
  for (std::size_t j = 1; j < flat.first.size(); ++j) {
    flat.first[j] = std::max(flat.first[j], flat.first[j - 1]);
  }
  return flat;
}

// The plain loop: each sum is a short chain of dependent additions whose length varies with the
// bin, so four rows go through the terms together (four chains in flight, one loop exit per four
// sums). A byte's value is read from a table.
void resample_baseline(const cv::Mat& bytes, int zeroed, const FlatAreaWeights& flat, int width,
                       cv::Mat& resampled) {
  double value_of[256];
  for (int v = 0; v < 256; ++v) value_of[v] = v;
  const int* first = flat.first.data();
  const int* columns = flat.columns.data();
  const double* weights = flat.weights.data();
  int a = 0;
  for (; a + 4 <= bytes.rows; a += 4) {
    const unsigned char* in0 = bytes.ptr<unsigned char>(a) + zeroed;
    const unsigned char* in1 = bytes.ptr<unsigned char>(a + 1) + zeroed;
    const unsigned char* in2 = bytes.ptr<unsigned char>(a + 2) + zeroed;
    const unsigned char* in3 = bytes.ptr<unsigned char>(a + 3) + zeroed;
    for (int j = 0; j < width; ++j) {
      double sum0 = 0.0;
      double sum1 = 0.0;
      double sum2 = 0.0;
      double sum3 = 0.0;
      for (int t = first[j]; t < first[j + 1]; ++t) {
        const int column = columns[t];
        const double w = weights[t];
        sum0 += w * value_of[in0[column]];
        sum1 += w * value_of[in1[column]];
        sum2 += w * value_of[in2[column]];
        sum3 += w * value_of[in3[column]];
      }
      resampled.at<float>(a, j) = static_cast<float>(sum0);
      resampled.at<float>(a + 1, j) = static_cast<float>(sum1);
      resampled.at<float>(a + 2, j) = static_cast<float>(sum2);
      resampled.at<float>(a + 3, j) = static_cast<float>(sum3);
    }
  }
  for (; a < bytes.rows; ++a) {
    const unsigned char* in = bytes.ptr<unsigned char>(a) + zeroed;
    for (int j = 0; j < width; ++j) {
      double sum = 0.0;
      for (int t = first[j]; t < first[j + 1]; ++t) sum += weights[t] * value_of[in[columns[t]]];
      resampled.at<float>(a, j) = static_cast<float>(sum);
    }
  }
}

#if RADARPR_AREA_RESAMPLING_X86
// With AVX2, sixteen rows go through the chains side by side, four per register of doubles:
// their bytes are interleaved first (column c's sixteen bytes together), so that one term of all
// sixteen sums is one 16-byte load, widenings, four multiplications and four additions. Every
// lane computes sum += weight * value in the plain loop's order, without FMA: the same roundings.
constexpr int kBlockRows = 16;

// Writes the bytes of rows[0..15], columns [begin, end), to out: column c's 16 bytes (in row
// order) at out + 16 (c - begin). A 16 x 16 byte transpose in four rounds of unpacking (pairs of
// rows, then fours, eights and all sixteen), each round doubling the bytes of a column kept
// together.
void interleave_rows(const std::array<const unsigned char*, kBlockRows>& rows, int begin, int end,
                     unsigned char* out) {
  int c = begin;
  for (; c + 16 <= end; c += 16) {
    __m128i r[16];
    for (int i = 0; i < 16; ++i) {
      r[i] =
          _mm_loadu_si128(reinterpret_cast<const __m128i*>(rows[static_cast<std::size_t>(i)] + c));
    }
    __m128i pairs[8][2];  // rows 2p, 2p + 1; columns 8h .. 8h + 7
    for (int p = 0; p < 8; ++p) {
      pairs[p][0] = _mm_unpacklo_epi8(r[2 * p], r[2 * p + 1]);
      pairs[p][1] = _mm_unpackhi_epi8(r[2 * p], r[2 * p + 1]);
    }
    __m128i fours[4][4];  // rows 4q .. 4q + 3; columns 4m .. 4m + 3
    for (int q = 0; q < 4; ++q) {
      for (int h = 0; h < 2; ++h) {
        fours[q][2 * h] = _mm_unpacklo_epi16(pairs[2 * q][h], pairs[2 * q + 1][h]);
        fours[q][2 * h + 1] = _mm_unpackhi_epi16(pairs[2 * q][h], pairs[2 * q + 1][h]);
      }
    }
    __m128i eights[2][8];  // rows 8o .. 8o + 7; columns 2n, 2n + 1
    for (int o = 0; o < 2; ++o) {
      for (int m = 0; m < 4; ++m) {
        eights[o][2 * m] = _mm_unpacklo_epi32(fours[2 * o][m], fours[2 * o + 1][m]);
        eights[o][2 * m + 1] = _mm_unpackhi_epi32(fours[2 * o][m], fours[2 * o + 1][m]);
      }
    }
    unsigned char* column = out + static_cast<std::ptrdiff_t>(c - begin) * kBlockRows;
    for (int n = 0; n < 8; ++n) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(column + 32 * n),
                       _mm_unpacklo_epi64(eights[0][n], eights[1][n]));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(column + 32 * n + 16),
                       _mm_unpackhi_epi64(eights[0][n], eights[1][n]));
    }
  }
  for (; c < end; ++c) {
    for (int i = 0; i < kBlockRows; ++i) {
      out[static_cast<std::ptrdiff_t>(c - begin) * kBlockRows + i] =
          rows[static_cast<std::size_t>(i)][c];
    }
  }
}

// The terms of every bin padded to the same count (the most any bin has): the padding goes first,
// weight 0 on column 0, and adds +0 to a sum that is still +0 (the values are not negative), so
// every sum is unchanged; the inner loop then has one trip count, which the branch predictor
// learns, instead of one that varies from bin to bin.
struct PaddedAreaWeights {
  int terms = 0;  // per bin
  std::vector<int> columns;
  std::vector<double> weights;
};

PaddedAreaWeights padded(const FlatAreaWeights& flat) {
  PaddedAreaWeights result;
  const std::size_t bins = flat.first.size() - 1;
  for (std::size_t j = 0; j < bins; ++j) {
    result.terms = std::max(result.terms, flat.first[j + 1] - flat.first[j]);
  }
  for (std::size_t j = 0; j < bins; ++j) {
    for (int pad = flat.first[j + 1] - flat.first[j]; pad < result.terms; ++pad) {
      result.columns.push_back(0);
      result.weights.push_back(0.0);
    }
    for (int t = flat.first[j]; t < flat.first[j + 1]; ++t) {
      result.columns.push_back(flat.columns[static_cast<std::size_t>(t)]);
      result.weights.push_back(flat.weights[static_cast<std::size_t>(t)]);
    }
  }
  return result;
}

// The sums of every output bin for one block of interleaved rows; out + 16 j holds bin j's.
__attribute__((target("avx2"))) void resample_block_avx2(const unsigned char* interleaved,
                                                         const PaddedAreaWeights& terms, int width,
                                                         float* out) {
  const int* columns = terms.columns.data();
  const double* weights = terms.weights.data();
  for (int j = 0; j < width; ++j) {
    __m256d sum0 = _mm256_setzero_pd();
    __m256d sum1 = sum0;
    __m256d sum2 = sum0;
    __m256d sum3 = sum0;
    for (int t = 0; t < terms.terms; ++t) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(
          interleaved + static_cast<std::ptrdiff_t>(columns[t]) * kBlockRows));
      const __m256i low = _mm256_cvtepu8_epi32(bytes);
      const __m256i high = _mm256_cvtepu8_epi32(_mm_unpackhi_epi64(bytes, bytes));
      const __m256d w = _mm256_broadcast_sd(weights + t);
      sum0 = _mm256_add_pd(sum0, _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(low)), w));
      sum1 = _mm256_add_pd(sum1,
                           _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(low, 1)), w));
      sum2 =
          _mm256_add_pd(sum2, _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(high)), w));
      sum3 = _mm256_add_pd(sum3,
                           _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(high, 1)), w));
    }
    columns += terms.terms;
    weights += terms.terms;
    float* bin = out + static_cast<std::ptrdiff_t>(j) * kBlockRows;
    _mm_storeu_ps(bin, _mm256_cvtpd_ps(sum0));
    _mm_storeu_ps(bin + 4, _mm256_cvtpd_ps(sum1));
    _mm_storeu_ps(bin + 8, _mm256_cvtpd_ps(sum2));
    _mm_storeu_ps(bin + 12, _mm256_cvtpd_ps(sum3));
  }
}

// Rows a .. a + rows - 1 of `resampled` from a block whose bin j holds 16 rows at 16 j: 4 x 4
// transposes where four rows and four bins are complete, single values at the edges.
void write_rows(const float* block, int width, int rows, cv::Mat& resampled, int a) {
  int i = 0;
  for (; i + 4 <= rows; i += 4) {
    float* out[4] = {resampled.ptr<float>(a + i), resampled.ptr<float>(a + i + 1),
                     resampled.ptr<float>(a + i + 2), resampled.ptr<float>(a + i + 3)};
    int j = 0;
    for (; j + 4 <= width; j += 4) {
      const float* in = block + static_cast<std::ptrdiff_t>(j) * kBlockRows + i;
      __m128 r0 = _mm_loadu_ps(in);
      __m128 r1 = _mm_loadu_ps(in + kBlockRows);
      __m128 r2 = _mm_loadu_ps(in + 2 * kBlockRows);
      __m128 r3 = _mm_loadu_ps(in + 3 * kBlockRows);
      _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
      _mm_storeu_ps(out[0] + j, r0);
      _mm_storeu_ps(out[1] + j, r1);
      _mm_storeu_ps(out[2] + j, r2);
      _mm_storeu_ps(out[3] + j, r3);
    }
    for (; j < width; ++j) {
      for (int k = 0; k < 4; ++k) {
        out[k][j] = block[static_cast<std::ptrdiff_t>(j) * kBlockRows + i + k];
      }
    }
  }
  for (; i < rows; ++i) {
    float* out = resampled.ptr<float>(a + i);
    for (int j = 0; j < width; ++j) out[j] = block[static_cast<std::ptrdiff_t>(j) * kBlockRows + i];
  }
}

void resample_avx2(const cv::Mat& bytes, int zeroed, const FlatAreaWeights& flat, int width,
                   cv::Mat& resampled) {
  const int kept = bytes.cols - zeroed;
  const PaddedAreaWeights terms = padded(flat);
  const std::vector<unsigned char> zero_row(static_cast<std::size_t>(bytes.cols), 0);
  std::vector<unsigned char> interleaved(static_cast<std::size_t>(kept) * kBlockRows);
  std::vector<float> block(static_cast<std::size_t>(width) * kBlockRows);
  for (int a = 0; a < bytes.rows; a += kBlockRows) {
    const int rows = std::min(kBlockRows, bytes.rows - a);
    std::array<const unsigned char*, kBlockRows> row_bytes{};
    for (int i = 0; i < kBlockRows; ++i) {
      row_bytes[static_cast<std::size_t>(i)] =
          i < rows ? bytes.ptr<unsigned char>(a + i) : zero_row.data();
    }
    interleave_rows(row_bytes, zeroed, bytes.cols, interleaved.data());
    resample_block_avx2(interleaved.data(), terms, width, block.data());
    write_rows(block.data(), width, rows, resampled, a);
  }
}
#endif

}  // namespace

cv::Mat area_resample_rows(const cv::Mat& rows, int width) {
  if (rows.empty() || rows.type() != CV_32FC1 || width < 1) {
    throw std::invalid_argument(
        "area_resample_rows: expected a non-empty CV_32FC1 matrix and a width >= 1, got " +
        std::to_string(rows.rows) + " x " + std::to_string(rows.cols) + " of type " +
        cv::typeToString(rows.type()) + " and width " + std::to_string(width));
  }
  const auto weights = area_weights(rows.cols, width);
  cv::Mat resampled(rows.rows, width, CV_32FC1);
  for (int a = 0; a < rows.rows; ++a) {
    const float* in = rows.ptr<float>(a);
    float* out = resampled.ptr<float>(a);
    for (int j = 0; j < width; ++j) {
      double sum = 0.0;
      for (const AreaWeight& w : weights[static_cast<std::size_t>(j)]) {
        sum += w.weight * in[w.column];
      }
      out[j] = static_cast<float>(sum);
    }
  }
  return resampled;
}

cv::Mat area_resample_bytes(const cv::Mat& bytes, int zeroed, int width, ResamplingPath path) {
  if (bytes.empty() || bytes.type() != CV_8UC1 || width < 1 || zeroed < 0) {
    throw std::invalid_argument(
        "area_resample_bytes: expected a non-empty CV_8UC1 matrix, a width >= 1 and zeroed >= 0, "
        "got " +
        std::to_string(bytes.rows) + " x " + std::to_string(bytes.cols) + " of type " +
        cv::typeToString(bytes.type()) + ", width " + std::to_string(width) + " and zeroed " +
        std::to_string(zeroed));
  }
  const int kept_from = std::min(zeroed, bytes.cols);
  if (kept_from == bytes.cols) {
    return cv::Mat(bytes.rows, width, CV_32FC1, cv::Scalar(0.0f));  // every column reads as 0
  }
  cv::Mat resampled(bytes.rows, width, CV_32FC1);
  const FlatAreaWeights flat = flat_area_weights(bytes.cols, width, kept_from);
#if RADARPR_AREA_RESAMPLING_X86
  static const bool avx2 = cpu_features().avx2;
  if (avx2 && path == ResamplingPath::fastest) {
    resample_avx2(bytes, kept_from, flat, width, resampled);
    return resampled;
  }
#endif
  static_cast<void>(path);
  resample_baseline(bytes, kept_from, flat, width, resampled);
  return resampled;
}

}  // namespace radarpr
