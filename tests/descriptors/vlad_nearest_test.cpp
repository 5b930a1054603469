// nearest_centres narrows the centres down with one matrix product and an error bound, then
// decides by plain squared differences: it must pick what the plain squared differences over
// every centre pick (the same Eigen expression, hence the same floats), the lower index on ties.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "descriptors/open_radvlad/vlad.hpp"

namespace radarpr {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<int> nearest_by_every_centre(const cv::Mat& rows, const cv::Mat& centres) {
  const Eigen::Map<const RowMatrix> points(rows.ptr<float>(), rows.rows, rows.cols);
  const Eigen::Map<const RowMatrix> codebook(centres.ptr<float>(), centres.rows, centres.cols);
  std::vector<int> nearest;
  for (Eigen::Index a = 0; a < points.rows(); ++a) {
    Eigen::Index best = 0;
    float best_distance = (codebook.row(0) - points.row(a)).squaredNorm();
    for (Eigen::Index c = 1; c < codebook.rows(); ++c) {
      const float distance = (codebook.row(c) - points.row(a)).squaredNorm();
      if (distance < best_distance) {
        best = c;
        best_distance = distance;
      }
    }
    nearest.push_back(static_cast<int>(best));
  }
  return nearest;
}

TEST(VladNearest, MatchesEveryCentresSquaredDifferencesIncludingTiesAndNearTies) {
  cv::RNG rng(17);
  cv::Mat centres(64, 512, CV_32F);
  rng.fill(centres, cv::RNG::UNIFORM, 0.0, 0.08);
  centres.row(5).copyTo(centres.row(9));  // an exact tie: index 5 must win
  cv::Mat rows(300, 512, CV_32F);
  rng.fill(rows, cv::RNG::UNIFORM, 0.0, 0.08);
  for (int a = 0; a < 100; ++a) {
    // Midpoints of two centres, nudged by one float step: their distances differ by far less
    // than the matrix product's error bound, so the plain squared differences decide.
    const int first = a % 64;
    const int second = (a * 7 + 3) % 64;
    cv::Mat midpoint = 0.5 * (centres.row(first) + centres.row(second));
    midpoint.at<float>(0, a) = std::nextafter(midpoint.at<float>(0, a), 1.0f);
    midpoint.copyTo(rows.row(a));
  }
  centres.row(5).copyTo(rows.row(100));
  const std::vector<int> nearest = nearest_centres(rows, centres);
  EXPECT_EQ(nearest, nearest_by_every_centre(rows, centres));
  EXPECT_EQ(nearest[100], 5);
}

// Rows like azimuth spectra, x[k] == x[D - k], take the product folded to half its depth: the
// same choices, with midpoints of two centres nudged by one float step on both mirrored bins.
TEST(VladNearest, SymmetricRowsGiveTheChoicesOfEveryCentre) {
  cv::RNG rng(23);
  const int dims = 512;
  auto mirrored = [&](cv::Mat m) {
    for (int r = 0; r < m.rows; ++r) {
      for (int k = 1; k < dims - k; ++k) m.at<float>(r, dims - k) = m.at<float>(r, k);
    }
    return m;
  };
  cv::Mat centres(64, dims, CV_32F);
  rng.fill(centres, cv::RNG::UNIFORM, 0.0, 0.08);
  centres = mirrored(centres);
  cv::Mat rows(200, dims, CV_32F);
  rng.fill(rows, cv::RNG::UNIFORM, 0.0, 0.08);
  rows = mirrored(rows);
  for (int a = 0; a < 100; ++a) {
    const int first = a % 64;
    const int second = (a * 5 + 1) % 64;
    cv::Mat midpoint = 0.5 * (centres.row(first) + centres.row(second));
    const int bin = 1 + a;
    midpoint.at<float>(0, bin) = std::nextafter(midpoint.at<float>(0, bin), 1.0f);
    midpoint.at<float>(0, dims - bin) = midpoint.at<float>(0, bin);
    midpoint.copyTo(rows.row(a));
  }
  EXPECT_EQ(nearest_centres(rows, centres), nearest_by_every_centre(rows, centres));
}

}  // namespace
}  // namespace radarpr
