#include "descriptors/open_radvlad/kmeans.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "descriptors/open_radvlad/seeded_random.hpp"
#include "descriptors/training_progress.hpp"

namespace radarpr {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMatrixD = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRowMap = Eigen::Map<const RowMatrix>;
using RowMap = Eigen::Map<RowMatrix>;

// Rows scored against every centre per matrix product: large enough for an efficient product,
// small enough (4096 x clusters floats) to stay in cache. A constant, so every run does the same
// arithmetic and gets the same bits.
constexpr Eigen::Index kAssignmentBlockRows = 4096;
constexpr std::uint64_t kSeedingStream = 1;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A continuous copy only when needed, so the Eigen maps below can view the rows in place.
cv::Mat checked_rows(const cv::Mat& rows, int clusters) {
  if (rows.empty() || rows.type() != CV_32FC1) {
    throw std::invalid_argument("k-means: expected a non-empty CV_32FC1 matrix of rows, got " +
                                std::to_string(rows.rows) + " x " + std::to_string(rows.cols) +
                                " of type " + cv::typeToString(rows.type()));
  }
  if (clusters < 1 || clusters > rows.rows) {
    throw std::invalid_argument("k-means: need 1 <= clusters <= rows, got " +
                                std::to_string(clusters) + " clusters for " +
                                std::to_string(rows.rows) + " rows");
  }
  if (!cv::checkRange(rows)) {
    throw std::invalid_argument("k-means: the rows hold NaN or infinite values");
  }
  return rows.isContinuous() ? rows : rows.clone();
}

void check_iterations(int max_iterations) {
  if (max_iterations < 1) {
    throw std::invalid_argument("k-means: max_iterations must be >= 1, got " +
                                std::to_string(max_iterations));
  }
}

ConstRowMap view(const cv::Mat& rows) {
  return {rows.ptr<float>(), rows.rows, rows.cols};
}

// nearest[i] <- min(nearest[i], squared distance from row i to row `centre`). Plain differences
// (not the ||x||^2 - 2 x.c + ||c||^2 expansion) so that duplicates of a centre get exactly 0.
void lower_to_distances(const ConstRowMap& points, std::size_t centre, Eigen::VectorXf& nearest) {
  const auto c = points.row(static_cast<Eigen::Index>(centre));
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    nearest[i] = std::min(nearest[i], (points.row(i) - c).squaredNorm());
  }
}

double total_of(const Eigen::VectorXf& values) {
  double total = 0.0;
  for (Eigen::Index i = 0; i < values.size(); ++i) total += values[i];
  return total;
}

// One D^2-weighted draw: the inverse CDF of the weights; the last positive weight guards against
// rounding. Uniform when every weight is 0 (every row is already a centre: a duplicate, never a
// NaN).
std::size_t draw_weighted(const Eigen::VectorXf& nearest, double total, SeededRandom& random) {
  if (!(total > 0.0)) return random.below(static_cast<std::size_t>(nearest.size()));
  const double target = random.uniform() * total;
  double cumulative = 0.0;
  std::size_t pick = 0;
  for (Eigen::Index i = 0; i < nearest.size(); ++i) {
    if (nearest[i] <= 0.0f) continue;
    pick = static_cast<std::size_t>(i);
    cumulative += nearest[i];
    if (cumulative > target) break;
  }
  return pick;
}

std::vector<std::size_t> seeds_of(const ConstRowMap& points, int clusters, std::uint64_t seed,
                                  KMeansSeeding seeding) {
  const auto count = static_cast<std::size_t>(points.rows());
  SeededRandom random(seed, kSeedingStream);
  std::vector<std::size_t> seeds{random.below(count)};
  Eigen::VectorXf nearest = Eigen::VectorXf::Constant(points.rows(), kInfinity);
  lower_to_distances(points, seeds[0], nearest);
  // scikit-learn's number of local trials.
  const int trials =
      seeding == KMeansSeeding::greedy ? 2 + static_cast<int>(std::log(clusters)) : 1;
  while (seeds.size() < static_cast<std::size_t>(clusters)) {
    const double total = total_of(nearest);
    std::size_t best = draw_weighted(nearest, total, random);
    if (trials > 1) {
      // Every candidate is drawn from the same weights, then the one leaving the smallest
      // total squared distance wins (ties: the first drawn).
      std::vector<std::size_t> candidates{best};
      for (int t = 1; t < trials; ++t) candidates.push_back(draw_weighted(nearest, total, random));
      double best_total = std::numeric_limits<double>::infinity();
      for (const std::size_t candidate : candidates) {
        Eigen::VectorXf lowered = nearest;
        lower_to_distances(points, candidate, lowered);
        const double candidate_total = total_of(lowered);
        if (candidate_total < best_total) {
          best_total = candidate_total;
          best = candidate;
        }
      }
    }
    seeds.push_back(best);
    lower_to_distances(points, best, nearest);
    report_training_step("k-means++ seeding, centres after the first",
                         static_cast<std::size_t>(clusters) - 1);
  }
  return seeds;
}

// Nearest centre of every row (ties -> lower index) by ||c||^2 - 2 x.c in blocked products;
// `residual` receives each row's squared distance to it. Returns whether any assignment changed.
bool assign_rows(const ConstRowMap& points, const Eigen::VectorXf& point_norms,
                 const RowMap& centres, std::vector<int>& assignment,
                 std::vector<float>& residual) {
  const Eigen::VectorXf centre_norms = centres.rowwise().squaredNorm();
  RowMatrix scores;
  bool changed = false;
  for (Eigen::Index start = 0; start < points.rows(); start += kAssignmentBlockRows) {
    const Eigen::Index block = std::min(kAssignmentBlockRows, points.rows() - start);
    scores.noalias() = points.middleRows(start, block) * centres.transpose();
    for (Eigen::Index r = 0; r < block; ++r) {
      int best = 0;
      float best_value = centre_norms[0] - 2.0f * scores(r, 0);
      for (Eigen::Index c = 1; c < centres.rows(); ++c) {
        const float value = centre_norms[c] - 2.0f * scores(r, c);
        if (value < best_value) {
          best_value = value;
          best = static_cast<int>(c);
        }
      }
      const auto i = static_cast<std::size_t>(start + r);
      if (assignment[i] != best) {
        assignment[i] = best;
        changed = true;
      }
      residual[i] = std::max(0.0f, point_norms[start + r] + best_value);
    }
  }
  return changed;
}

// Centres <- means of their rows; empty clusters re-seeded at the worst-fitted rows. When the next
// assignment changes nothing, this step would repeat itself exactly: that is convergence.
void update_centres(const ConstRowMap& points, const std::vector<int>& assignment,
                    std::vector<float>& residual, RowMap& centres) {
  RowMatrixD sums = RowMatrixD::Zero(centres.rows(), centres.cols());
  std::vector<std::size_t> counts(static_cast<std::size_t>(centres.rows()), 0);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const int cluster = assignment[static_cast<std::size_t>(i)];
    sums.row(cluster) += points.row(i).cast<double>();
    ++counts[static_cast<std::size_t>(cluster)];
  }
  for (Eigen::Index c = 0; c < centres.rows(); ++c) {
    const std::size_t count = counts[static_cast<std::size_t>(c)];
    if (count > 0) {
      centres.row(c) = (sums.row(c) / static_cast<double>(count)).cast<float>();
      continue;
    }
    const auto farthest = std::max_element(residual.begin(), residual.end());
    if (*farthest <= 0.0f) continue;  // every row sits on a centre: keep the old one
    centres.row(c) = points.row(farthest - residual.begin());
    *farthest = 0.0f;  // one empty cluster per row
  }
}

}  // namespace

std::vector<std::size_t> kmeans_plus_plus_seeds(const cv::Mat& rows, int clusters,
                                                std::uint64_t seed, KMeansSeeding seeding) {
  const cv::Mat points = checked_rows(rows, clusters);
  return seeds_of(view(points), clusters, seed, seeding);
}

double absolute_tolerance(const cv::Mat& rows, double relative_tolerance) {
  const cv::Mat data = checked_rows(rows, 1);
  const ConstRowMap points = view(data);
  const Eigen::RowVectorXd mean = points.cast<double>().colwise().mean();
  double variance_sum = 0.0;
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    variance_sum += (points.col(j).cast<double>().array() - mean[j]).square().mean();
  }
  return relative_tolerance * variance_sum / static_cast<double>(points.cols());
}

KMeansResult lloyd(const cv::Mat& rows, const cv::Mat& initial_centres, int max_iterations,
                   double shift_tolerance) {
  check_iterations(max_iterations);
  const cv::Mat data = checked_rows(rows, initial_centres.rows);
  if (initial_centres.type() != CV_32FC1 || initial_centres.cols != data.cols ||
      !cv::checkRange(initial_centres)) {
    throw std::invalid_argument("k-means: initial centres must be finite CV_32FC1 with " +
                                std::to_string(data.cols) + " columns, got " +
                                std::to_string(initial_centres.rows) + " x " +
                                std::to_string(initial_centres.cols) + " of type " +
                                cv::typeToString(initial_centres.type()));
  }
  const ConstRowMap points = view(data);

  KMeansResult result;
  result.centres = initial_centres.clone();  // continuous, and the caller's matrix stays intact
  RowMap centres(result.centres.ptr<float>(), result.centres.rows, result.centres.cols);
  const Eigen::VectorXf point_norms = points.rowwise().squaredNorm();
  result.assignment.assign(static_cast<std::size_t>(data.rows), -1);
  std::vector<float> residual(static_cast<std::size_t>(data.rows), 0.0f);
  const std::string stage = "k-means iterations (at most " + std::to_string(max_iterations) + ")";
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    const bool changed = assign_rows(points, point_norms, centres, result.assignment, residual);
    report_training_step(stage, static_cast<std::size_t>(max_iterations));
    result.iterations = iteration;
    if (!changed) {
      result.converged = true;
      break;
    }
    const RowMatrix previous = centres;
    update_centres(points, result.assignment, residual, centres);
    if (shift_tolerance > 0.0 &&
        (centres - previous).cast<double>().squaredNorm() <= shift_tolerance) {
      result.converged = true;
      break;
    }
  }
  return result;
}

KMeansResult kmeans(const cv::Mat& rows, const KMeansParams& params) {
  check_iterations(params.max_iterations);
  const cv::Mat data = checked_rows(rows, params.clusters);
  cv::Mat initial_centres(params.clusters, data.cols, CV_32FC1);
  const std::vector<std::size_t> seeds =
      seeds_of(view(data), params.clusters, params.seed, params.seeding);
  for (int c = 0; c < params.clusters; ++c) {
    data.row(static_cast<int>(seeds[static_cast<std::size_t>(c)])).copyTo(initial_centres.row(c));
  }
  const double tolerance =
      params.relative_tolerance > 0.0 ? absolute_tolerance(data, params.relative_tolerance) : 0.0;
  return lloyd(data, initial_centres, params.max_iterations, tolerance);
}

}  // namespace radarpr
