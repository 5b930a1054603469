#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace radarpr {

// A small seeded k-means (k-means++ seeding, then Lloyd iterations) for Open-RadVLAD's codebook.
// Rows are points: a CV_32FC1 N x d matrix (cv::Mat at the interface because Eigen is private to
// the descriptors library; the arithmetic maps the same memory as Eigen row-major matrices).
// Deterministic: single-threaded, fixed block sizes, so one seed gives bit-identical centres.
// k-means++ as first published (one D^2-weighted draw per centre), or the greedy variant
// scikit-learn's KMeans uses: 2 + floor(ln clusters) D^2-weighted candidates per centre, keeping
// the one that lowers the total squared distance most.
enum class KMeansSeeding { plain, greedy };

struct KMeansParams {
  int clusters = 64;
  std::uint64_t seed = 42;
  int max_iterations = 20;  // Lloyd iterations cap; stops earlier once no assignment changes
  KMeansSeeding seeding = KMeansSeeding::plain;
  // Also stop when the centres' total squared move in one update is <= relative_tolerance x the
  // mean over dimensions of the rows' variance (scikit-learn's tol; 1e-4 there); 0 = off.
  double relative_tolerance = 0.0;
};

struct KMeansResult {
  cv::Mat centres;              // clusters x d CV_32FC1
  std::vector<int> assignment;  // of each row, from the last assignment step; ties -> lower index
  int iterations = 0;           // assignment steps run
  bool converged = false;  // the last step changed no assignment, or the centres moved <= tolerance
};

// k-means++ seeding: the first centre is a uniformly drawn row, each next one a row drawn with
// probability proportional to its squared distance to the nearest chosen centre. When every row
// coincides with a chosen centre (fewer distinct rows than clusters), the next one is drawn
// uniformly: a duplicate centre, never a NaN. Returns the chosen row indices, in order.
// Throws std::invalid_argument unless rows is a non-empty CV_32FC1 matrix and
// 1 <= clusters <= rows.
std::vector<std::size_t> kmeans_plus_plus_seeds(const cv::Mat& rows, int clusters,
                                                std::uint64_t seed,
                                                KMeansSeeding seeding = KMeansSeeding::plain);

// scikit-learn's absolute tolerance: relative_tolerance x the mean over columns of the column
// variances (population variance, computed in double).
double absolute_tolerance(const cv::Mat& rows, double relative_tolerance);

// Lloyd's algorithm from `initial_centres` (clusters x d CV_32FC1). An empty cluster is re-seeded
// at the row farthest from its own centre (the worst-fitted point; each row used once per step) and
// the iterations go on; when every row sits exactly on its centre, the empty cluster keeps its old
// centre (a duplicate of a row). Centres are means accumulated in double. Throws
// std::invalid_argument for max_iterations < 1 or matrices that do not fit. With
// shift_tolerance > 0 it also stops after an update whose total squared centre move is <= it.
KMeansResult lloyd(const cv::Mat& rows, const cv::Mat& initial_centres, int max_iterations,
                   double shift_tolerance = 0.0);

// lloyd() from the k-means++ seeds; the same throws as both.
KMeansResult kmeans(const cv::Mat& rows, const KMeansParams& params);

}  // namespace radarpr
