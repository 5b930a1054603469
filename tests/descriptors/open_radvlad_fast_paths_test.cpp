// The fast paths of the Open-RadVLAD encoding against the plain code: the AVX2 resampling of the
// scan's bytes gives bit for bit area_resample_rows's floats, the spectra from OpenCV's packed
// DFT those of the full complex DFT, and the AVX2 centre products stay within the dot product's
// error bound (as Eigen's baseline product does). On a processor without AVX2 both paths are
// the baseline and the comparisons still hold.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "descriptors/open_radvlad/area_resampling.hpp"
#include "descriptors/open_radvlad/azimuth_spectra.hpp"
#include "descriptors/open_radvlad/centre_products.hpp"
#include "descriptors/opencv_image.hpp"

namespace radarpr {
namespace {

bool bit_identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && a.isContinuous() && b.isContinuous() &&
         std::memcmp(a.data, b.data, a.total() * a.elemSize()) == 0;
}

// Radar-like bytes: mostly a low floor, a third of them anywhere in 0..255.
cv::Mat radar_bytes(int rows, int cols, std::uint64_t state) {
  cv::RNG rng(state);
  cv::Mat bytes(rows, cols, CV_8UC1);
  for (int a = 0; a < rows; ++a) {
    for (int r = 0; r < cols; ++r) {
      bytes.at<std::uint8_t>(a, r) = static_cast<std::uint8_t>(
          rng.uniform(0, 3) == 0 ? rng.uniform(0, 256) : rng.uniform(0, 8));
    }
  }
  return bytes;
}

// What area_resample_bytes is defined as: area_resample_rows of the float copy, columns below
// `zeroed` set to 0.
cv::Mat plain_resampling(const cv::Mat& bytes, int zeroed, int width) {
  cv::Mat values;
  bytes.convertTo(values, CV_32FC1);
  if (zeroed > 0) values.colRange(0, std::min(zeroed, values.cols)).setTo(0.0f);
  return area_resample_rows(values, width);
}

TEST(OpenRadVladFastPaths, ByteResamplingIsBitIdenticalToThePlainResamplingOnEitherPath) {
  struct Case {
    int rows, cols, zeroed, width;
  };
  // Rows around the 16-row blocks, shrinking and enlarging widths, columns around the 16-column
  // interleaving, nothing zeroed, some, all but one, all.
  const Case cases[] = {{400, 3360, 60, 512}, {400, 3768, 60, 512}, {17, 3360, 0, 10},
                        {15, 1000, 999, 7},   {1, 33, 5, 64},       {33, 16, 0, 3},
                        {16, 47, 47, 5},      {3, 5, 2, 1},         {31, 200, 13, 511}};
  std::uint64_t state = 1;
  for (const Case& c : cases) {
    const cv::Mat bytes = radar_bytes(c.rows, c.cols, state++);
    const cv::Mat expected = plain_resampling(bytes, c.zeroed, c.width);
    EXPECT_TRUE(bit_identical(area_resample_bytes(bytes, c.zeroed, c.width), expected))
        << c.rows << " x " << c.cols << " zeroed " << c.zeroed << " width " << c.width;
    EXPECT_TRUE(bit_identical(
        area_resample_bytes(bytes, c.zeroed, c.width, ResamplingPath::baseline), expected))
        << c.rows << " x " << c.cols << " zeroed " << c.zeroed << " width " << c.width;
  }
  // A view into a wider image (rows not contiguous) reads only its own columns.
  const cv::Mat wide = radar_bytes(20, 300, 99);
  const cv::Mat view = wide.colRange(0, 250);
  EXPECT_TRUE(
      bit_identical(area_resample_bytes(view, 10, 40), plain_resampling(view.clone(), 10, 40)));
}

TEST(OpenRadVladFastPaths, ByteResamplingRejectsBadInput) {
  EXPECT_THROW(area_resample_bytes(cv::Mat(), 0, 4), std::invalid_argument);
  EXPECT_THROW(area_resample_bytes(cv::Mat(2, 4, CV_32FC1, cv::Scalar(1.0f)), 0, 4),
               std::invalid_argument);
  EXPECT_THROW(area_resample_bytes(radar_bytes(2, 4, 1), 0, 0), std::invalid_argument);
  EXPECT_THROW(area_resample_bytes(radar_bytes(2, 4, 1), -1, 4), std::invalid_argument);
}

// The spectra take the magnitudes from OpenCV's packed real DFT and mirror them; the full
// complex DFT of the same resampled rows must give the same floats, for even and odd widths.
TEST(OpenRadVladFastPaths, SpectraEqualTheMagnitudesOfTheFullComplexDft) {
  for (const int bin_dim : {512, 511, 10, 7, 2, 1}) {
    PolarImage scan;
    scan.power = to_byte_image(radar_bytes(37, 900, static_cast<std::uint64_t>(bin_dim)));
    scan.azimuths_rad = uniform_azimuths(scan.power.rows());
    scan.range_resolution_m = 0.05;
    AzimuthSpectraParams params;
    params.min_bin = 20;
    params.bin_dim = bin_dim;
    const cv::Mat spectra = azimuth_spectra(scan, params);

    cv::Mat complex;
    cv::dft(plain_resampling(opencv_view(scan.power), params.min_bin, bin_dim), complex,
            cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
    cv::Mat expected(complex.rows, bin_dim, CV_32FC1);
    for (int a = 0; a < complex.rows; ++a) {
      double squared = 0.0;
      for (int k = 0; k < bin_dim; ++k) {
        const cv::Vec2f z = complex.at<cv::Vec2f>(a, k);
        const double re = z[0];
        const double im = z[1];
        expected.at<float>(a, k) = static_cast<float>(std::sqrt(re * re + im * im));
        squared += static_cast<double>(expected.at<float>(a, k)) * expected.at<float>(a, k);
      }
      const double inverse = squared == 0.0 ? 1.0 : 1.0 / std::sqrt(squared);
      for (int k = 0; k < bin_dim; ++k) {
        expected.at<float>(a, k) = static_cast<float>(expected.at<float>(a, k) * inverse);
      }
    }
    EXPECT_TRUE(bit_identical(spectra, expected)) << "bin_dim " << bin_dim;
  }
}

// Every product within the bound the header states, against the exact value (in double, whose
// error here is far below float's), for mirror-symmetric rows (folded) and others, with counts
// of rows and centres that do not fill the 4 x 16 blocks.
TEST(OpenRadVladFastPaths, CentreProductsStayWithinTheDotProductBoundOnEitherPath) {
  cv::RNG rng(5);
  for (const bool symmetric : {true, false}) {
    for (const int dims : {512, 129, 4}) {
      cv::Mat rows(203, dims, CV_32FC1);
      cv::Mat centres(37, dims, CV_32FC1);
      rng.fill(rows, cv::RNG::UNIFORM, 0.0, 0.08);
      rng.fill(centres, cv::RNG::UNIFORM, -0.05, 0.08);
      if (symmetric) {
        for (int a = 0; a < rows.rows; ++a) {
          for (int k = 1; k < dims - k; ++k) rows.at<float>(a, dims - k) = rows.at<float>(a, k);
        }
      }
      const double terms = symmetric ? dims / 2 + 2 : dims + 2;
      for (const ProductPath path : {ProductPath::fastest, ProductPath::baseline}) {
        const std::vector<float> products = centre_products(rows, centres, path);
        ASSERT_EQ(products.size(), static_cast<std::size_t>(rows.rows * centres.rows));
        for (int a = 0; a < rows.rows; ++a) {
          for (int c = 0; c < centres.rows; ++c) {
            double exact = 0.0;
            double lengths = 0.0;
            double x_squared = 0.0;
            double c_squared = 0.0;
            for (int k = 0; k < dims; ++k) {
              exact += static_cast<double>(rows.at<float>(a, k)) * centres.at<float>(c, k);
              x_squared += static_cast<double>(rows.at<float>(a, k)) * rows.at<float>(a, k);
              c_squared += static_cast<double>(centres.at<float>(c, k)) * centres.at<float>(c, k);
            }
            lengths = std::sqrt(x_squared) * std::sqrt(c_squared);
            const double bound = terms * 0x1p-24 * lengths;
            EXPECT_LE(std::abs(products[static_cast<std::size_t>(a * centres.rows + c)] - exact),
                      bound)
                << "row " << a << " centre " << c << " dims " << dims
                << (symmetric ? " symmetric" : "");
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace radarpr
