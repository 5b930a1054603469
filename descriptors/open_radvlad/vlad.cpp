#include "descriptors/open_radvlad/vlad.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

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

std::vector<int> nearest_of(const cv::Mat& rows, const cv::Mat& centres) {
  const auto points = view(rows);
  const auto codebook = view(centres);
  std::vector<int> nearest(static_cast<std::size_t>(rows.rows), 0);
  Eigen::VectorXf distances(codebook.rows());
  for (Eigen::Index a = 0; a < points.rows(); ++a) {
    // Plain squared differences: exact ties stay ties, so the lower index wins as specified.
    for (Eigen::Index c = 0; c < codebook.rows(); ++c) {
      distances[c] = (codebook.row(c) - points.row(a)).squaredNorm();
    }
    Eigen::Index best = 0;
    for (Eigen::Index c = 1; c < distances.size(); ++c) {
      if (distances[c] < distances[best]) best = c;
    }
    nearest[static_cast<std::size_t>(a)] = static_cast<int>(best);
  }
  return nearest;
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

  double squared_norm = 0.0;
  for (double& v : residuals) {
    v = std::copysign(std::sqrt(std::abs(v)), v);
    squared_norm += v * v;
  }
  // An all-zero V (every row exactly on its centre) stays zero instead of 0/0.
  const double scale = squared_norm > 0.0 ? 1.0 / std::sqrt(squared_norm) : 0.0;
  std::vector<float> vlad(residuals.size());
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    vlad[i] = static_cast<float>(residuals[i] * scale);
  }
  return vlad;
}

}  // namespace radarpr
