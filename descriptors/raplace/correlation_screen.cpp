#include "descriptors/raplace/correlation_screen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "datasets/cpu_features.hpp"

// The AVX2 + FMA kernels exist on x86-64 only; elsewhere the default sums run.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RADARPR_CORRELATION_SCREEN_X86 1
#endif

namespace radarpr::raplace {
namespace {

constexpr std::size_t kBlock = 8;  // database values per vector

// Feature index of (harmonic m, line l, part): real part 0, imaginary part 1.
std::size_t feature(int m, int l, int lines, int part) {
  return (static_cast<std::size_t>(m) * static_cast<std::size_t>(lines) +
          static_cast<std::size_t>(l)) *
             2 +
         static_cast<std::size_t>(part);
}

// |F| over every harmonic and line (the norm the error bound uses).
double spectrum_norm(const LineSpectra& spectra) {
  double squares = 0.0;
  for (std::size_t i = 0; i < spectra.real.size(); ++i) {
    squares += spectra.real[i] * spectra.real[i] + spectra.imag[i] * spectra.imag[i];
  }
  return std::sqrt(squares);
}

constexpr std::size_t kQueries = CorrelationScreen::kQueries;

// The sizes and tables one block needs.
struct Kernel {
  const float* queries[kQueries] = {};  // features of each query
  const float* weights = nullptr;       // shift_weights
  std::size_t features = 0;
  int harmonics = 0;
  int length = 0;
};

#if RADARPR_CORRELATION_SCREEN_X86
// The best shift of every (query, database lane) from the cross spectra in `cross` (per query:
// 2 x harmonics rows of 8 lanes), times n (the caller scales).
__attribute__((target("avx2,fma"))) void best_shifts_avx2(const Kernel& kernel, const float* cross,
                                                          float* best) {
  const std::size_t terms = 2 * static_cast<std::size_t>(kernel.harmonics);
  // Six shifts at a time share each load of the cross spectrum and overlap their sums.
  constexpr int kShifts = 6;
  __m256 top = _mm256_set1_ps(-std::numeric_limits<float>::infinity());
  for (int s0 = 0; s0 < kernel.length; s0 += kShifts) {
    const int shifts = std::min(kShifts, kernel.length - s0);
    __m256 sums[kShifts];
    for (int i = 0; i < kShifts; ++i) sums[i] = _mm256_setzero_ps();
    for (std::size_t t = 0; t < terms; ++t) {
      const __m256 value = _mm256_loadu_ps(cross + t * kBlock);
      for (int i = 0; i < kShifts; ++i) {
        if (i < shifts) {
          const float weight = kernel.weights[static_cast<std::size_t>(s0 + i) * terms + t];
          sums[i] = _mm256_fmadd_ps(_mm256_set1_ps(weight), value, sums[i]);
        }
      }
    }
    for (int i = 0; i < shifts; ++i) top = _mm256_max_ps(top, sums[i]);
  }
  _mm256_storeu_ps(best, top);
}

// Eight database values (one block, feature-major) against kQueries queries: the best shift's
// correlation of each pair, times n, into best[query * 8 + lane].
__attribute__((target("avx2,fma"))) void block_avx2(const Kernel& kernel, const float* block,
                                                    float* cross, float* best) {
  const int lines = static_cast<int>(kernel.features / 2) / kernel.harmonics;
  const std::size_t cross_size = 2 * static_cast<std::size_t>(kernel.harmonics) * kBlock;
  for (int m = 0; m < kernel.harmonics; ++m) {
    // A real and an imaginary sum per query: eight independent chains of fused multiply-adds,
    // and each database load serves the four queries.
    __m256 real[kQueries];
    __m256 imag[kQueries];
    for (std::size_t q = 0; q < kQueries; ++q) {
      real[q] = _mm256_setzero_ps();
      imag[q] = _mm256_setzero_ps();
    }
    const std::size_t first = feature(m, 0, lines, 0);
    for (int l = 0; l < lines; ++l) {
      const std::size_t f = first + 2 * static_cast<std::size_t>(l);
      const __m256 database_real = _mm256_loadu_ps(block + f * kBlock);
      const __m256 database_imag = _mm256_loadu_ps(block + (f + 1) * kBlock);
      for (std::size_t q = 0; q < kQueries; ++q) {
        const __m256 query_real = _mm256_set1_ps(kernel.queries[q][f]);
        const __m256 query_imag = _mm256_set1_ps(kernel.queries[q][f + 1]);
        // conj(q) d = (qr dr + qi di) + i (qr di - qi dr)
        real[q] = _mm256_fmadd_ps(query_real, database_real, real[q]);
        real[q] = _mm256_fmadd_ps(query_imag, database_imag, real[q]);
        imag[q] = _mm256_fmadd_ps(query_real, database_imag, imag[q]);
        imag[q] = _mm256_fnmadd_ps(query_imag, database_real, imag[q]);
      }
    }
    for (std::size_t q = 0; q < kQueries; ++q) {
      float* out = cross + q * cross_size + 2 * static_cast<std::size_t>(m) * kBlock;
      _mm256_storeu_ps(out, real[q]);
      _mm256_storeu_ps(out + kBlock, imag[q]);
    }
  }
  for (std::size_t q = 0; q < kQueries; ++q) {
    best_shifts_avx2(kernel, cross + q * cross_size, best + q * kBlock);
  }
}
#endif

// The same sums without AVX2, lane by lane.
void block_default(const Kernel& kernel, const float* block, float* cross, float* best) {
  const int lines = static_cast<int>(kernel.features / 2) / kernel.harmonics;
  const std::size_t terms = 2 * static_cast<std::size_t>(kernel.harmonics);
  for (std::size_t q = 0; q < kQueries; ++q) {
    const float* query = kernel.queries[q];
    for (int m = 0; m < kernel.harmonics; ++m) {
      float real[kBlock] = {};
      float imag[kBlock] = {};
      for (int l = 0; l < lines; ++l) {
        const std::size_t f = feature(m, l, lines, 0);
        for (std::size_t lane = 0; lane < kBlock; ++lane) {
          const float database_real = block[f * kBlock + lane];
          const float database_imag = block[(f + 1) * kBlock + lane];
          real[lane] += query[f] * database_real + query[f + 1] * database_imag;
          imag[lane] += query[f] * database_imag - query[f + 1] * database_real;
        }
      }
      for (std::size_t lane = 0; lane < kBlock; ++lane) {
        cross[(2 * static_cast<std::size_t>(m)) * kBlock + lane] = real[lane];
        cross[(2 * static_cast<std::size_t>(m) + 1) * kBlock + lane] = imag[lane];
      }
    }
    float* top = best + q * kBlock;
    std::fill(top, top + kBlock, -std::numeric_limits<float>::infinity());
    for (int s = 0; s < kernel.length; ++s) {
      const float* weights = kernel.weights + static_cast<std::size_t>(s) * terms;
      for (std::size_t lane = 0; lane < kBlock; ++lane) {
        float sum = 0.0f;
        for (std::size_t t = 0; t < terms; ++t) sum += weights[t] * cross[t * kBlock + lane];
        top[lane] = std::max(top[lane], sum);
      }
    }
  }
}

}  // namespace

CorrelationScreen::CorrelationScreen(const CircularCorrelation& correlation,
                                     const std::vector<LineSpectra>& queries,
                                     const std::vector<LineSpectra>& database)
    : lines_(correlation.length() == correlation.cols() ? correlation.rows() : correlation.cols()),
      harmonics_(correlation.length() / 2 + 1),
      length_(correlation.length()),
      shared_(&queries == &database) {
  features_ = 2 * static_cast<std::size_t>(harmonics_) * static_cast<std::size_t>(lines_);
  // corr[s] = (1/n) (R[0] + 2 sum over paired m of (Re R[m] cos - Im R[m] sin) + (-1)^s R[n/2]),
  // the 1/n applied after the max.
  const bool has_nyquist = length_ % 2 == 0;
  const int last_paired = has_nyquist ? harmonics_ - 2 : harmonics_ - 1;
  shift_weights_.assign(static_cast<std::size_t>(length_) * 2 * harmonics_, 0.0f);
  for (int s = 0; s < length_; ++s) {
    float* weights = shift_weights_.data() + static_cast<std::size_t>(s) * 2 * harmonics_;
    weights[0] = 1.0f;
    for (int m = 1; m <= last_paired; ++m) {
      const double angle = 2.0 * std::numbers::pi * ((m * s) % length_) / length_;
      weights[2 * m] = static_cast<float>(2.0 * std::cos(angle));
      weights[2 * m + 1] = static_cast<float>(-2.0 * std::sin(angle));
    }
    if (has_nyquist && length_ > 1) weights[2 * (harmonics_ - 1)] = s % 2 == 0 ? 1.0f : -1.0f;
  }

  const auto expected = features_ / 2;
  const auto store = [&](const LineSpectra& spectra, std::size_t index, const char* role) {
    if (spectra.real.size() != expected || spectra.imag.size() != expected) {
      throw std::invalid_argument("raplace: the " + std::string(role) + " spectra of value " +
                                  std::to_string(index) + " have " +
                                  std::to_string(spectra.real.size()) + " coefficients, expected " +
                                  std::to_string(expected));
    }
  };
  const std::size_t blocks = (database.size() + kBlock - 1) / kBlock;
  database_blocks_.assign(blocks * kBlock * features_, 0.0f);
  double largest_norm = 0.0;
  for (std::size_t j = 0; j < database.size(); ++j) {
    store(database[j], j, "database");
    float* block = database_blocks_.data() + (j / kBlock) * kBlock * features_;
    for (std::size_t c = 0; c < expected; ++c) {
      // LineSpectra index m * lines + l is feature pair c.
      block[(2 * c) * kBlock + j % kBlock] = static_cast<float>(database[j].real[c]);
      block[(2 * c + 1) * kBlock + j % kBlock] = static_cast<float>(database[j].imag[c]);
    }
    largest_norm = std::max(largest_norm, spectrum_norm(database[j]));
  }
  if (!shared_) {
    query_features_.assign(queries.size() * features_, 0.0f);
    for (std::size_t q = 0; q < queries.size(); ++q) {
      store(queries[q], q, "query");
      float* out = query_features_.data() + q * features_;
      for (std::size_t c = 0; c < expected; ++c) {
        out[2 * c] = static_cast<float>(queries[q].real[c]);
        out[2 * c + 1] = static_cast<float>(queries[q].imag[c]);
      }
    }
  }
  const double unit = std::ldexp(1.0, -24);
  const double factor = 4.0 * unit * (2.0 * lines_ + 2.0 * harmonics_ + 4.0) * 4.0 / length_;
  errors_.reserve(queries.size());
  // Float sums of products stay far from overflow (and the bound holds) while every norm is
  // below 1e15; beyond, the screen offers no bound and the search computes every distance.
  constexpr double kLargestUsableNorm = 1e15;
  for (const LineSpectra& spectra : queries) {
    const double norm = spectrum_norm(spectra);
    errors_.push_back(norm < kLargestUsableNorm && largest_norm < kLargestUsableNorm
                          ? factor * norm * largest_norm
                          : std::numeric_limits<double>::infinity());
  }
}

void CorrelationScreen::max_correlations(const std::size_t* query, std::size_t count,
                                         std::size_t begin, std::size_t end, float* out) const {
  if (count == 0 || count > kQueries || begin % kBlock != 0 || end < begin ||
      end > database_blocks_.size() / features_) {
    throw std::invalid_argument("raplace: screen of " + std::to_string(count) + " queries over [" +
                                std::to_string(begin) + ", " + std::to_string(end) +
                                ") is not block-aligned, too many or beyond the database");
  }
  // The queries' features, gathered from the shared blocks in a single session; a missing query
  // repeats the first (its results are not stored).
  thread_local std::vector<float> gathered;
  gathered.resize(kQueries * features_);
  Kernel kernel;
  for (std::size_t i = 0; i < kQueries; ++i) {
    const std::size_t q = query[i < count ? i : 0];
    if (shared_) {
      float* features = gathered.data() + i * features_;
      const float* block = database_blocks_.data() + (q / kBlock) * kBlock * features_;
      for (std::size_t f = 0; f < features_; ++f) features[f] = block[f * kBlock + q % kBlock];
      kernel.queries[i] = features;
    } else {
      kernel.queries[i] = query_features_.data() + q * features_;
    }
  }
  kernel.weights = shift_weights_.data();
  kernel.features = features_;
  kernel.harmonics = harmonics_;
  kernel.length = length_;
  thread_local std::vector<float> cross;
  cross.resize(kQueries * 2 * static_cast<std::size_t>(harmonics_) * kBlock);
#if RADARPR_CORRELATION_SCREEN_X86
  static const auto block_here =
      cpu_features().avx2 && cpu_features().fma ? block_avx2 : block_default;
#else
  const auto block_here = block_default;
#endif
  const float scale = 1.0f / static_cast<float>(length_);
  const std::size_t width = end - begin;
  float best[kQueries * kBlock];
  for (std::size_t j = begin; j < end; j += kBlock) {
    const float* block = database_blocks_.data() + (j / kBlock) * kBlock * features_;
    block_here(kernel, block, cross.data(), best);
    const std::size_t lanes = std::min(kBlock, end - j);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t lane = 0; lane < lanes; ++lane) {
        out[i * width + j - begin + lane] = best[i * kBlock + lane] * scale;
      }
    }
  }
}

}  // namespace radarpr::raplace
