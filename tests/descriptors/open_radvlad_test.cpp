// Open-RadVLAD (descriptors.md §6): spectra, k-means, VLAD and the trainable descriptor, on
// hand-computed inputs, plus real MulRan KAIST03 frames (../shared/data/real).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "descriptors/descriptor_registry.hpp"
#include "descriptors/open_radvlad/azimuth_spectra.hpp"
#include "descriptors/open_radvlad/kmeans.hpp"
#include "descriptors/open_radvlad/open_radvlad.hpp"
#include "descriptors/open_radvlad/training_rows.hpp"
#include "descriptors/open_radvlad/vlad.hpp"
#include "descriptors/opencv_image.hpp"
#include "descriptors/vector_training_scans.hpp"
#include "tests/descriptors/mulran_frames.hpp"

namespace radarpr {
namespace {

using testing::native_frame;
using testing::read_native;

PolarImage scan_of(const std::vector<std::vector<int>>& rows) {
  PolarImage scan;
  scan.power = ByteImage(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()));
  for (int a = 0; a < scan.power.rows(); ++a) {
    for (int r = 0; r < scan.power.cols(); ++r) {
      scan.power(a, r) = static_cast<std::uint8_t>(rows[a][r]);
    }
  }
  scan.azimuths_rad = uniform_azimuths(scan.power.rows());
  scan.range_resolution_m = 0.05;
  return scan;
}

PolarImage random_scan(int azimuths, int range_bins, std::uint64_t state) {
  PolarImage scan;
  cv::Mat bytes(azimuths, range_bins, CV_8UC1);
  cv::RNG(state).fill(bytes, cv::RNG::UNIFORM, 0, 256);
  scan.power = to_byte_image(bytes);
  scan.azimuths_rad = uniform_azimuths(azimuths);
  scan.range_resolution_m = 0.05;
  return scan;
}

// Row a of the result = row (a + shift) mod A of `scan`: the sensor turned by `shift` azimuths.
PolarImage turned(const PolarImage& scan, int shift) {
  PolarImage result = scan;
  result.power = ByteImage(scan.power.rows(), scan.power.cols());
  const int azimuths = scan.azimuth_count();
  for (int a = 0; a < azimuths; ++a)
    std::copy_n(scan.power.row((a + shift) % azimuths), scan.power.cols(), result.power.row(a));
  return result;
}

cv::Mat matrix_of(const std::vector<std::vector<float>>& rows) {
  cv::Mat m(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_32FC1);
  for (int i = 0; i < m.rows; ++i) {
    for (int j = 0; j < m.cols; ++j) m.at<float>(i, j) = rows[i][j];
  }
  return m;
}

std::vector<float> row_of(const cv::Mat& m, int row) {
  return {m.ptr<float>(row), m.ptr<float>(row) + m.cols};
}

bool bit_identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && a.isContinuous() && b.isContinuous() &&
         std::memcmp(a.data, b.data, a.total() * a.elemSize()) == 0;
}

AzimuthSpectraParams spectra_params(int min_bin, int max_bin, int bin_dim) {
  AzimuthSpectraParams params;
  params.min_bin = min_bin;
  params.max_bin = max_bin;
  params.bin_dim = bin_dim;
  return params;
}

void expect_row_near(const cv::Mat& m, int row, const std::vector<double>& expected) {
  ASSERT_EQ(m.cols, static_cast<int>(expected.size()));
  for (int j = 0; j < m.cols; ++j) {
    EXPECT_NEAR(m.at<float>(row, j), expected[static_cast<std::size_t>(j)], 1e-6) << "column " << j;
  }
}

// --- Steps 1-2: azimuth spectra ---

TEST(OpenRadVladSpectra, SpectrumIsTheDftMagnitudeOverItsNorm) {
  // Row [1 2 3 4], no zeroing, 4 bins kept as they are. DFT X_k = sum x_n e^{-i 2 pi k n / 4}:
  // X0 = 10, X1 = 1 - 2i - 3 + 4i = -2 + 2i, X2 = 1 - 2 + 3 - 4 = -2, X3 = -2 - 2i.
  // |X| = [10, 2 sqrt2, 2, 2 sqrt2], norm sqrt(100 + 8 + 4 + 8) = sqrt(120).
  const cv::Mat spectra = azimuth_spectra(scan_of({{1, 2, 3, 4}}), spectra_params(0, 0, 4));
  ASSERT_EQ(spectra.rows, 1);
  ASSERT_EQ(spectra.type(), CV_32FC1);
  const double norm = std::sqrt(120.0);
  expect_row_near(spectra, 0,
                  {10 / norm, 2 * std::sqrt(2.0) / norm, 2 / norm, 2 * std::sqrt(2.0) / norm});
}

TEST(OpenRadVladSpectra, MinBinZeroesNearBinsBeforeAreaAveraging) {
  // [7 7 1 1 2 2 3 3], min_bin 2 -> [0 0 1 1 2 2 3 3]; 8 -> 4 bins averages pairs: [0 1 2 3].
  // X0 = 6, X1 = 0 - i - 2 + 3i = -2 + 2i, X2 = 0 - 1 + 2 - 3 = -2, X3 = -2 - 2i.
  // |X| = [6, 2 sqrt2, 2, 2 sqrt2], norm sqrt(36 + 8 + 4 + 8) = sqrt(56).
  const cv::Mat spectra =
      azimuth_spectra(scan_of({{7, 7, 1, 1, 2, 2, 3, 3}}), spectra_params(2, 0, 4));
  const double norm = std::sqrt(56.0);
  expect_row_near(spectra, 0,
                  {6 / norm, 2 * std::sqrt(2.0) / norm, 2 / norm, 2 * std::sqrt(2.0) / norm});
}

TEST(OpenRadVladSpectra, MaxBinCropsTheRangeAndIsCappedAtR) {
  // Cropped to 4 bins, [1 2 3 4 200 100 50 25] is the first test's row.
  const double norm = std::sqrt(120.0);
  const std::vector<double> expected = {10 / norm, 2 * std::sqrt(2.0) / norm, 2 / norm,
                                        2 * std::sqrt(2.0) / norm};
  expect_row_near(
      azimuth_spectra(scan_of({{1, 2, 3, 4, 200, 100, 50, 25}}), spectra_params(0, 4, 4)), 0,
      expected);
  // max_bin beyond R keeps all R bins.
  expect_row_near(azimuth_spectra(scan_of({{1, 2, 3, 4}}), spectra_params(0, 3768, 4)), 0,
                  expected);
}

TEST(OpenRadVladSpectra, AreaResamplingAveragesOverFractionalBins) {
  // Shrinking 3 -> 2: bin 0 covers input [0, 1.5): (3 + 0.5 * 6) / 1.5 = 4; bin 1 covers
  // [1.5, 3): (0.5 * 6 + 9) / 1.5 = 8.
  const cv::Mat shrunk = area_resample_rows(matrix_of({{3, 6, 9}}), 2);
  EXPECT_FLOAT_EQ(shrunk.at<float>(0, 0), 4.0f);
  EXPECT_FLOAT_EQ(shrunk.at<float>(0, 1), 8.0f);
  // Enlarging 2 -> 3: bins cover [0, 2/3), [2/3, 4/3), [4/3, 2): 3, (3/3 + 9/3) / (2/3) = 6, 9.
  const cv::Mat enlarged = area_resample_rows(matrix_of({{3, 9}}), 3);
  EXPECT_FLOAT_EQ(enlarged.at<float>(0, 0), 3.0f);
  EXPECT_FLOAT_EQ(enlarged.at<float>(0, 1), 6.0f);
  EXPECT_FLOAT_EQ(enlarged.at<float>(0, 2), 9.0f);
}

TEST(OpenRadVladSpectra, AnAzimuthWithNothingBeyondMinBinStaysZero) {
  // Row 0 only has power before min_bin = 2: zeroed, so its spectrum is zero rather than NaN.
  const cv::Mat spectra =
      azimuth_spectra(scan_of({{9, 9, 0, 0}, {0, 0, 5, 0}}), spectra_params(2, 0, 4));
  expect_row_near(spectra, 0, {0, 0, 0, 0});
  // Row 1 = [0 0 5 0]: |X| = [5 5 5 5] -> 0.5 each.
  expect_row_near(spectra, 1, {0.5, 0.5, 0.5, 0.5});
}

TEST(OpenRadVladSpectra, RejectsAnEmptyOrWideScanAndBadParameters) {
  PolarImage empty;
  EXPECT_THROW(azimuth_spectra(empty, spectra_params(0, 0, 4)), std::invalid_argument);
  EXPECT_THROW(azimuth_spectra(scan_of({{1, 2}}), spectra_params(0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(azimuth_spectra(scan_of({{1, 2}}), spectra_params(-1, 0, 4)), std::invalid_argument);
}

// min_bin at or beyond the kept range zeroes every bin of every scan: one value for all scans,
// which used to be scored by tie-breaking. Refused, naming the largest min_bin the scans allow.
TEST(OpenRadVladSpectra, AMinBinThatZeroesEveryBinIsRefusedNamingTheMaximum) {
  const PolarImage scan = scan_of({{1, 2, 3, 4, 5, 6, 7, 8}});
  EXPECT_NO_THROW(azimuth_spectra(scan, spectra_params(7, 0, 4)));
  try {
    azimuth_spectra(scan, spectra_params(8, 0, 4));
    ADD_FAILURE() << "min_bin = R accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "open_radvlad: min_bin = 8 zeroes every range bin of a scan with 8; at most 7 "
                 "for these scans");
  }
  // Within R, but beyond the max_bin crop.
  EXPECT_NO_THROW(azimuth_spectra(scan, spectra_params(3, 4, 4)));
  try {
    azimuth_spectra(scan, spectra_params(5, 4, 4));
    ADD_FAILURE() << "min_bin beyond the crop accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "open_radvlad: min_bin = 5 zeroes every range bin of a scan with 8 (cropped to "
                 "max_bin = 4); at most 3 for these scans");
  }
}

// --- k-means ---

TEST(OpenRadVladKMeans, FindsTheTwoObviousClustersOfATinyPlaneSet) {
  // Means: (0+0+1, 0+1+0) / 3 = (1/3, 1/3) and (10+10+11, 10+11+10) / 3 = (31/3, 31/3).
  const cv::Mat rows = matrix_of({{0, 0}, {0, 1}, {1, 0}, {10, 10}, {10, 11}, {11, 10}});
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const KMeansResult result = kmeans(rows, {.clusters = 2, .seed = seed, .max_iterations = 10});
    ASSERT_TRUE(result.converged) << "seed " << seed;
    const int near = result.assignment[0];
    const int far = 1 - near;
    EXPECT_EQ(result.assignment, (std::vector<int>{near, near, near, far, far, far}));
    EXPECT_NEAR(result.centres.at<float>(near, 0), 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(result.centres.at<float>(near, 1), 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(result.centres.at<float>(far, 0), 31.0 / 3.0, 1e-5);
    EXPECT_NEAR(result.centres.at<float>(far, 1), 31.0 / 3.0, 1e-5);
  }
}

cv::Mat random_rows(int count, int dims, std::uint64_t state) {
  cv::Mat rows(count, dims, CV_32FC1);
  cv::RNG(state).fill(rows, cv::RNG::UNIFORM, 0.0, 1.0);
  return rows;
}

TEST(OpenRadVladKMeans, KMeansPlusPlusSeedingIsDeterministicPerSeed) {
  const cv::Mat rows = random_rows(200, 8, 11);
  const auto seeds = kmeans_plus_plus_seeds(rows, 6, 42);
  ASSERT_EQ(seeds.size(), 6u);
  EXPECT_EQ(std::set<std::size_t>(seeds.begin(), seeds.end()).size(), 6u);  // distinct rows
  EXPECT_EQ(kmeans_plus_plus_seeds(rows, 6, 42), seeds);
  bool another_seed_differs = false;
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    another_seed_differs |= kmeans_plus_plus_seeds(rows, 6, seed) != seeds;
  }
  EXPECT_TRUE(another_seed_differs);
}

// 99 rows at the origin and one at (100, 0): once an origin row is chosen, every other origin row
// has squared distance 0, so D^2 weighting must pick the far row (a uniform pick would almost
// never); if the far row comes first, the second seed is an origin row. Either way, for every seed,
// the seeds are the far row and one origin row.
TEST(OpenRadVladKMeans, KMeansPlusPlusWeightsBySquaredDistance) {
  cv::Mat rows = cv::Mat::zeros(100, 2, CV_32FC1);
  rows.at<float>(99, 0) = 100.0f;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const auto seeds = kmeans_plus_plus_seeds(rows, 2, seed);
    ASSERT_EQ(seeds.size(), 2u);
    EXPECT_EQ(std::count(seeds.begin(), seeds.end(), std::size_t{99}), 1) << "seed " << seed;
  }
}

TEST(OpenRadVladKMeans, SameSeedGivesBitIdenticalCentres) {
  const cv::Mat rows = random_rows(5000, 16, 12);
  const KMeansParams params{.clusters = 8, .seed = 7, .max_iterations = 30};
  const KMeansResult first = kmeans(rows, params);
  const KMeansResult second = kmeans(rows, params);
  EXPECT_TRUE(bit_identical(first.centres, second.centres));
  EXPECT_EQ(first.assignment, second.assignment);
  EXPECT_EQ(first.iterations, second.iterations);
}

TEST(OpenRadVladKMeans, EmptyClusterIsReseededAtTheFarthestRow) {
  // 1-D rows 0, 2, 10, 11 from centres 1.5, 100, 10.5. Step 1: 0 and 2 -> c0, 10 and 11 -> c2,
  // c1 empty; squared distances to own centre 2.25, 0.25, 0.25, 0.25, so c1 restarts at row 0
  // (c0 = 1, c2 = 10.5 as means). Step 2: 0 -> c1 (0 < 1), 2 -> c0; means c0 = 2, c1 = 0.
  // Step 3: nothing changes.
  const KMeansResult result =
      lloyd(matrix_of({{0}, {2}, {10}, {11}}), matrix_of({{1.5f}, {100}, {10.5f}}), 10);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 3);
  EXPECT_EQ(result.assignment, (std::vector<int>{1, 0, 2, 2}));
  EXPECT_EQ(row_of(result.centres, 0), std::vector<float>{2.0f});
  EXPECT_EQ(row_of(result.centres, 1), std::vector<float>{0.0f});
  EXPECT_EQ(row_of(result.centres, 2), std::vector<float>{10.5f});
}

TEST(OpenRadVladKMeans, FewerDistinctRowsThanClustersGiveDuplicateCentresNotNan) {
  // Two distinct rows, three clusters: the seeding takes both, then a duplicate; the duplicate
  // cluster stays empty (ties go to the lower index) and keeps its centre.
  const cv::Mat rows = matrix_of({{1, 2}, {1, 2}, {1, 2}, {5, 5}});
  const KMeansResult result = kmeans(rows, {.clusters = 3, .seed = 3, .max_iterations = 10});
  EXPECT_TRUE(result.converged);
  std::set<std::vector<float>> centres;
  for (int c = 0; c < 3; ++c) centres.insert(row_of(result.centres, c));
  EXPECT_EQ(centres, (std::set<std::vector<float>>{{1, 2}, {5, 5}}));
  // All rows identical: every centre is that row.
  const KMeansResult same = kmeans(matrix_of({{3, 4}, {3, 4}, {3, 4}}), {.clusters = 3});
  for (int c = 0; c < 3; ++c) EXPECT_EQ(row_of(same.centres, c), (std::vector<float>{3, 4}));
}

TEST(OpenRadVladKMeans, RejectsFewerRowsThanClustersAndBadInputs) {
  EXPECT_THROW(kmeans(matrix_of({{1}, {2}}), {.clusters = 3}), std::invalid_argument);
  EXPECT_THROW(kmeans(matrix_of({{1}, {2}}), {.clusters = 1, .max_iterations = 0}),
               std::invalid_argument);
  EXPECT_THROW(kmeans(matrix_of({{1}, {std::nanf("")}}), {.clusters = 1}), std::invalid_argument);
  EXPECT_THROW(kmeans(cv::Mat(), {.clusters = 1}), std::invalid_argument);
}

// --- Step 4: VLAD ---

TEST(OpenRadVladVlad, HandSizedExampleWithSignedRootAndNormalisation) {
  // Centres c0 = (1, 0), c1 = (0, 1). Squared distances to (c0, c1): x1 = (0.8, 0.6): 0.40, 0.80
  // -> c0; x2 = (0.6, 0.8): 0.80, 0.40 -> c1; x3 = (0.28, 0.96): 1.44, 0.08 -> c1.
  // V0 = x1 - c0 = (-0.2, 0.6); V1 = (0.6, -0.2) + (0.28, -0.04) = (0.88, -0.24).
  // Cluster-major [-0.2, 0.6, 0.88, -0.24] -> signed roots, whose squares sum to 1.92:
  // [-sqrt(0.2/1.92), sqrt(0.6/1.92), sqrt(0.88/1.92), -sqrt(0.24/1.92)].
  const cv::Mat rows = matrix_of({{0.8f, 0.6f}, {0.6f, 0.8f}, {0.28f, 0.96f}});
  const cv::Mat centres = matrix_of({{1, 0}, {0, 1}});
  EXPECT_EQ(nearest_centres(rows, centres), (std::vector<int>{0, 1, 1}));
  const std::vector<float> vlad = vlad_vector(rows, centres);
  ASSERT_EQ(vlad.size(), 4u);
  EXPECT_NEAR(vlad[0], -std::sqrt(0.2 / 1.92), 1e-6);
  EXPECT_NEAR(vlad[1], std::sqrt(0.6 / 1.92), 1e-6);
  EXPECT_NEAR(vlad[2], std::sqrt(0.88 / 1.92), 1e-6);
  EXPECT_NEAR(vlad[3], -std::sqrt(0.24 / 1.92), 1e-6);
}

TEST(OpenRadVladVlad, ATieGoesToTheLowerIndex) {
  // (0.5, 0.5) is 0.5 from both centres -> c0: V0 = (-0.5, 0.5), V1 = 0; roots +-sqrt(0.5) have
  // norm 1.
  const std::vector<float> vlad =
      vlad_vector(matrix_of({{0.5f, 0.5f}}), matrix_of({{1, 0}, {0, 1}}));
  EXPECT_NEAR(vlad[0], -std::sqrt(0.5), 1e-7);
  EXPECT_NEAR(vlad[1], std::sqrt(0.5), 1e-7);
  EXPECT_EQ(vlad[2], 0.0f);
  EXPECT_EQ(vlad[3], 0.0f);
}

TEST(OpenRadVladVlad, RowsOnTheirCentresGiveAZeroVectorNotNan) {
  const std::vector<float> vlad =
      vlad_vector(matrix_of({{1, 0}, {0, 1}, {1, 0}}), matrix_of({{1, 0}, {0, 1}}));
  EXPECT_EQ(vlad, (std::vector<float>{0, 0, 0, 0}));
}

TEST(OpenRadVladVlad, RejectsMismatchedWidths) {
  EXPECT_THROW(vlad_vector(matrix_of({{1, 0, 0}}), matrix_of({{1, 0}})), std::invalid_argument);
}

// --- The descriptor ---

OpenRadVladParams small_params() {
  OpenRadVladParams params;
  params.spectra = spectra_params(4, 0, 16);
  params.clusters = 4;
  params.max_iterations = 50;
  params.max_training_rows = 0;
  return params;
}

VectorTrainingScans random_scans(int count, int azimuths, int range_bins) {
  std::vector<PolarImage> scans;
  for (int i = 0; i < count; ++i) {
    scans.push_back(random_scan(azimuths, range_bins, 100 + static_cast<std::uint64_t>(i)));
  }
  return VectorTrainingScans(std::move(scans), "three random scans");
}

TEST(OpenRadVladDescriptor, ExtractBeforeTrainingThrowsSayingSo) {
  const OpenRadVladDescriptor vlad(small_params());
  EXPECT_TRUE(vlad.trainable());
  EXPECT_FALSE(vlad.is_trained());
  try {
    vlad.extract(random_scan(8, 64, 1));
    FAIL() << "extract before train must throw";
  } catch (const std::logic_error& error) {
    EXPECT_NE(std::string(error.what()).find("open_radvlad is not trained"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("database session"), std::string::npos);
  }
}

TEST(OpenRadVladDescriptor, TrainingOnTooFewRowsThrowsNamingTheScans) {
  OpenRadVladDescriptor vlad(small_params());  // 4 clusters
  const VectorTrainingScans tiny({random_scan(3, 64, 1)}, "a tiny test set");
  try {
    vlad.train(tiny);
    FAIL() << "3 rows cannot make 4 clusters";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("a tiny test set"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(vlad.is_trained());
  EXPECT_THROW(vlad.train(VectorTrainingScans({}, "no scans")), std::invalid_argument);
}

TEST(OpenRadVladDescriptor, RejectsACapBelowTheClusterCount) {
  OpenRadVladParams params = small_params();
  params.max_training_rows = 3;
  EXPECT_THROW(OpenRadVladDescriptor{params}, std::invalid_argument);
  params.max_training_rows = 4;
  EXPECT_NO_THROW(OpenRadVladDescriptor{params});
}

TEST(OpenRadVladDescriptor, TrainingIsBitIdenticalForTheSameSeedAndScans) {
  const VectorTrainingScans scans = random_scans(3, 40, 200);
  OpenRadVladDescriptor first(small_params());
  OpenRadVladDescriptor second(small_params());
  first.train(scans);
  second.train(scans);
  ASSERT_TRUE(first.is_trained());
  EXPECT_EQ(first.codebook().size(), cv::Size(16, 4));
  EXPECT_TRUE(bit_identical(first.codebook(), second.codebook()));
  EXPECT_EQ(first.training().rows, 120u);
  EXPECT_EQ(first.training().scans_used, 3u);
}

TEST(OpenRadVladDescriptor, ValueIsUnitNormAndOrderlessOverAzimuths) {
  OpenRadVladDescriptor vlad(small_params());
  vlad.train(random_scans(3, 40, 200));
  const PolarImage scan = random_scan(40, 200, 7);
  const DescriptorValue value = vlad.extract(scan);
  ASSERT_EQ(value.rows, 64);
  ASSERT_EQ(value.cols, 1);
  double squared = 0.0;
  for (const float v : value.values) squared += static_cast<double>(v) * v;
  EXPECT_NEAR(squared, 1.0, 1e-5);
  EXPECT_LT(vlad.distance(value, vlad.extract(turned(scan, 13))), 1e-6);
  EXPECT_GT(vlad.distance(value, vlad.extract(random_scan(40, 200, 8))), 1e-3);
  // Another range geometry resamples to the same bin_dim.
  EXPECT_EQ(vlad.extract(random_scan(40, 77, 9)).rows, 64);
  EXPECT_THROW(vlad.distance(value, DescriptorValue{2, 1, {0, 0}}), std::invalid_argument);
}

TEST(OpenRadVladDescriptor, ASavedCodebookLoadsIntoAFreshInstanceThatExtractsTheSame) {
  OpenRadVladDescriptor trained(small_params());
  EXPECT_TRUE(trained.saves_training());
  EXPECT_THROW(static_cast<void>(trained.save_training()), std::logic_error);  // nothing learnt
  trained.train(random_scans(3, 40, 200));
  const std::string state = trained.save_training();

  OpenRadVladDescriptor loaded(small_params());
  loaded.load_training(state);
  ASSERT_TRUE(loaded.is_trained());
  EXPECT_TRUE(bit_identical(loaded.codebook(), trained.codebook()));
  const PolarImage scan = random_scan(40, 200, 7);
  EXPECT_EQ(loaded.extract(scan).values, trained.extract(scan).values);

  // Another shape, a cut file, damaged elements or another format are refused, and the
  // descriptor stays as it was.
  OpenRadVladParams wider = small_params();
  wider.clusters = 5;
  OpenRadVladDescriptor other(wider);
  const auto refusal = [&](OpenRadVladDescriptor& descriptor, const std::string& bytes) {
    try {
      descriptor.load_training(bytes);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(refusal(other, state).find("4 x 16, this descriptor's is 5 x 16"), std::string::npos)
      << refusal(other, state);
  EXPECT_FALSE(other.is_trained());
  EXPECT_NE(refusal(loaded, state.substr(0, state.size() - 1)).find("bytes of elements"),
            std::string::npos);
  std::string damaged = state;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(damaged.data() + damaged.size() - sizeof nan, &nan, sizeof nan);
  EXPECT_NE(refusal(loaded, damaged).find("non-finite"), std::string::npos);
  EXPECT_NE(refusal(loaded, "P5 not a codebook").find("not a saved codebook"), std::string::npos);
  EXPECT_TRUE(bit_identical(loaded.codebook(), trained.codebook()));
}

TEST(OpenRadVladDescriptor, RegisteredWithTheSpecDefaultsAndShapes) {
  const DescriptorRegistry& registry = DescriptorRegistry::global();
  std::vector<std::string> names;
  for (const ParameterSpec& spec : registry.info("open_radvlad").parameters) {
    names.push_back(spec.name);
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"bin_dim", "clusters", "codebook", "kmeans", "max_bin",
                                             "max_iterations", "max_training_rows", "min_bin",
                                             "parity", "resize", "save_codebook", "seed"}));

  const DescriptorInstance paper = registry.create_from_id("open_radvlad");
  EXPECT_EQ(paper.id, "open_radvlad");
  EXPECT_EQ(paper.parameters.integer("min_bin"), 60);
  EXPECT_EQ(paper.parameters.integer("max_bin"), 0);
  EXPECT_EQ(paper.parameters.integer("bin_dim"), 512);
  EXPECT_EQ(paper.parameters.integer("clusters"), 64);
  EXPECT_EQ(paper.parameters.integer("seed"), 42);
  EXPECT_EQ(paper.parameters.integer("max_iterations"), 0);  // as the k-means choice says: 20
  EXPECT_EQ(dynamic_cast<const OpenRadVladDescriptor&>(*paper.descriptor).params().max_iterations,
            20);
  EXPECT_EQ(paper.parameters.integer("max_training_rows"), 0);  // every row, as the spec says
  const ScanGeometry mulran{400, 3360, 200.0 / 3360.0};
  EXPECT_EQ(paper.descriptor->shape(mulran), (DescriptorShape{32768, 1}));
  EXPECT_EQ(paper.descriptor->shape(mulran).paper_bytes(), 262272u);  // descriptors.md §7
  EXPECT_TRUE(paper.descriptor->trainable());
  EXPECT_FALSE(paper.descriptor->is_trained());
  EXPECT_TRUE(paper.descriptor->rotation_invariant());
  EXPECT_EQ(paper.descriptor->retrieval_method(), RetrievalMethod::exhaustive_l2);

  const DescriptorInstance small = registry.create_from_id("open_radvlad:bin_dim=10");
  EXPECT_EQ(small.id, "open_radvlad:bin_dim=10");
  EXPECT_EQ(small.descriptor->shape(mulran), (DescriptorShape{640, 1}));
  EXPECT_EQ(small.descriptor->shape(mulran).paper_bytes(), 5248u);
  // A fresh instance trains and extracts that shape.
  const auto fresh = small.create_fresh();
  fresh->train(random_scans(2, 64, 300));
  EXPECT_EQ(fresh->extract(random_scan(64, 300, 5)).values.size(), 640u);
}

// --- Training rows ---

TEST(OpenRadVladTrainingRows, CapTakesSeededWholeScansThenPartOfTheLast) {
  const VectorTrainingScans scans = random_scans(3, 4, 32);
  const AzimuthSpectraParams params = spectra_params(0, 0, 4);
  std::vector<std::vector<float>> all_rows;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const cv::Mat spectra = azimuth_spectra(scans.load(i), params);
    for (int a = 0; a < spectra.rows; ++a) all_rows.push_back(row_of(spectra, a));
  }

  // 6 of 12 rows: one whole scan (4 rows) and 2 rows of a second.
  const TrainingRows capped = collect_training_rows(scans, params, 6, 42);
  EXPECT_EQ(capped.rows.rows, 6);
  EXPECT_EQ(capped.scans_used, 2u);
  std::set<std::vector<float>> distinct;
  for (int i = 0; i < capped.rows.rows; ++i) {
    const std::vector<float> row = row_of(capped.rows, i);
    EXPECT_NE(std::find(all_rows.begin(), all_rows.end(), row), all_rows.end()) << "row " << i;
    distinct.insert(row);
  }
  EXPECT_EQ(distinct.size(), 6u);  // drawn without replacement
  EXPECT_TRUE(bit_identical(collect_training_rows(scans, params, 6, 42).rows, capped.rows));

  // No cap: every row in scan order. A cap above the total: every row too.
  const TrainingRows every = collect_training_rows(scans, params, 0, 42);
  ASSERT_EQ(every.rows.rows, 12);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(row_of(every.rows, i), all_rows[i]);
  EXPECT_EQ(collect_training_rows(scans, params, 100, 42).rows.rows, 12);
}

// --- Real data: MulRan KAIST03 ---

TEST(OpenRadVladOnMulran, TurnedFrameIsAtZeroAndTheNextFrameCloserThanTheTenth) {
  for (const char* frame : {"000000", "000001", "000002", "000010"}) {
    if (!std::filesystem::exists(native_frame(frame))) {
      GTEST_SKIP() << "MulRan KAIST03 sample frame absent: " << native_frame(frame);
    }
  }
  const PolarImage first = read_native("000000");
  const PolarImage next = read_native("000001");
  const PolarImage tenth = read_native("000010");
  const auto vlad = DescriptorRegistry::global().create_from_id("open_radvlad:clusters=8");
  const auto descriptor = vlad.create_fresh();
  descriptor->train(VectorTrainingScans({first, next, read_native("000002"), tenth},
                                        "MulRan KAIST03 frames 0, 1, 2, 10"));
  const DescriptorValue first_value = descriptor->extract(first);
  ASSERT_EQ(first_value.rows, 8 * 512);
  // Orderless over azimuths: a turn of 123 azimuths only reorders the sums.
  EXPECT_LT(descriptor->distance(first_value, descriptor->extract(turned(first, 123))), 1e-6);
  // 0.25 s apart vs 2.25 s apart while driving: the scene changes more in the second pair.
  EXPECT_LT(descriptor->distance(first_value, descriptor->extract(next)),
            descriptor->distance(first_value, descriptor->extract(tenth)));
}

}  // namespace
}  // namespace radarpr
